// Contact problems with Blanco's correction of the influence coefficients (C=4,
// spec-additions.md §B8): what the symmetry of the problem and the limits of the correction
// fix about the answer.

#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "rollcontact/solve.hpp"
#include "support/hertz_problem.hpp"
#include "support/patch_solve.hpp"

namespace rollcontact {
namespace {

/// A Hertzian patch (a = 3, b = 2 mm, 10 kN) on a 31 × 31 grid with steady rolling (or a shift),
/// the surface's inclination changing by `curvature` [rad/mm] across the rows (variant `variant`,
/// 0: plain half-space), Panagiotopoulos' process for the coupling it brings.
model::PatchProblem turned_problem(int variant, double curvature, model::TangentialKind kind,
                                   double xi, double eta, double phi) {
  model::PatchProblem p = test::hertz_problem(3.0, 2.0, 10000.0, 82000.0, 0.28, 31, 31, 1.2);
  p.solver.tolerance = 1e-7;
  p.solver.max_normal_tangential_passes = 20;
  p.tangential.kind = kind;
  p.tangential.creepage = {xi, eta, phi};
  p.rolling.step_mm = 0.2;
  p.rolling.velocity_mm_per_s = 2000.0;
  if (variant != 0) {
    p.bodies.inclination.variant = variant;
    p.bodies.inclination.y_mm = {-5.0, 5.0};
    p.bodies.inclination.alpha_rad = {-5.0 * curvature, 5.0 * curvature};
  }
  return p;
}

// α = c₁·y is its own mirror image (y → −y turns α into −α at −y), and so is a longitudinal
// creepage: the lateral force and the spin moment vanish, whatever the variant.
TEST(InclinationCorrectionSolve, MirrorSymmetricRollingHasNoLateralForceOrSpinMoment) {
  for (int variant = 1; variant <= 4; ++variant) {
    const Solution s = test::solve_converged(
        turned_problem(variant, 0.05, model::TangentialKind::SteadyRolling, 1e-3, 0.0, 0.0));
    const double fx = std::abs(s.totals.fx);
    EXPECT_GT(fx, 0.3 * 0.3 * 10000.0) << variant;
    EXPECT_LT(std::abs(s.totals.fy), 1e-6 * fx) << variant;
    EXPECT_LT(std::abs(s.totals.mz), 1e-6 * fx * 3.0) << variant;
    // The turned normal load pushes the surface apart laterally: odd in y, no net force.
    EXPECT_GT(s.statistics.inorm, 1) << variant;
  }
}

// A table of one inclination (a plane) leaves the coefficients those of the plain half-space:
// the answer of C=2 bit for bit.
TEST(InclinationCorrectionSolve, ConstantInclinationIsThePlainHalfSpace) {
  model::PatchProblem p =
      turned_problem(0, 0.0, model::TangentialKind::SteadyRolling, 1e-3, -5e-4, 1e-4);
  const Solution plain = test::solve_converged(p);
  p.bodies.inclination.variant = 3;
  p.bodies.inclination.y_mm = {-4.0, 0.0, 4.0};
  p.bodies.inclination.alpha_rad = {0.2, 0.2, 0.2};
  const Solution same = test::solve_converged(p);
  EXPECT_EQ(same.totals.fn, plain.totals.fn);
  EXPECT_EQ(same.totals.fx, plain.totals.fx);
  EXPECT_EQ(same.totals.fy, plain.totals.fy);
  EXPECT_EQ(same.totals.pen, plain.totals.pen);
  EXPECT_EQ(same.px, plain.px);
}

// The correction is smooth in the curvature: halving it about halves the change of the forces
// (first order, the coupling terms sin θ ≈ θ), and it vanishes with the curvature.
TEST(InclinationCorrectionSolve, ChangeOfTheForcesIsFirstOrderInTheCurvature) {
  const auto forces = [](double curvature) {
    const Solution s = test::solve_converged(
        turned_problem(1, curvature, model::TangentialKind::SteadyRolling, 1e-3, -5e-4, 1e-4));
    return std::array<double, 2>{s.totals.fx, s.totals.fy};
  };
  const std::array<double, 2> f0 = forces(0.0), f1 = forces(0.02), f2 = forces(0.01);
  for (int k = 0; k < 2; ++k) {
    const double d1 = f1[k] - f0[k], d2 = f2[k] - f0[k];
    EXPECT_GT(std::abs(d1), 1e-4 * std::abs(f0[k])) << k;  // the correction acts
    EXPECT_NEAR(d2 / d1, 0.5, 0.1) << k;
  }
}

// Every variant solves shifts (PCG for the symmetric variant 4, GMRES for the others) and
// steady rolling with the normal force met; a turn of at most 0.15 rad across the patch changes
// the tangential force by a few per cent, not its size.
TEST(InclinationCorrectionSolve, EveryVariantSolvesShiftsAndRolling) {
  for (model::TangentialKind kind :
       {model::TangentialKind::Shift, model::TangentialKind::SteadyRolling}) {
    const double creep = kind == model::TangentialKind::Shift ? 2e-4 : 1e-3;
    const double plain =
        test::solve_converged(turned_problem(0, 0.0, kind, creep, 0.5 * creep, 0.0)).totals.fx;
    for (int variant = 1; variant <= 4; ++variant) {
      const Solution s =
          test::solve_converged(turned_problem(variant, -0.04, kind, creep, 0.5 * creep, 0.0));
      EXPECT_NEAR(s.totals.fn, 10000.0, 1e-6 * 10000.0) << variant;
      EXPECT_NE(s.totals.fx, plain) << variant;
      EXPECT_NEAR(s.totals.fx, plain, 0.05 * std::abs(plain)) << variant;
    }
  }
}

}  // namespace
}  // namespace rollcontact
