// The exact tangential solvers against closed-form solutions: Cattaneo (shift of a sphere),
// Carter (2-D steady rolling) and Kalker's linear theory (creep coefficients).

#include <gtest/gtest.h>

#include <cmath>

#include "rollcontact/solve.hpp"
#include "support/hertz_problem.hpp"

namespace rollcontact {
namespace {

// Cattaneo–Mindlin: a sphere pressed with FN and loaded by Q = f·μFN shifts by
// δ = 3μFN(2−ν)/(8 G a) · [1 − (1 − f)^{2/3}] (identical bodies, Johnson, Contact Mechanics §7.2).
TEST(AnalyticTangential, CattaneoShiftOfASphere) {
  const double a = 1.0, g = 200.0, nu = 0.42, mu = 0.4, fn = 9.1954, f = 0.875;
  model::PatchProblem p = test::hertz_problem(a, a, fn, g, nu, 31, 31, 1.1);
  p.tangential.kind = test::tangential_kind(1);
  p.tangential.prescribed = model::TangentialPrescribed::Forces;
  p.tangential.force_x_over_mu_fn = -f;
  p.tangential.force_y_over_mu_fn = 0.0;
  p.friction = {mu, mu};
  p.solver.tolerance = 1e-6;
  PatchSolver state;
  const Solution s = state.solve(p);
  ASSERT_TRUE(s.solver.converged) << s.solver.message;
  const double analytic =
      3.0 * mu * fn * (2.0 - nu) / (8.0 * g * a) * (1.0 - std::cbrt(std::pow(1.0 - f, 2.0)));
  EXPECT_NEAR(analytic, 0.00817, 0.00001);  // the value quoted with cattaneo.inp
  // 31 × 31 elements over 2.2 mm: the discrete answer is within 2 % (issue acceptance).
  EXPECT_NEAR(s.totals.shift_x, analytic, 0.02 * analytic);
  EXPECT_NEAR(s.totals.fx, -f * mu * fn, 1e-5 * mu * fn);
  // The adhesion area is a circle of radius a(1 − f)^{1/3} = 0.5 a.
  const double adhesion_area = s.statistics.nadh * s.grid.element_area();
  EXPECT_NEAR(adhesion_area, std::acos(-1.0) * 0.25, 0.15 * std::acos(-1.0) * 0.25);
}

// Carter (1926): 2-D steady rolling of identical cylinders, relative radius R, half width a:
// the adhesion zone at the leading edge has half width a′ = a(1 − |ξ|R/(μa)) and
// FX = −sign(ξ)·μFN·(1 − (a′/a)²).
double carter_force_ratio(double dx) {
  const double r = 500.0, mu = 0.3, xi = -0.00024, g = 82000.0, nu = 0.28;
  const double estar = g / (1.0 - nu);
  const double a = 1.0, width = 200.0;
  const double fn = std::acos(-1.0) * a * a * estar / (4.0 * r) * width;  // a² = 4 R F′/(π E*)
  model::PatchProblem p;
  p.tangential.kind = test::tangential_kind(3);
  p.solver.tolerance = 1e-7;
  p.solver.max_inner_iterations = 999;
  p.normal.force_N = fn;
  p.tangential.creepage.longitudinal = xi;
  p.rolling.direction_rad = 0.0;
  p.rolling.step_mm = dx;
  p.rolling.velocity_mm_per_s = 30000.0;
  p.friction = {mu, mu};
  p.bodies.body1 = p.bodies.body2 = {nu, g};
  const int mx = static_cast<int>(std::lround(2.2 * a / dx));
  p.potential.ipotcn = 1;
  p.potential.mx = mx;
  p.potential.my = 1;
  p.potential.values = {-0.5 * mx * dx, -0.5 * width, dx, width};
  p.gap.ibase = 1;
  p.gap.coeffs = {1.0 / (2.0 * r), 0.0, 0.0, 0.0, 0.0, 0.0};
  PatchSolver state;
  const Solution s = state.solve(p);
  EXPECT_TRUE(s.solver.converged) << s.solver.message;
  return s.totals.fx / (mu * s.totals.fn);
}

TEST(AnalyticTangential, CarterSteadyRollingConvergesToTheAnalyticForce) {
  const double analytic = 1.0 - 0.6 * 0.6;  // |ξ|R/(μa) = 0.4
  const double coarse = carter_force_ratio(0.04);
  const double fine = carter_force_ratio(0.01);
  EXPECT_NEAR(coarse, 0.648, 0.002);  // carter2d.ref_out: FX/FSTAT/FN = 0.6480 at dx = 0.04
  EXPECT_LT(std::abs(fine - analytic), std::abs(coarse - analytic));
  EXPECT_NEAR(fine, analytic, 0.01 * analytic);
}

}  // namespace
}  // namespace rollcontact
