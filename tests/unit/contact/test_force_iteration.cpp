// The creepage iteration for prescribed forces (physics.md §9.6) on model creep curves: a start
// Jacobian from the previous case replaces the finite-difference start and saves evaluations.

#include <gtest/gtest.h>

#include <cmath>

#include "contact/force_iteration.hpp"

namespace rollcontact {
namespace {

/// A saturating creep curve F(ξ)/(μFN) = −tanh(ξ/ξ0), like a Hertzian one, with ξ0 = 1e-3.
std::array<double, 2> creep_curve(double ksi, double eta, int& calls) {
  ++calls;
  return {-std::tanh(ksi / 1e-3), -std::tanh(eta / 2e-3)};
}

TEST(ForceIteration, PreviousSlopeSavesTheFiniteDifferenceSolve) {
  ForceIterationInput in;
  in.target_x = -0.5;
  in.start_ksi = 5.4e-4;  // the previous case's creepage, near the root 5.493e-4
  in.eps = 1e-9;
  int fd_calls = 0, warm_calls = 0;
  const ForceIterationResult fd =
      force_iteration(in, [&](double k, double e) { return creep_curve(k, e, fd_calls); });
  in.start_jacobian = {fd.jacobian[0], 0.0, 0.0, 0.0};  // as the previous case left it
  const ForceIterationResult warm =
      force_iteration(in, [&](double k, double e) { return creep_curve(k, e, warm_calls); });
  ASSERT_TRUE(fd.converged);
  ASSERT_TRUE(warm.converged);
  EXPECT_NEAR(warm.ksi, 1e-3 * std::atanh(0.5), 1e-9 * 1e-3 / (1.0 - 0.25));
  EXPECT_LT(warm_calls, fd_calls);
}

TEST(ForceIteration, UnusableSlopeFallsBackToFiniteDifferences) {
  ForceIterationInput in;
  in.target_x = -0.5;
  in.start_ksi = 1e-6;
  in.eps = 1e-9;
  for (double slope : {0.0, 1e-30, std::nan("")}) {  // zero, full sliding (huge step), unknown
    in.start_jacobian = {slope, 0.0, 0.0, 0.0};
    int calls = 0;
    const ForceIterationResult r =
        force_iteration(in, [&](double k, double e) { return creep_curve(k, e, calls); });
    EXPECT_TRUE(r.converged) << slope;
    EXPECT_NEAR(r.ksi, 1e-3 * std::atanh(0.5), 1e-8) << slope;
  }
}

TEST(ForceIteration, TwoUnknownsWithPreviousJacobian) {
  ForceIterationInput in;
  in.unknowns = 2;
  in.target_x = -0.3;
  in.target_y = 0.4;
  in.start_ksi = 3.0e-4;
  in.start_eta = -8.4e-4;
  in.eps = 1e-9;
  int fd_calls = 0, warm_calls = 0;
  const ForceIterationResult fd =
      force_iteration(in, [&](double k, double e) { return creep_curve(k, e, fd_calls); });
  in.start_jacobian = fd.jacobian;
  const ForceIterationResult warm =
      force_iteration(in, [&](double k, double e) { return creep_curve(k, e, warm_calls); });
  ASSERT_TRUE(fd.converged);
  ASSERT_TRUE(warm.converged);
  EXPECT_NEAR(warm.ksi, 1e-3 * std::atanh(0.3), 1e-8);
  EXPECT_NEAR(warm.eta, -2e-3 * std::atanh(0.4), 1e-8);
  EXPECT_LT(warm_calls, fd_calls);
}

}  // namespace
}  // namespace rollcontact
