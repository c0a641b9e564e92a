#include <gtest/gtest.h>

#include <cmath>

#include "post/stress_invariants.hpp"

namespace rollcontact::post {
namespace {

TEST(StressInvariants, DiagonalTensor) {
  const Matrix3 s{{{-1.0, 0.0, 0.0}, {0.0, 2.0, 0.0}, {0.0, 0.0, 0.5}}};
  const StressInvariants r = stress_invariants(s);
  EXPECT_NEAR(r.principal[0], 2.0, 1e-14);
  EXPECT_NEAR(r.principal[1], 0.5, 1e-14);
  EXPECT_NEAR(r.principal[2], -1.0, 1e-14);
  EXPECT_NEAR(r.hydrostatic, 0.5, 1e-15);
  EXPECT_NEAR(r.tresca, 3.0, 1e-14);
  // σ_vm² = ½[(σ1−σ2)² + (σ2−σ3)² + (σ3−σ1)²]
  EXPECT_NEAR(r.von_mises, std::sqrt(0.5 * (2.25 + 2.25 + 9.0)), 1e-14);
}

TEST(StressInvariants, GeneralTensorSatisfiesCharacteristicEquation) {
  const Matrix3 s{{{0.3, -0.7, 0.2}, {-0.7, -1.1, 0.4}, {0.2, 0.4, 0.9}}};
  const StressInvariants r = stress_invariants(s);
  EXPECT_GE(r.principal[0], r.principal[1]);
  EXPECT_GE(r.principal[1], r.principal[2]);
  EXPECT_NEAR(r.principal[0] + r.principal[1] + r.principal[2], 0.3 - 1.1 + 0.9, 1e-13);
  for (double l : r.principal) {
    // det(σ − λI) = 0
    const double a = s[0][0] - l, b = s[1][1] - l, c = s[2][2] - l;
    const double det = a * (b * c - s[1][2] * s[1][2]) -
                       s[0][1] * (s[0][1] * c - s[1][2] * s[0][2]) +
                       s[0][2] * (s[0][1] * s[1][2] - b * s[0][2]);
    EXPECT_NEAR(det, 0.0, 1e-12);
  }
  // Pure shear: von Mises = √3 τ.
  const Matrix3 shear{{{0.0, 1.0, 0.0}, {1.0, 0.0, 0.0}, {0.0, 0.0, 0.0}}};
  EXPECT_NEAR(stress_invariants(shear).von_mises, std::sqrt(3.0), 1e-14);
  EXPECT_NEAR(stress_invariants(shear).tresca, 2.0, 1e-14);
}

}  // namespace
}  // namespace rollcontact::post
