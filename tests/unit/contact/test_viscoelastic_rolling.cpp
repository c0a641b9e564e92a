// Steady rolling of viscoelastic (standard linear solid) bodies, M=1 (spec-additions §B5): the
// elastic limits of the material and the rolling resistance of the relaxation in between.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "rollcontact/solve.hpp"
#include "support/patch_solve.hpp"

namespace rollcontact {
namespace {

constexpr double kGlassy = 1143.0, kNu = 0.4, kVelocity = 1000.0;  // N/mm², -, mm/s (PA6)

/// A sphere-like contact of identical bodies: h = 0.05(x² + y²) on a 21 × 21 grid of 0.2 mm,
/// FN = 600 N (semi-axis about 1.3 mm glassy, 1.6 mm rubbery), pure rolling (creepages
/// prescribed, zero unless given), μ = 0.3.
model::PatchProblem rolling_ball(double creep_ratio, double relaxation_time_s, bool viscoelastic,
                                 double shear_modulus = kGlassy, double creepage = 0.0) {
  model::PatchProblem p;
  p.potential.ipotcn = 3;
  p.potential.mx = p.potential.my = 21;
  p.potential.values = {-2.0, -2.0, 0.2, 0.2};
  p.gap.ibase = 1;
  p.gap.coeffs = {0.05, 0.0, 0.05, 0.0, 0.0, 0.0};
  p.normal.kind = model::NormalLoadKind::Force;
  p.normal.force_N = 600.0;
  p.bodies.body1 = p.bodies.body2 = {kNu, shear_modulus};
  p.bodies.viscoelastic = viscoelastic;
  p.bodies.viscous1 = p.bodies.viscous2 = {creep_ratio, relaxation_time_s};
  p.tangential.kind = model::TangentialKind::SteadyRolling;
  p.tangential.creepage.longitudinal = creepage;
  p.rolling.velocity_mm_per_s = kVelocity;
  p.rolling.step_mm = 0.2;
  p.friction = {0.3, 0.3};
  p.solver.tolerance = 1e-9;
  return p;
}

double pmax(const Solution& s) {
  return *std::max_element(s.pn.begin(), s.pn.end());
}

/// x of the centre of pressure [mm]: > 0 towards the leading edge (χ = 0 rolls towards +x).
double pressure_centre(const Solution& s) {
  double m = 0.0, f = 0.0;
  for (int iy = 0; iy < s.grid.my; ++iy)
    for (int ix = 0; ix < s.grid.mx; ++ix) {
      const double p = s.pn[s.grid.index(ix, iy)];
      m += p * s.grid.x_centre(ix);
      f += p;
    }
  return m / f;
}

void expect_same_case(const Solution& a, const Solution& b, double rel) {
  EXPECT_NEAR(a.totals.pen, b.totals.pen, rel * std::abs(b.totals.pen));
  EXPECT_NEAR(pmax(a), pmax(b), rel * pmax(b));
  EXPECT_NEAR(a.totals.fx, b.totals.fx, rel * std::abs(b.totals.fx) + 1e-9 * b.totals.fn);
  EXPECT_EQ(a.statistics.ncon, b.statistics.ncon);
}

TEST(ViscoelasticRolling, NoCreepIsTheElasticSolutionBitForBit) {
  // FG = 0: no viscous part, whatever TC; the elastic operators and solvers are used unchanged.
  const Solution visco = test::solve_converged(rolling_ball(0.0, 0.01, true, kGlassy, -1e-3));
  const Solution elastic = test::solve_converged(rolling_ball(0.0, 0.0, false, kGlassy, -1e-3));
  EXPECT_EQ(visco.pn, elastic.pn);
  EXPECT_EQ(visco.px, elastic.px);
  EXPECT_EQ(visco.totals.pen, elastic.totals.pen);
  EXPECT_EQ(visco.totals.fx, elastic.totals.fx);
}

TEST(ViscoelasticRolling, InstantRelaxationIsTheRubberyElasticSolution) {
  // TC = 0: both bodies respond with G_r = G_g/(1 + FG) at once. The coefficients equal the
  // rubbery ones to rounding; the normal solvers differ (active set with GMRES vs NormCG to
  // EPS = 1e-9), hence 1e-7. TC = 1e-9 s (ℓ = 1 µm, 1/200 element): within O(ℓ/δx) = 1e-3.
  const double fg = 1.0;
  const Solution rubbery =
      test::solve_converged(rolling_ball(0.0, 0.0, false, kGlassy / (1.0 + fg), -1e-3));
  expect_same_case(test::solve_converged(rolling_ball(fg, 0.0, true, kGlassy, -1e-3)), rubbery,
                   1e-7);
  expect_same_case(test::solve_converged(rolling_ball(fg, 1e-6, true, kGlassy, -1e-3)), rubbery,
                   1e-3);
}

TEST(ViscoelasticRolling, SlowRelaxationIsTheGlassyElasticSolution) {
  // TC → ∞: the material has no time to creep while it passes the contact; the viscous part
  // decays like FG·(L/ℓ)·log(ℓ/L), L = 4 mm the grid: ℓ = 1e7 mm leaves ~5e-6.
  const Solution glassy = test::solve_converged(rolling_ball(0.0, 0.0, false, kGlassy, -1e-3));
  expect_same_case(test::solve_converged(rolling_ball(1.0, 1e4, true, kGlassy, -1e-3)), glassy,
                   1e-4);
}

TEST(ViscoelasticRolling, RollingResistancePeaksAtIntermediateRelaxation) {
  // Pure rolling: the material entering the contact (leading edge, +x) is stiffer than the
  // creeping material leaving it, so the pressure centre moves ahead of the axle and the normal
  // force resists rolling with the arm x_c (Wang & Knothe 1993; CONTACT's visc_cylindr: PMAX
  // rises from the rubbery 60 to 85 N/mm² with the peak moving forward). Both elastic limits are
  // symmetric (x_c = 0); the arm is largest when the relaxation length is comparable to the
  // contact length (semi-axis a ≈ 1.3–1.6 mm here).
  std::vector<double> arm;
  for (double tc : {0.0, 1e-4, 1.5e-3, 2e-2, 1e1})  // ℓ = 0, 0.1, 1.5, 20, 1e4 mm
    arm.push_back(pressure_centre(test::solve_converged(rolling_ball(1.0, tc, true))));
  EXPECT_NEAR(arm[0], 0.0, 1e-9);
  EXPECT_LT(std::abs(arm[4]), 0.02 * arm[2]);
  for (std::size_t k = 1; k < 4; ++k) EXPECT_GT(arm[k], 0.0) << k;
  EXPECT_GT(arm[2], arm[1]);
  EXPECT_GT(arm[2], arm[3]);
}

}  // namespace
}  // namespace rollcontact
