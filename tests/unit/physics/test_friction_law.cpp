// Coulomb's law as the model describes it: g = μ_s·p_n, zero bound where there is no pressure.

#include <gtest/gtest.h>

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
