// The rolling step δq where it differs from the element size δx (issue 18, items 5 and 7):
// steady rolling is discretised with δq = δx whatever the solver (physics.md §14), and in
// transient rolling with δq > δx only the part of the step after a particle entered the contact
// counts as its slip (§9.4).

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "rollcontact/solve.hpp"
#include "support/hertz_problem.hpp"
#include "tangential/leading_edge.hpp"

namespace rollcontact {
namespace {

constexpr double kDx = 2.0 * 1.1 * 0.6 / 31;  // element size of the 31 × 41 grid below [mm]

model::PatchProblem rolling_case(int t, double step_mm) {
  model::PatchProblem p = test::hertz_problem(0.6, 1.0, 10.0, 82000.0, 0.28, 31, 41, 1.1);
  p.tangential.kind = test::tangential_kind(t);
  p.solver.tolerance = 1e-8;
  p.rolling.velocity_mm_per_s = 10000.0;
  p.rolling.step_mm = step_mm;
  p.tangential.creepage.longitudinal = 2.0e-5;  // μp₀/G ≈ 3e-5: partial slip
  p.tangential.creepage.lateral = -1.0e-5;
  p.tangential.creepage.spin_rad_per_mm = 2.0e-5;
  return p;
}

bool has_warning(const Solution& s, const std::string& text) {
  for (const std::string& w : s.warnings)
    if (w.find(text) != std::string::npos) return true;
  return false;
}

class SteadyRollingStep : public ::testing::TestWithParam<model::TangentialMethod> {};

TEST_P(SteadyRollingStep, IsOneElementWhateverTheSolver) {
  // CONTACT gives the same steady-rolling answer for DQ = 5·DX as for DQ = DX with SteadyGS and
  // with ConvexGS alike; a longer step would only be a coarser difference quotient of u.
  model::PatchProblem one = rolling_case(3, kDx), five = rolling_case(3, 5.0 * kDx);
  one.solver.tangential_method = five.solver.tangential_method = GetParam();
  PatchSolver s1, s2;
  const Solution a = s1.solve(one), b = s2.solve(five);
  ASSERT_TRUE(a.solver.converged && b.solver.converged);
  EXPECT_DOUBLE_EQ(b.kinematics.dq, a.grid.dx);
  EXPECT_EQ(a.totals.fx, b.totals.fx);
  EXPECT_EQ(a.totals.fy, b.totals.fy);
  EXPECT_TRUE(has_warning(b, "Using DQ = DX"));
  EXPECT_FALSE(has_warning(a, "Using DQ = DX"));
}

INSTANTIATE_TEST_SUITE_P(Solvers, SteadyRollingStep,
                         ::testing::Values(model::TangentialMethod::Default,
                                           model::TangentialMethod::ConvexGS));

TEST(SteadyRollingStep, BothSolversAgree) {
  model::PatchProblem gs = rolling_case(3, 5.0 * kDx);
  gs.solver.tangential_method = model::TangentialMethod::ConvexGS;
  PatchSolver s1, s2;
  const Solution a = s1.solve(rolling_case(3, 5.0 * kDx)), b = s2.solve(gs);
  const double mu_fn = 0.3 * a.totals.fn;
  // Both converge to EPS = 1e-8 in the tractions: the forces agree far below 1e-5·μFN.
  EXPECT_NEAR(a.totals.fx, b.totals.fx, 1e-5 * mu_fn);
  EXPECT_NEAR(a.totals.fy, b.totals.fy, 1e-5 * mu_fn);
}

TEST(TransientRollingStep, LongStepCountsSlipOnlyAfterEntry) {
  // From zero tractions a transient step is a shift by δq·w, except that a particle within δq
  // of the leading edge entered the contact during the step: for it only f·δq·w counts
  // (f = distance to the edge / δq). A shift problem with exactly that rigid slip must give the
  // same tractions.
  const double step = 2.5 * kDx;
  model::PatchProblem rolling = rolling_case(2, step);
  PatchSolver s1;
  const Solution r = s1.solve(rolling);
  ASSERT_TRUE(r.solver.converged) << r.solver.message;

  std::vector<char> contact(r.pn.size());
  for (std::size_t i = 0; i < r.pn.size(); ++i) contact[i] = r.pn[i] > 0.0;
  const auto entries = tangential::leading_edge_entries(r.grid, contact, 0.0, step);
  ASSERT_GE(entries.size(), 2U * 20);  // two elements in each of the rows in contact

  model::PatchProblem shift = rolling_case(1, step);
  const auto& c = rolling.tangential.creepage;
  shift.tangential.creepage.longitudinal = step * c.longitudinal;
  shift.tangential.creepage.lateral = step * c.lateral;
  shift.tangential.creepage.spin_rad_per_mm = step * c.spin_rad_per_mm;
  // The spin's rigid slip of a rolling step is taken a fraction f_φ along it.
  const double offset = rolling.rolling.spin_offset_factor * step;
  shift.tangential.spin_centre_x_mm = -offset;
  shift.tangential.extra_slip.assign(2 * r.grid.size(), 0.0);
  for (const auto& e : entries) {
    const int ix = static_cast<int>(e.element % r.grid.mx);
    const double x = r.grid.x_centre(ix) + offset;
    const double y = r.grid.y_centre(static_cast<int>(e.element / r.grid.mx));
    shift.tangential.extra_slip[2 * e.element] =
        (e.factor - 1.0) * step * (c.longitudinal - c.spin_rad_per_mm * y);
    shift.tangential.extra_slip[2 * e.element + 1] =
        (e.factor - 1.0) * step * (c.lateral + c.spin_rad_per_mm * x);
  }
  PatchSolver s2;
  const Solution s = s2.solve(shift);
  ASSERT_TRUE(s.solver.converged) << s.solver.message;
  const double mu_fn = 0.3 * r.totals.fn;
  EXPECT_NEAR(r.totals.fx, s.totals.fx, 1e-7 * mu_fn);
  EXPECT_NEAR(r.totals.fy, s.totals.fy, 1e-7 * mu_fn);

  // Without the correction the answer would be the plain shift by δq·w: visibly different.
  model::PatchProblem plain = shift;
  plain.tangential.extra_slip.clear();
  PatchSolver s3;
  const Solution u = s3.solve(plain);
  EXPECT_GT(std::abs(u.totals.fx - r.totals.fx), 1e-3 * mu_fn);
}

TEST(TransientRollingStep, ForcePrescribedStepOfTwoElements) {
  // Issue 18 item 7: from zero tractions with FX prescribed and DQ = 2·DX, CONTACT solves a
  // creepage 1.5 % larger than half the one of DQ = DX; without the leading-edge correction the
  // two would be the same shift δq·ξ exactly. Here: FX reached, and the creepage of the long
  // step above half the short one's by more than 0.5 %, as the correction requires.
  auto solve = [](double step) {
    model::PatchProblem p = rolling_case(2, step);
    p.tangential.prescribed = model::TangentialPrescribed::LongitudinalForceLateralCreepage;
    p.tangential.force_x_over_mu_fn = -0.4;
    p.tangential.creepage.lateral = 0.0;
    p.tangential.creepage.spin_rad_per_mm = 0.0;
    PatchSolver s;
    return s.solve(p);
  };
  const Solution one = solve(kDx), two = solve(2.0 * kDx);
  ASSERT_TRUE(one.solver.converged && two.solver.converged);
  const double mu_fn = 0.3 * two.totals.fn;
  EXPECT_NEAR(two.totals.fx, -0.4 * mu_fn, 1e-4 * mu_fn);
  EXPECT_NEAR(one.totals.fx, -0.4 * mu_fn, 1e-4 * mu_fn);
  const double ratio = 2.0 * two.totals.creep_x / one.totals.creep_x;
  EXPECT_GT(ratio, 1.005);
  EXPECT_LT(ratio, 1.10);
}

}  // namespace
}  // namespace rollcontact
