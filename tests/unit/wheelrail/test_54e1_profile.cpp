// The 54E1 rail head of examples/profiles/54E1_head.prr (written by scripts/make_54e1_profile.py)
// as rollcontact reads it: the EN 13674-1 design geometry (R300 crown, R80 shoulders, R13
// corners, 1:20 flanks, head width 70 mm), tangent continuity and symmetry. The tolerances are
// those of a cubic spline through points 0.1 mm apart on the arcs (its curvature is exact to
// O(h²/R²) except within a few nodes of the curvature jumps at the tangent points).

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "format/profiles/profile_points.hpp"
#include "format/profiles/profile_reader.hpp"
#include "wheelrail/profile_curve.hpp"

namespace rollcontact::wheelrail {
namespace {

const std::filesystem::path kProfile = std::filesystem::path(ROLLCONTACT_TEST_DATA_DIR) / ".." /
                                       ".." / "examples" / "profiles" / "54E1_head.prr";

/// The file read as an .inp rail profile line reads it (MIRRORZ = −1: z is already downward).
model::WheelRailProfile read_54e1() {
  format::ProfileOptions options;
  options.mirror_z = -1;
  std::vector<std::string> warnings;
  model::WheelRailProfile p;
  p.points = format::read_profile_file(kProfile, options, warnings);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  return p;
}

/// Curvature 1/R [1/mm] of the rail surface at y: the derivative of the slope by central
/// differences (h = 0.01 mm; the spline's slope is smooth there to ~1e-10).
double curvature(const ProfileCurve& c, double y) {
  const double h = 0.01;
  const double s = c.at_y(y).dz_dy;
  const double ds = (c.at_y(y + h).dz_dy - c.at_y(y - h).dz_dy) / (2.0 * h);
  return ds / std::pow(1.0 + s * s, 1.5);
}

/// The lateral position on one side (sign ±1) where the surface lies `depth` mm below the crown
/// top, by bisection between the crown (z < depth) and the end of the flank (z > depth).
double y_at_depth(const ProfileCurve& c, double depth, double sign) {
  double inner = 0.0, outer = sign > 0 ? c.y_max() : c.y_min();
  for (int it = 0; it < 100; ++it) {
    const double mid = 0.5 * (inner + outer);
    (c.at_y(mid).z < depth ? inner : outer) = mid;
  }
  return 0.5 * (inner + outer);
}

TEST(Rail54E1, FileIsAnAdmissibleRailProfile) {
  const model::WheelRailProfile p = read_54e1();
  ASSERT_GE(p.points.y.size(), 2u);
  const double chord = format::profile_chord_length(p.points);
  EXPECT_TRUE(format::is_admissible_profile_length(chord)) << chord;
  // Points at most 0.25 mm apart where the wheel runs (the crown and the R80 shoulders).
  for (std::size_t i = 1; i < p.points.y.size(); ++i) {
    if (std::abs(p.points.y[i]) > 25.0) continue;
    EXPECT_LE(std::hypot(p.points.y[i] - p.points.y[i - 1], p.points.z[i] - p.points.z[i - 1]),
              0.25)
        << "at y = " << p.points.y[i];
  }
}

TEST(Rail54E1, CrownShoulderAndCornerRadii) {
  const ProfileCurve c(read_54e1(), true);
  // Crown top at the origin, R300 there (1 %).
  EXPECT_NEAR(c.at_y(0.0).z, 0.0, 1e-9);
  EXPECT_NEAR(c.at_y(0.0).dz_dy, 0.0, 1e-9);
  EXPECT_NEAR(1.0 / curvature(c, 0.0), 300.0, 3.0);
  EXPECT_NEAR(1.0 / curvature(c, 5.0), 300.0, 3.0);
  // R80 shoulder: between the R300 (|y| ≤ 10.2) and R13 (|y| ≥ 24.8) parts.
  for (double y : {14.0, 17.5, 21.0}) EXPECT_NEAR(1.0 / curvature(c, y), 80.0, 0.8) << y;
  // R13 corner, halfway round (slope about 1.2) and near its end on the flank side.
  for (double y : {30.0, 32.0, 34.0}) EXPECT_NEAR(1.0 / curvature(c, y), 13.0, 0.13) << y;
  // The flank is straight: no curvature once the R13 has ended (|y| = 35 at 14.07 mm depth).
  EXPECT_NEAR(curvature(c, 35.5), 0.0, 1e-4);
}

TEST(Rail54E1, HeadWidthSeventyAndFlankOneInTwenty) {
  const ProfileCurve c(read_54e1(), true);
  // EN drawings give the head width at the R13/flank tangent points, here 14.07 mm below the
  // crown. At the gauge height GAUGHT = 14 mm, still on the R13 arc, the head is narrower by
  // less than 2·0.07/20 = 0.007 mm (the flank's 1:20 over the last 0.07 mm): 0.02 mm allowed.
  const double w14 = y_at_depth(c, 14.0, +1.0) - y_at_depth(c, 14.0, -1.0);
  EXPECT_NEAR(w14, 70.0, 0.02);
  // Below it the flanks are straight: 6 mm further down each has moved 6/20 mm outward.
  const double w16 = y_at_depth(c, 16.0, +1.0) - y_at_depth(c, 16.0, -1.0);
  const double w22 = y_at_depth(c, 22.0, +1.0) - y_at_depth(c, 22.0, -1.0);
  EXPECT_NEAR(w22 - w16, 2.0 * 6.0 / 20.0, 1e-6);
  // ... and extrapolated back to the tangent depth they give the 70 mm.
  EXPECT_NEAR(w16 - 2.0 * (16.0 - 14.07) / 20.0, 70.0, 1e-3);
}

TEST(Rail54E1, TangentContinuousAndSymmetric) {
  const model::WheelRailProfile p = read_54e1();
  // No kink: the polyline turns at most by one arc step of the tightest arc (0.1 mm on R13 =
  // 0.0077 rad) from one point to the next; a kink at a tangent point would show as more.
  const auto& y = p.points.y;
  const auto& z = p.points.z;
  double max_turn = 0.0;
  for (std::size_t i = 1; i + 1 < y.size(); ++i) {
    const double a = std::atan2(z[i] - z[i - 1], y[i] - y[i - 1]);
    const double b = std::atan2(z[i + 1] - z[i], y[i + 1] - y[i]);
    max_turn = std::max(max_turn, std::abs(b - a));
  }
  EXPECT_LT(max_turn, 0.1 / 13.0 * 1.01);
  const ProfileCurve c(p, true);
  EXPECT_EQ(c.section_count(), 1u);  // the kink detection of §13.1 finds none either
  // Symmetric about y = 0: the same surface height and the opposite slope.
  for (double yy : {2.0, 10.228, 17.0, 24.83, 30.0, 34.9, 35.5}) {
    EXPECT_NEAR(c.at_y(yy).z, c.at_y(-yy).z, 1e-9) << yy;
    EXPECT_NEAR(c.at_y(yy).dz_dy, -c.at_y(-yy).dz_dy, 1e-7) << yy;
  }
}

}  // namespace
}  // namespace rollcontact::wheelrail
