// The friction disk |p| ≤ g: projection, slip test and the derivative of the projection that
// semismooth Newton uses (checked against central differences of the projection itself).

#include <gtest/gtest.h>

#include <cmath>

#include "physics/friction_disk.hpp"

namespace rollcontact::physics {
namespace {

TEST(FrictionDisk, ProjectionKeepsInteriorScalesExteriorZeroesWithoutBound) {
  double x = 0.3, y = -0.4;  // |p| = 0.5
  project_onto_disk(x, y, 1.0);
  EXPECT_EQ(x, 0.3);
  EXPECT_EQ(y, -0.4);
  project_onto_disk(x, y, 0.25);  // onto the rim, same direction
  EXPECT_NEAR(std::hypot(x, y), 0.25, 1e-15);
  EXPECT_NEAR(x / y, 0.3 / -0.4, 1e-14);
  project_onto_disk(x, y, 0.0);
  EXPECT_EQ(x, 0.0);
  EXPECT_EQ(y, 0.0);
  EXPECT_FALSE(std::signbit(x));  // a positive zero, not −0 (printed the same everywhere)
}

TEST(FrictionDisk, ProjectionIsIdempotentAndNonExpansive) {
  // ‖P(a) − P(b)‖ ≤ ‖a − b‖ for a convex set, and P(P(z)) = P(z).
  const double pts[][2] = {{2.0, 1.0}, {-0.1, 0.2}, {0.0, -3.0}, {0.7, 0.7}};
  for (const auto& a : pts)
    for (const auto& b : pts) {
      double ax = a[0], ay = a[1], bx = b[0], by = b[1];
      project_onto_disk(ax, ay, 1.0);
      project_onto_disk(bx, by, 1.0);
      EXPECT_LE(std::hypot(ax - bx, ay - by), std::hypot(a[0] - b[0], a[1] - b[1]) + 1e-15);
      double cx = ax, cy = ay;
      project_onto_disk(cx, cy, 1.0);
      EXPECT_EQ(cx, ax);
      EXPECT_EQ(cy, ay);
    }
}

TEST(FrictionDisk, SlipTestCountsTheRimWithinRoundingAsSlip) {
  EXPECT_TRUE(slips(1.0, 1.0));
  EXPECT_TRUE(slips(1.0 - 1e-12, 1.0));  // projected onto the rim, a few ulp short
  EXPECT_FALSE(slips(1.0 - 1e-6, 1.0));
  EXPECT_TRUE(slips(0.0, 0.0));  // no pressure: slip by definition
}

TEST(FrictionDisk, LinearisationMatchesDifferencesOfTheProjection) {
  const double g = 0.8, h = 1e-6;
  const double zs[][2] = {{1.5, -0.6}, {0.2, 0.3}, {-2.0, 0.1}};
  for (const auto& z : zs) {
    const DiskLinearisation lin = linearise_disk_projection(z[0], z[1], g);
    const bool outside = std::hypot(z[0], z[1]) > g;
    EXPECT_EQ(lin.region,
              outside ? DiskLinearisation::Region::Exterior : DiskLinearisation::Region::Interior);
    for (int k = 0; k < 2; ++k) {
      // Column k of the Jacobian: κ (I − n nᵀ) outside, I inside.
      double px = z[0] + (k == 0 ? h : 0.0), py = z[1] + (k == 1 ? h : 0.0);
      double mx = z[0] - (k == 0 ? h : 0.0), my = z[1] - (k == 1 ? h : 0.0);
      project_onto_disk(px, py, g);
      project_onto_disk(mx, my, g);
      const double jx = (px - mx) / (2 * h), jy = (py - my) / (2 * h);
      const double n[2] = {lin.nx, lin.ny};
      const double ex = outside ? lin.kappa * ((k == 0 ? 1.0 : 0.0) - n[0] * n[k]) : (k == 0);
      const double ey = outside ? lin.kappa * ((k == 1 ? 1.0 : 0.0) - n[1] * n[k]) : (k == 1);
      EXPECT_NEAR(jx, ex, 1e-8);
      EXPECT_NEAR(jy, ey, 1e-8);
    }
  }
  EXPECT_EQ(linearise_disk_projection(1.0, 1.0, 0.0).region, DiskLinearisation::Region::ZeroBound);
}

}  // namespace
}  // namespace rollcontact::physics
