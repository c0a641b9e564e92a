// IPLAN=4: rectangles of one grid that feel each other only in part (f_ij). Two identical
// bumps side by side: with f = 0 each half is the problem of one bump alone, with f = 1 the
// full interaction returns, and in between the load lies between the two.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "rollcontact/solve.hpp"
#include "support/hertz_problem.hpp"
#include "support/patch_solve.hpp"

namespace rollcontact {
namespace {

constexpr int kMx = 16, kMy = 24;
constexpr double kStep = 0.1, kRadius = 10.0;  // [mm]

/// Two paraboloids at y = ±0.6 mm (or only the one at y < 0), approach 0.01 mm, steady rolling
/// with ξ = −1e-3; `factor` < 0: no planform (IPLAN=1).
model::PatchProblem two_bumps(double factor, bool lower_only = false) {
  model::PatchProblem p;
  p.potential.ipotcn = 1;
  p.potential.mx = kMx;
  p.potential.my = kMy;
  p.potential.values = {-0.5 * kMx * kStep, -0.5 * kMy * kStep, kStep, kStep};
  p.gap.ibase = 9;
  for (int iy = 0; iy < kMy; ++iy)
    for (int ix = 0; ix < kMx; ++ix) {
      const double x = (ix + 0.5 - 0.5 * kMx) * kStep, y = (iy + 0.5 - 0.5 * kMy) * kStep;
      const double yc = y < 0.0 ? -0.6 : 0.6;
      const double h = (x * x + (y - yc) * (y - yc)) / (2.0 * kRadius);
      p.gap.values.push_back(lower_only && y > 0.0 ? 1.0 : h);
    }
  if (factor >= 0.0) {
    p.gap.iplan = 4;
    p.gap.npatch = 2;
    p.gap.planform = {-10, 10, -10, 0, -10, 10, 0, 10};
    p.gap.patch_factors = {factor};
  }
  p.normal.kind = model::NormalLoadKind::Approach;
  p.normal.approach_mm = 0.01;
  p.bodies.body1 = p.bodies.body2 = {0.28, 82000.0};
  p.friction = {0.3, 0.3};
  p.tangential.kind = test::tangential_kind(3);
  p.tangential.creepage.longitudinal = -1e-3;
  p.rolling.step_mm = kStep;
  p.rolling.velocity_mm_per_s = 1000.0;
  p.solver.tolerance = 1e-8;
  return p;
}

TEST(PlanformInteraction, NoInteractionSplitsIntoIndependentProblems) {
  const Solution one = test::solve_converged(two_bumps(-1.0, true));
  const Solution split = test::solve_converged(two_bumps(0.0));
  ASSERT_GT(one.statistics.ncon, 20);
  EXPECT_NEAR(split.totals.fn, 2.0 * one.totals.fn, 1e-6 * one.totals.fn);
  EXPECT_NEAR(split.totals.fx, 2.0 * one.totals.fx, 1e-5 * std::abs(one.totals.fx));
  EXPECT_EQ(split.statistics.ncon, 2 * one.statistics.ncon);
}

TEST(PlanformInteraction, FullInteractionIsThePlainProblem) {
  const Solution plain = test::solve_converged(two_bumps(-1.0));
  const Solution full = test::solve_converged(two_bumps(1.0));
  EXPECT_NEAR(full.totals.fn, plain.totals.fn, 1e-9 * plain.totals.fn);
  EXPECT_NEAR(full.totals.fx, plain.totals.fx, 1e-9 * std::abs(plain.totals.fx));
}

TEST(PlanformInteraction, PartialInteractionLiesBetween) {
  // At a fixed approach, the neighbour's pressure lifts the surface: less interaction, more load.
  const double fn_full = test::solve_converged(two_bumps(1.0)).totals.fn;
  const double fn_half = test::solve_converged(two_bumps(0.5)).totals.fn;
  const double fn_none = test::solve_converged(two_bumps(0.0)).totals.fn;
  EXPECT_LT(fn_full, fn_half);
  EXPECT_LT(fn_half, fn_none);
  EXPECT_GT(fn_none - fn_full, 1e-3 * fn_full);  // the effect is visible at all
}

}  // namespace
}  // namespace rollcontact
