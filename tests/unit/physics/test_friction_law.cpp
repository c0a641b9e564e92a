// Coulomb's law as the model describes it: g = μ_s·p_n, zero bound where there is no pressure;
// and the falling laws L = 2, 3, 4 of physics.md §10.1 at their characteristic slip velocities.

#include <gtest/gtest.h>

#include <cmath>

#include "physics/friction_law.hpp"

namespace rollcontact::physics {
namespace {

TEST(FrictionLaw, CoulombBoundIsStaticCoefficientTimesPressure) {
  model::CoulombFriction f;
  f.static_coefficient = 0.3;
  f.kinetic_coefficient = 0.25;
  const auto law = make_friction_law(f);
  EXPECT_DOUBLE_EQ(law->coefficient(), 0.3);
  EXPECT_DOUBLE_EQ(law->traction_bound(1000.0), 300.0);
  std::vector<double> bound;
  law->traction_bounds({1000.0, 0.0, -5.0, 2.0}, bound);
  ASSERT_EQ(bound.size(), 4u);
  EXPECT_DOUBLE_EQ(bound[0], 300.0);
  EXPECT_EQ(bound[1], 0.0);
  EXPECT_EQ(bound[2], 0.0);  // tension is not contact
  EXPECT_DOUBLE_EQ(bound[3], 0.6);
}

TEST(FrictionLaw, FrictionlessContactHasNoBound) {
  const CoulombLaw law(0.0);
  EXPECT_EQ(law.traction_bound(1234.0), 0.0);
}

}  // namespace
}  // namespace rollcontact::physics

namespace rollcontact::physics {
namespace {

model::Friction falling(model::FrictionLawKind kind, double fkin, double f1, double s1, double f2,
                        double s2) {
  model::Friction f;
  f.law = kind;
  f.kinetic_coefficient = fkin;
  f.terms = {model::FallingTerm{f1, s1}, model::FallingTerm{f2, s2}};
  return f;
}

TEST(FallingFriction, StaticValueIsTheSumOfTheTerms) {
  // physics.md §10.1: μ(0) = FKIN + F1 + F2 for every falling law; it scales FX/FSTAT/FN.
  for (const auto kind :
       {model::FrictionLawKind::LinearFalling, model::FrictionLawKind::RationalFalling,
        model::FrictionLawKind::ExponentialFalling}) {
    const auto law = make_friction_law(falling(kind, 0.18, 0.12, 100.0, 0.05, 10.0));
    EXPECT_TRUE(law->velocity_dependent());
    EXPECT_NEAR(law->coefficient(), 0.35, 1e-15);
    EXPECT_NEAR(law->coefficient_at(0.0), 0.35, 1e-15);
    EXPECT_NEAR(law->traction_bound(100.0), 35.0, 1e-12);
  }
}

TEST(FallingFriction, EachLawAtItsCharacteristicSpeeds) {
  using K = model::FrictionLawKind;
  // Exponential: halves at SABSH, quarters at 2·SABSH.
  const auto e = make_friction_law(falling(K::ExponentialFalling, 0.18, 0.12, 100.0, 0.0, 1e-4));
  EXPECT_NEAR(e->coefficient_at(100.0), 0.18 + 0.06, 1e-15);
  EXPECT_NEAR(e->coefficient_at(200.0), 0.18 + 0.03, 1e-15);
  EXPECT_NEAR(e->coefficient_at(1e9), 0.18, 1e-15);
  // Linear: half at SABSH, FKIN from 2·SABSH on.
  const auto l = make_friction_law(falling(K::LinearFalling, 0.2, 0.1, 50.0, 0.0, 1e-4));
  EXPECT_NEAR(l->coefficient_at(50.0), 0.25, 1e-15);
  EXPECT_NEAR(l->coefficient_at(100.0), 0.2, 1e-15);
  EXPECT_NEAR(l->coefficient_at(500.0), 0.2, 1e-15);
  // Rational: F1/(1 + s/S1) and F2/(1 + (s/S2)²), both half at their speed.
  const auto r = make_friction_law(falling(K::RationalFalling, 0.18, 0.06, 100.0, 0.06, 0.3162));
  EXPECT_NEAR(r->coefficient_at(100.0), 0.18 + 0.03 + 0.06 / (1.0 + std::pow(100.0 / 0.3162, 2)),
              1e-15);
  // Monotonically falling.
  for (double s = 0.0; s < 1000.0; s += 7.0)
    EXPECT_GE(e->coefficient_at(s), e->coefficient_at(s + 7.0));
}

}  // namespace
}  // namespace rollcontact::physics

namespace rollcontact::physics {
namespace {

TEST(FrictionLaw, TemperatureLawIsLinearBetweenTrefAndTrefPlusDtheat) {
  // L = 6 (spec-additions B2): FREF up to TREF, FREF + DFHEAT from TREF + DTHEAT on, linear
  // between.
  model::Friction f;
  f.law = model::FrictionLawKind::TemperatureDependent;
  f.static_coefficient = f.kinetic_coefficient = 0.3;
  f.temperature = {100.0, -0.2, 400.0};
  const auto law = make_friction_law(f);
  EXPECT_TRUE(law->temperature_dependent());
  EXPECT_FALSE(law->velocity_dependent());
  EXPECT_DOUBLE_EQ(law->coefficient(), 0.3);  // static value: scales FX/FSTAT/FN
  EXPECT_DOUBLE_EQ(law->traction_bound(1000.0), 300.0);
  EXPECT_DOUBLE_EQ(law->coefficient_at_temperature(-50.0), 0.3);
  EXPECT_DOUBLE_EQ(law->coefficient_at_temperature(100.0), 0.3);
  EXPECT_DOUBLE_EQ(law->coefficient_at_temperature(200.0), 0.25);
  EXPECT_DOUBLE_EQ(law->coefficient_at_temperature(500.0), 0.1);
  EXPECT_DOUBLE_EQ(law->coefficient_at_temperature(900.0), 0.1);
  // Other laws do not depend on the temperature.
  EXPECT_DOUBLE_EQ(CoulombLaw(0.4).coefficient_at_temperature(900.0), 0.4);
}

}  // namespace
}  // namespace rollcontact::physics
