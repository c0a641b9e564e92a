// Temperature-dependent friction (L = 6, spec/physics.md §10.1, §10.3): the fixed point on body
// 1's surface temperature around the unchanged tangential solvers. A flat law is Coulomb's; a
// law that is constant over the temperatures that occur is Coulomb's with that constant; and in
// the converged solution every sliding element sits on μ(T) at its own final temperature.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "physics/friction_law.hpp"
#include "rollcontact/solve.hpp"
#include "support/hertz_problem.hpp"

namespace rollcontact {
namespace {

/// Circular Hertzian contact (a = b = 3 mm, FN = 10 kN) of steel bodies rolling at 20 m/s with
/// creepage ξ (ξ = 0.05: full sliding at 1 m/s), heat calculation on, bulk temperature `bulk_C`.
model::PatchProblem rolling_problem(double creepage, double bulk_C) {
  model::PatchProblem p = test::hertz_problem(3.0, 3.0, 1e4, 82000.0, 0.28, 40, 40, 1.1);
  p.tangential.kind = model::TangentialKind::SteadyRolling;
  p.tangential.creepage.longitudinal = creepage;
  p.rolling = {0.0, 2.0 * 3.0 * 1.1 / 40, 20000.0, 1.0 / 6.0};
  p.heat.enabled = true;
  p.heat.body1 = p.heat.body2 = {bulk_C, 450.0, 50e-3, 7.85e-6};
  return p;
}

/// μ = 0.3 up to 20 °C falling to 0.15 at 220 °C.
model::PatchProblem with_temperature_law(model::PatchProblem p, double change) {
  p.friction.law = model::FrictionLawKind::TemperatureDependent;
  p.friction.static_coefficient = p.friction.kinetic_coefficient = 0.3;
  p.friction.temperature = {20.0, change, 200.0};
  return p;
}

TEST(TemperatureFriction, FlatLawIsCoulomb) {
  PatchSolver coulomb_solver, flat_solver;
  const Solution coulomb = coulomb_solver.solve(rolling_problem(0.002, 20.0));
  const Solution flat = flat_solver.solve(with_temperature_law(rolling_problem(0.002, 20.0), 0.0));
  ASSERT_TRUE(flat.solver.converged) << flat.solver.message;
  EXPECT_NEAR(flat.totals.fx, coulomb.totals.fx, 1e-8 * coulomb.totals.fn);
  EXPECT_NEAR(flat.totals.max_temp1, coulomb.totals.max_temp1, 1e-6);
  EXPECT_EQ(flat.statistics.nslip, coulomb.statistics.nslip);
}

TEST(TemperatureFriction, HotBodiesSlideOnTheHotCoefficient) {
  // Bulk 300 °C ≥ TREF + DTHEAT: μ = FREF + DFHEAT = 0.15 wherever the contact is, so the result
  // is Coulomb's with μ = 0.15 (full sliding: FX = 0.15·FN).
  PatchSolver hot_solver, coulomb_solver;
  const Solution hot = hot_solver.solve(with_temperature_law(rolling_problem(0.05, 300.0), -0.15));
  model::PatchProblem coulomb = rolling_problem(0.05, 300.0);
  coulomb.friction = {0.15, 0.15};
  const Solution reference = coulomb_solver.solve(coulomb);
  ASSERT_TRUE(hot.solver.converged) << hot.solver.message;
  EXPECT_NEAR(hot.totals.fx, reference.totals.fx, 1e-8 * reference.totals.fn);
  EXPECT_NEAR(std::abs(hot.totals.fx), 0.15 * hot.totals.fn, 1e-3 * hot.totals.fn);
}

TEST(TemperatureFriction, SlidingElementsSitOnTheLawAtTheirTemperature) {
  // Full sliding at 1 m/s heats the surface by 100s of °C: μ falls from 0.3 towards 0.15. The
  // fixed point converges (ITANG counts its passes) and leaves |p_t| = μ(T₁)·p_n in every
  // element, with T₁ the final surface temperature of body 1.
  PatchSolver solver;
  model::PatchProblem p = with_temperature_law(rolling_problem(0.05, 20.0), -0.15);
  const Solution s = solver.solve(p);
  ASSERT_TRUE(s.solver.converged) << s.solver.message;
  EXPECT_GE(s.statistics.itang, 2);
  ASSERT_EQ(s.statistics.nadh, 0);
  const auto law = physics::make_friction_law(p.friction);
  double worst = 0.0;
  for (std::size_t i = 0; i < s.pn.size(); ++i) {
    if (s.pn[i] <= 0.0) continue;
    const double mu = law->coefficient_at_temperature(s.temp1[i]);
    EXPECT_NEAR(s.mu[i], mu, 2e-3) << i;
    worst = std::max(worst, std::abs(std::hypot(s.px[i], s.py[i]) - mu * s.pn[i]) / s.pn[i]);
  }
  EXPECT_LT(worst, 2e-3);
  // Friction fell with the heat: FX/FN between the hot and the cold coefficient.
  const double mean_mu = std::abs(s.totals.fx) / s.totals.fn;
  EXPECT_LT(mean_mu, 0.29);
  EXPECT_GT(mean_mu, 0.15);
  // Less friction, less heat: cooler than the same case with Coulomb's μ = 0.3.
  PatchSolver coulomb_solver;
  const Solution coulomb = coulomb_solver.solve(rolling_problem(0.05, 20.0));
  EXPECT_LT(s.totals.max_temp1, coulomb.totals.max_temp1);
}

}  // namespace
}  // namespace rollcontact
