// Eqs 4–10 of Ma et al. (2018) against values computed by hand for the paper's steel
// (E = 210 GPa, ν = 0.3, ρ = 7900 kg/m³) and the table of spec dynamic-rolling.md §3.

#include <gtest/gtest.h>

#include <cmath>

#include "rollcontact/errors.hpp"
#include "rollcontact/fe_advice.hpp"

namespace rollcontact::fe_advice {
namespace {

const FeMaterial kSteel{};  // the paper's steel is the default

TEST(FeAdviceFormulas, BulkModulusAndWaveSpeedOfThePapersSteel) {
  // K = 210000/(3·0.4) = 175000 N/mm²; c = √(210000·0.7/(7.9e-9·1.3·0.4)) = 5981.96 m/s.
  EXPECT_NEAR(bulk_modulus_N_mm2(kSteel), 175000.0, 1e-9);
  EXPECT_NEAR(dilatational_wave_speed_mm_s(kSteel), 5.98196e6, 10.0);
  EXPECT_NEAR(dilatational_wave_speed_mm_s(kSteel) / 1e3, 5982.0, 0.5);  // [m/s], spec §3
}

TEST(FeAdviceFormulas, CourantStepOfAOneMillimetreElement) {
  // 1 mm / 5981.96 m/s = 0.167169 µs; LS-DYNA's TSSFAC 0.9 makes it 0.150452 µs.
  EXPECT_NEAR(courant_time_step_s(1.0, kSteel, 1.0), 1.67169e-7, 1e-12);
  EXPECT_NEAR(courant_time_step_s(1.0, kSteel), 1.50452e-7, 1e-12);
  EXPECT_NEAR(courant_time_step_s(2.0, kSteel), 2.0 * courant_time_step_s(1.0, kSteel), 1e-20);
}

TEST(FeAdviceFormulas, PenaltyStiffnessOfEq6) {
  // C_d = 1 mm: α = 0.1 → 17500 N/mm = 1.75e7 N/m; α = 12.8 → 2.24e9 N/m (spec §3, eq 6).
  EXPECT_NEAR(penalty_stiffness_N_mm(0.1, 175000.0, 1.0) * 1e3, 1.75e7, 1e-6);
  EXPECT_NEAR(penalty_stiffness_N_mm(12.8, 175000.0, 1.0) * 1e3, 2.24e9, 1e-3);
  EXPECT_NEAR(penalty_stiffness_N_mm(0.1, 175000.0, 2.0), 35000.0, 1e-9);
}

TEST(FeAdviceFormulas, NodalMassAndContactTimeStepOfEq8) {
  // m = ¼·7.9e-9 t = 1.975e-9 t (1.975e-6 kg); 2√(m/k) = 0.67188 µs at α = 0.1 (spec: 0.67 µs).
  const double m = nodal_mass_t(1.0, kSteel.density_t_mm3);
  EXPECT_NEAR(m, 1.975e-9, 1e-21);
  EXPECT_NEAR(contact_time_step_undamped_s(m, 17500.0), 6.71884e-7, 1e-12);
  // The spec's illustration: 0.059, 0.021, 0.015, 0.0105 µs at α = 12.8, 102.4, 204.8, 409.6.
  const double expected_us[] = {0.0594, 0.0210, 0.0148, 0.0105};
  const double alphas[] = {12.8, 102.4, 204.8, 409.6};
  for (int i = 0; i < 4; ++i) {
    const double k = penalty_stiffness_N_mm(alphas[i], 175000.0, 1.0);
    EXPECT_NEAR(contact_time_step_undamped_s(m, k) * 1e6, expected_us[i], 5e-4) << alphas[i];
  }
}

TEST(FeAdviceFormulas, DampingReductionFactorsOfEq9) {
  // The table of spec §3: √(1 + ξ²) − ξ for VDC = 10 … 180.
  const double vdc[] = {10, 20, 40, 60, 80, 100, 120, 140, 160, 180};
  const double factor[] = {0.905, 0.820, 0.677, 0.566, 0.481, 0.414, 0.362, 0.321, 0.287, 0.259};
  for (int i = 0; i < 10; ++i)
    EXPECT_NEAR(damping_reduction_factor(damping_ratio_from_vdc(vdc[i])), factor[i], 6e-4)
        << "VDC " << vdc[i];
  EXPECT_DOUBLE_EQ(damping_reduction_factor(0.0), 1.0);
  EXPECT_NEAR(contact_time_step_s(1.975e-9, 17500.0, 0.8), 6.71884e-7 * (std::sqrt(1.64) - 0.8),
              1e-12);
}

TEST(FeAdviceFormulas, StabilityVerdictAndInterfaceCompliance) {
  EXPECT_TRUE(contact_stable(1.0e-7, 1.0e-7));
  EXPECT_FALSE(contact_stable(1.0000001e-7, 1.0e-7));
  // L = C_d²/k = C_d/(αK): 1 mm, α = 0.1 → 1/17500 mm³/N.
  EXPECT_NEAR(interface_compliance_mm3_N(1.0, 17500.0), 1.0 / 17500.0, 1e-18);
  EXPECT_NEAR(interface_compliance_mm3_N(2.0, 35000.0), 2.0 / 17500.0, 1e-18);
}

TEST(FeAdviceFormulas, RefusesValuesWithoutMeaning) {
  EXPECT_THROW((void)courant_time_step_s(0.0, kSteel), InvalidValueError);
  EXPECT_THROW((void)courant_time_step_s(-1.0, kSteel), InvalidValueError);
  EXPECT_THROW((void)penalty_stiffness_N_mm(0.0, 175000.0, 1.0), InvalidValueError);
  EXPECT_THROW((void)penalty_stiffness_N_mm(NAN, 175000.0, 1.0), InvalidValueError);
  EXPECT_THROW((void)damping_ratio_from_vdc(-1.0), InvalidValueError);
  EXPECT_THROW((void)bulk_modulus_N_mm2({210000.0, 0.5, 7.9e-9}), InvalidValueError);
  EXPECT_THROW((void)bulk_modulus_N_mm2({-1.0, 0.3, 7.9e-9}), InvalidValueError);
  EXPECT_THROW((void)nodal_mass_t(1.0, 0.0), InvalidValueError);
  try {
    (void)courant_time_step_s(-2.0, kSteel);
  } catch (const InvalidValueError& e) {
    EXPECT_EQ(e.field(), "element_size_mm");
    EXPECT_NE(std::string(e.what()).find("-2"), std::string::npos);
  }
}

}  // namespace
}  // namespace rollcontact::fe_advice
