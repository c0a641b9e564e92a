// Eq 10 over the paper's penalty factors: Δt_cont ∝ α^−½, the boundary where it meets Δt_calc,
// and the calculation step from the mesh.

#include <gtest/gtest.h>

#include <cmath>

#include "rollcontact/errors.hpp"
#include "rollcontact/fe_advice.hpp"

namespace rollcontact::fe_advice {
namespace {

TEST(FeStabilityAdvice, SweepIsThePapersPenaltyFactors) {
  const std::vector<double> a = penalty_factor_sweep();
  ASSERT_EQ(a.size(), 14u);
  EXPECT_DOUBLE_EQ(a.front(), 0.05);
  EXPECT_DOUBLE_EQ(a[1], 0.1);
  EXPECT_DOUBLE_EQ(a[8], 12.8);
  EXPECT_DOUBLE_EQ(a.back(), 409.6);
}

TEST(FeStabilityAdvice, ContactTimeStepFallsAsOneOverRootAlpha) {
  const FeContactSettings s;
  const std::vector<double> alphas = penalty_factor_sweep();
  const StabilityAdvice first = stability_advice(s, alphas.front());
  for (const double alpha : alphas) {
    const StabilityAdvice a = stability_advice(s, alpha);
    const double expected = std::sqrt(first.penalty_factor / alpha);
    EXPECT_NEAR(a.contact_time_step_undamped_s / first.contact_time_step_undamped_s, expected,
                1e-12 * expected);
    EXPECT_NEAR(a.contact_time_step_s / first.contact_time_step_s, expected, 1e-12 * expected);
    // VDC 80: eq 9 is eq 8 times √1.64 − 0.8 = 0.4806 at every α.
    EXPECT_NEAR(a.contact_time_step_s / a.contact_time_step_undamped_s, 0.4806, 1e-4);
  }
}

TEST(FeStabilityAdvice, DefaultCalculationStepIsTheCourantStepOfTheSmallestElement) {
  FeContactSettings s;  // 1 mm contact elements, TSSFAC 0.9
  EXPECT_NEAR(calculation_time_step_s(s), 1.50452e-7, 1e-12);
  s.smallest_element_mm = 0.12;
  EXPECT_NEAR(calculation_time_step_s(s), 0.12 * 1.50452e-7, 1e-12);
  s.calc_time_step_s = 1.8e-8;  // given: wins
  EXPECT_DOUBLE_EQ(calculation_time_step_s(s), 1.8e-8);
}

TEST(FeStabilityAdvice, BoundaryIsWhereContactAndCalculationStepsMeet) {
  FeContactSettings s;
  for (const bool damped : {false, true}) {
    const double alpha = stability_boundary_penalty_factor(s, damped);
    const StabilityAdvice at = stability_advice(s, alpha);
    const double dt_cont = damped ? at.contact_time_step_s : at.contact_time_step_undamped_s;
    EXPECT_NEAR(dt_cont, at.calc_time_step_s, 1e-12 * dt_cont);
    const StabilityAdvice above = stability_advice(s, 1.001 * alpha);
    const StabilityAdvice below = stability_advice(s, 0.999 * alpha);
    EXPECT_FALSE(damped ? above.stable : above.stable_undamped);
    EXPECT_TRUE(damped ? below.stable : below.stable_undamped);
  }
  // With the Courant step of the 1 mm contact elements themselves the undamped boundary is
  // α = (0.67188/0.150452)²·0.1 = 1.99 (docs/fe-advice.md: far below the paper's ≈ 100).
  EXPECT_NEAR(stability_boundary_penalty_factor(s, false), 1.994, 1e-3);
}

TEST(FeStabilityAdvice, PapersTimeStepPutsTheBoundaryBetween102And205) {
  // Δt_calc = 0.018 µs (inferred from the paper's VDC study, docs/fe-advice.md): the undamped
  // boundary lies at α ≈ 139, i.e. 102.4 stable and 204.8 unstable as in the paper's Fig. 4b.
  FeContactSettings s;
  s.calc_time_step_s = 1.8e-8;
  const double alpha = stability_boundary_penalty_factor(s, false);
  EXPECT_GT(alpha, 102.4);
  EXPECT_LT(alpha, 204.8);
  EXPECT_TRUE(stability_advice(s, 102.4).stable_undamped);
  EXPECT_FALSE(stability_advice(s, 204.8).stable_undamped);
  // The same step by eq 9 at α = 12.8: VDC 140 stable, VDC 160 unstable (the paper's Fig. 16).
  s.vdc_percent = 140.0;
  EXPECT_TRUE(stability_advice(s, 12.8).stable);
  s.vdc_percent = 160.0;
  EXPECT_FALSE(stability_advice(s, 12.8).stable);
}

TEST(FeStabilityAdvice, RefusesBadSettings) {
  FeContactSettings s;
  s.element_size_mm = 0.0;
  EXPECT_THROW((void)stability_advice(s, 1.0), InvalidValueError);
  s = {};
  s.vdc_percent = -5.0;
  EXPECT_THROW((void)stability_advice(s, 1.0), InvalidValueError);
  s = {};
  s.calc_time_step_s = -1e-8;
  EXPECT_THROW((void)calculation_time_step_s(s), InvalidValueError);
  s = {};
  EXPECT_THROW((void)stability_advice(s, -0.1), InvalidValueError);
}

}  // namespace
}  // namespace rollcontact::fe_advice
