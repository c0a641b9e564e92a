// T13-8 of spec dynamic-rolling.md §6.4: the penalty oscillator integrated with eq 2 is bounded
// for Δt ≤ 0.999·Δt_cont and grows for Δt ≥ 1.001·Δt_cont (eq 9) for ξ = 0, 0.8 and 1.8, and the
// measured growth is the analytic spectral radius of the scheme.

#include <gtest/gtest.h>

#include <cmath>

#include "rollcontact/fe_advice.hpp"

namespace rollcontact::fe_advice {
namespace {

// The paper's contact node: C_d = 1 mm, recommended α = 12.8.
PenaltyOscillator paper_node(double xi) {
  return {nodal_mass_t(1.0, 7.9e-9), penalty_stiffness_N_mm(12.8, 175000.0, 1.0), xi};
}

class PenaltyOscillatorSwitch : public ::testing::TestWithParam<double> {};

TEST_P(PenaltyOscillatorSwitch, BoundedBelowAndGrowingAboveTheContactTimeStep) {
  const PenaltyOscillator o = paper_node(GetParam());
  const double dt_cont = contact_time_step_s(o.mass_t, o.stiffness_N_mm, o.damping_ratio);
  const OscillatorRun below = run_penalty_oscillator(o, 0.999 * dt_cont);
  const OscillatorRun above = run_penalty_oscillator(o, 1.001 * dt_cont);
  EXPECT_TRUE(below.bounded) << below.growth_per_step;
  EXPECT_LE(below.growth_per_step, 1.0 + 1e-6);
  EXPECT_FALSE(above.bounded) << above.growth_per_step;
  EXPECT_GT(above.growth_per_step, 1.002);  // ≥ 1.0023 per step for ξ ≤ 1.8
  EXPECT_GT(above.growth_per_period, 1.0);
}

INSTANTIATE_TEST_SUITE_P(DampingRatios, PenaltyOscillatorSwitch, ::testing::Values(0.0, 0.8, 1.8));

TEST(PenaltyOscillator, MeasuredGrowthIsTheSpectralRadiusOfTheScheme) {
  for (const double xi : {0.0, 0.3, 0.8, 1.8})
    for (const double f : {0.5, 0.9, 0.999, 1.001, 1.05}) {
      const PenaltyOscillator o = paper_node(xi);
      const double dt = f * contact_time_step_s(o.mass_t, o.stiffness_N_mm, xi);
      const OscillatorRun run = run_penalty_oscillator(o, dt);
      EXPECT_NEAR(run.growth_per_step, run.spectral_radius, 1e-4) << "xi " << xi << " f " << f;
      EXPECT_EQ(run.bounded, run.spectral_radius <= 1.0 + 1e-9) << "xi " << xi << " f " << f;
    }
}

TEST(PenaltyOscillator, Eq9IsTheExactLimitOfTheScheme) {
  // The spectral radius is 1 exactly at Ω = 2(√(1+ξ²) − ξ), below 1 just under and above 1 just
  // over it (ξ > 0; ξ = 0 is neutral below the limit).
  for (const double xi : {0.0, 0.1, 0.8, 1.8, 5.0}) {
    const double limit = 2.0 * damping_reduction_factor(xi);
    EXPECT_NEAR(central_difference_spectral_radius(limit, xi), 1.0, 1e-6) << xi;
    EXPECT_GT(central_difference_spectral_radius(limit * 1.001, xi), 1.0) << xi;
    EXPECT_LE(central_difference_spectral_radius(limit * 0.999, xi), 1.0 + 1e-12) << xi;
  }
  EXPECT_NEAR(central_difference_spectral_radius(0.5, 0.0), 1.0, 1e-12);  // undamped: neutral
  EXPECT_LT(central_difference_spectral_radius(0.5, 0.8), 1.0);
}

TEST(PenaltyOscillator, TheSwitchDoesNotDependOnThePenaltyFactor) {
  // Δt_cont ∝ α^−½ and the run at Δt/Δt_cont is the same for every α: the scheme sees only Ω.
  for (const double alpha : penalty_factor_sweep()) {
    const PenaltyOscillator o{nodal_mass_t(1.0, 7.9e-9),
                              penalty_stiffness_N_mm(alpha, 175000.0, 1.0), 0.8};
    const double dt = contact_time_step_s(o.mass_t, o.stiffness_N_mm, 0.8);
    EXPECT_TRUE(run_penalty_oscillator(o, 0.999 * dt).bounded) << alpha;
    EXPECT_FALSE(run_penalty_oscillator(o, 1.001 * dt).bounded) << alpha;
  }
}

}  // namespace
}  // namespace rollcontact::fe_advice
