// The profile curve: smoothing splines, evaluation at y, kinks and zig-zags (physics.md §13.1).

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "rollcontact/errors.hpp"
#include "wheelrail/profile_curve.hpp"
#include "wheelrail/smoothing_spline.hpp"
#include "wheelrail_problems.hpp"

namespace rollcontact::wheelrail {
namespace {

TEST(SmoothingSpline, InterpolatesTheNodesAndReproducesAStraightLine) {
  const std::vector<double> s{0, 0.5, 1.7, 2.0, 3.1, 4.5};
  std::vector<double> line, wiggle;
  for (double v : s) {
    line.push_back(2.0 - 0.5 * v);
    wiggle.push_back(std::sin(v));
  }
  const SplineNodes a = fit_smoothing_spline(s, line, {}, 0.0);
  for (std::size_t i = 0; i < s.size(); ++i) {
    EXPECT_NEAR(a.value[i], line[i], 1e-14);
    EXPECT_NEAR(a.second[i], 0.0, 1e-12);  // a line has no curvature
  }
  const SplineNodes b = fit_smoothing_spline(s, wiggle, {}, 0.0);
  for (std::size_t i = 0; i < s.size(); ++i) EXPECT_NEAR(b.value[i], wiggle[i], 1e-14);
  EXPECT_EQ(b.second.front(), 0.0);  // natural end conditions
  EXPECT_EQ(b.second.back(), 0.0);
}

TEST(SmoothingSpline, LargeLambdaTendsToTheLeastSquaresLine) {
  // Noise on a line: λ → ∞ leaves the regression line (no curvature allowed).
  std::vector<double> s, f;
  for (int i = 0; i < 40; ++i) {
    s.push_back(0.25 * i);
    f.push_back(1.0 + 0.3 * s.back() + (i % 2 == 0 ? 0.01 : -0.01));
  }
  const SplineNodes n = fit_smoothing_spline(s, f, {}, 1e9);
  for (std::size_t i = 0; i < s.size(); ++i) EXPECT_NEAR(n.value[i], 1.0 + 0.3 * s[i], 2e-3);
  // A smaller λ smooths less: the residual lies between interpolation and the line.
  const SplineNodes m = fit_smoothing_spline(s, f, {}, 0.01);
  double res_m = 0, res_n = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    res_m += std::abs(m.value[i] - f[i]);
    res_n += std::abs(n.value[i] - f[i]);
  }
  EXPECT_GT(res_m, 0.0);
  EXPECT_LT(res_m, res_n);
}

TEST(ProfileCurve, CircularRailHeadIsEvaluatedToSplineAccuracy) {
  const double r = 300.0;
  model::WheelRailProfile prof;
  prof.points = test_support::sampled_profile(
      [r](double y) { return r - std::sqrt(r * r - y * y); }, -30, 30, 0.5, false);
  const ProfileCurve c(prof, true);
  EXPECT_EQ(c.section_count(), 1u);
  // Inside, the cubic interpolates the circle to O(h⁴); within a few nodes of the ends the
  // natural end condition (zero curvature) costs O(h²/r) in z and O(h/r) in slope.
  for (double y : {-12.345, 0.0, 0.1, 7.77, 25.0}) {
    const CurvePoint p = c.at_y(y);
    ASSERT_TRUE(p.found);
    EXPECT_NEAR(p.z, r - std::sqrt(r * r - y * y), 1e-8) << y;
    EXPECT_NEAR(p.dz_dy, y / std::sqrt(r * r - y * y), 1e-6) << y;
  }
  for (double y : {-29.9, 29.5}) {
    const CurvePoint p = c.at_y(y);
    EXPECT_NEAR(p.z, r - std::sqrt(r * r - y * y), 0.5 * 0.5 * 0.5 / r) << y;
    EXPECT_NEAR(p.dz_dy, y / std::sqrt(r * r - y * y), 0.5 / r) << y;
  }
  EXPECT_FALSE(c.at_y(30.5).found);
  // Arc length of a circle: r·(θ1 − θ0).
  EXPECT_NEAR(c.length(), 2 * r * std::asin(30.0 / r), 1e-5);
}

TEST(ProfileCurve, KinkSplitsTheProfileIntoSections) {
  // A V: two straight lines meeting at y = 0 with a 40° change of direction.
  const double slope = std::tan(20.0 * std::numbers::pi / 180.0);
  model::WheelRailProfile prof;
  prof.points = test_support::sampled_profile([slope](double y) { return slope * std::abs(y); },
                                              -10, 10, 0.5, false);
  const ProfileCurve c(prof, true);
  EXPECT_EQ(c.section_count(), 2u);
  // Each section is a straight line up to the kink: no overshoot from a spline across it.
  for (double y : {-2.0, -0.3, 0.3, 2.0}) EXPECT_NEAR(c.at_y(y).z, slope * std::abs(y), 1e-12);
  // Without the kink the interpolating spline would round the corner.
  model::WheelRailProfile smooth = prof;
  smooth.smoothing.kink_high_rad = std::numbers::pi;  // nothing is a kink
  const ProfileCurve d(smooth, true);
  EXPECT_EQ(d.section_count(), 1u);
  EXPECT_GT(std::abs(d.at_y(0.25).z - slope * 0.25), 1e-3);
}

TEST(ProfileCurve, ZigZagIsReplacedByItsMeanPoint) {
  model::WheelRailProfile prof;
  prof.points = test_support::sampled_profile([](double) { return 0.0; }, 0, 10, 1.0, false);
  // Points 5 and 6 swapped in y: the profile runs back and forth.
  std::swap(prof.points.y[5], prof.points.y[6]);
  const ProfileCurve c(prof, true);
  EXPECT_EQ(c.node_y().size(), prof.points.y.size() - 1);
  EXPECT_NEAR(c.at_y(5.5).z, 0.0, 1e-12);
  // MAXOMIT = 0 refuses any removal, naming the file.
  prof.smoothing.max_omitted_fraction = 0.0;
  try {
    ProfileCurve refused(prof, true);
    FAIL() << "expected a GeometryError";
  } catch (const GeometryError& e) {
    EXPECT_NE(std::string(e.what()).find("rail (test)"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("MAXOMIT"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace rollcontact::wheelrail
