// Combined material constants (spec/physics.md §3.1) against the CONTACT reference outputs.

#include <gtest/gtest.h>

#include <limits>

#include "elastic/material.hpp"
#include "rollcontact/errors.hpp"

namespace rollcontact::elastic {
namespace {

TEST(CombineMaterials, BentallAluminiumOnSteel) {
  // bentall.inp: POISS 0.310 0.280, GG 23000 82000. bentall.ref_out prints Ak = 0.1002;
  // physics.md §3.1 gives G = 35 924 and ν = 0.3034 (printed digits: tolerance half a unit).
  const CombinedMaterial m = combine_materials(0.31, 0.28, 23000.0, 82000.0);
  EXPECT_NEAR(m.g, 35924.0, 0.5);
  EXPECT_NEAR(m.nu, 0.3034, 0.5e-4);
  EXPECT_NEAR(m.k, 0.1002, 0.5e-4);
}

TEST(CombineMaterials, Spence35SoftOnRigid) {
  // spence35.inp: POISS 0 0, GG 0.5 1e5; spence35.ref_out prints NU 0.000, G 1.000, AK 0.5000.
  const CombinedMaterial m = combine_materials(0.0, 0.0, 0.5, 1e5);
  EXPECT_NEAR(m.g, 1.0, 0.5e-3);
  EXPECT_EQ(m.nu, 0.0);
  EXPECT_NEAR(m.k, 0.5, 0.5e-4);
}

TEST(CombineMaterials, ExactFormulas) {
  const double nu1 = 0.25, nu2 = 0.4, g1 = 70.0, g2 = 30.0;
  const CombinedMaterial m = combine_materials(nu1, nu2, g1, g2);
  const double g = 1.0 / (0.5 * (1.0 / g1 + 1.0 / g2));
  EXPECT_NEAR(m.g, g, 1e-13 * g);
  EXPECT_NEAR(m.nu, g * 0.5 * (nu1 / g1 + nu2 / g2), 1e-15);
  EXPECT_NEAR(m.k, 0.25 * g * ((1 - 2 * nu1) / g1 - (1 - 2 * nu2) / g2), 1e-15);
  EXPECT_NEAR(contact_modulus(m), m.g / (1.0 - m.nu), 1e-12 * m.g);
}

TEST(CombineMaterials, IdenticalBodiesAreQuasiIdentical) {
  const CombinedMaterial m = combine_materials(0.28, 0.28, 82000.0, 82000.0);
  EXPECT_NEAR(m.g, 82000.0, 1e-9);
  EXPECT_NEAR(m.nu, 0.28, 1e-15);
  EXPECT_EQ(m.k, 0.0);
}

TEST(CombineMaterials, SwappingBodiesFlipsK) {
  const CombinedMaterial a = combine_materials(0.31, 0.28, 23000.0, 82000.0);
  const CombinedMaterial b = combine_materials(0.28, 0.31, 82000.0, 23000.0);
  EXPECT_DOUBLE_EQ(a.g, b.g);
  EXPECT_DOUBLE_EQ(a.nu, b.nu);
  EXPECT_DOUBLE_EQ(a.k, -b.k);
  EXPECT_GT(a.k, 0.0);
}

TEST(CombineMaterials, IncompressibleBodiesHaveNoCoupling) {
  EXPECT_EQ(combine_materials(0.5, 0.5, 1.0, 5.0).k, 0.0);
}

TEST(CombineMaterials, RejectsInadmissibleData) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(combine_materials(0.3, 0.3, 0.0, 1.0), ProblemError);
  EXPECT_THROW(combine_materials(0.3, 0.3, 1.0, -2.0), ProblemError);
  EXPECT_THROW(combine_materials(-0.01, 0.3, 1.0, 1.0), ProblemError);
  EXPECT_THROW(combine_materials(0.3, 0.51, 1.0, 1.0), ProblemError);
  EXPECT_THROW(combine_materials(nan, 0.3, 1.0, 1.0), ProblemError);
  EXPECT_THROW(combine_materials(0.3, 0.3, nan, 1.0), ProblemError);
  EXPECT_NO_THROW(combine_materials(0.0, 0.5, 1.0, 1.0));
}

}  // namespace
}  // namespace rollcontact::elastic
