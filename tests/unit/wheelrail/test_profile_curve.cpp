// The profile curve: smoothing splines, evaluation at y, kinks and zig-zags (physics.md §13.1).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

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

TEST(ThirdOrderSmoothing, QuadraticsPassUnchanged) {
  // ISMOOTH = 2 penalises third derivatives only: any quadratic is its own smoothing, on
  // non-uniform nodes too.
  std::vector<double> s, f;
  for (int i = 0; i < 60; ++i) {
    s.push_back(0.3 * i + 0.1 * std::sin(1.7 * i));
    f.push_back(2.0 - 0.4 * s.back() + 0.05 * s.back() * s.back());
  }
  const std::vector<double> g = wheelrail::smooth_third_order(s, f, {}, 1e3);
  for (std::size_t i = 0; i < f.size(); ++i) EXPECT_NEAR(g[i], f[i], 1e-7) << i;  // rounding
}

TEST(ThirdOrderSmoothing, ASineAtTheFilterWavelengthKeepsHalfItsAmplitude) {
  // Dense uniform nodes with chord-length weights: the filter 1/(1 + λ(2π/L)⁶) with
  // λ = (L_filt/2π)⁶ — 1/2 at L = L_filt, 0.99976 at 4·L_filt, 1/65 at L_filt/2 — read off in
  // the middle, away from the ends.
  const double l_filt = 4.0, ds = 0.02;
  const double lambda = std::pow(l_filt / (2.0 * std::numbers::pi), 6);
  for (const auto& [wavelength, expected] :
       {std::pair{l_filt, 0.5}, std::pair{4.0 * l_filt, 1.0 / (1.0 + std::pow(0.25, 6))},
        std::pair{0.5 * l_filt, 1.0 / 65.0}}) {
    std::vector<double> s, f, w;
    for (int i = 0; i <= 4000; ++i) {
      s.push_back(ds * i);
      f.push_back(std::sin(2.0 * std::numbers::pi * s.back() / wavelength));
      w.push_back(ds);
    }
    const std::vector<double> g = wheelrail::smooth_third_order(s, f, w, lambda);
    double amplitude = 0.0;
    for (std::size_t i = 1500; i <= 2500; ++i) amplitude = std::max(amplitude, std::abs(g[i]));
    EXPECT_NEAR(amplitude, expected, 0.01 * expected + 1e-3) << "L = " << wavelength;
  }
}

TEST(ThirdOrderSmoothing, ProfileCurveWithIsmooth2FiltersNoise) {
  // A circular head with ±5 µm of noise (period 0.3 mm) on points 0.1 mm apart: ISMOOTH = 2, L_filt
  // = 2 mm, brings the curve back to within 1.5 µm of the circle, ISMOOTH = 0 without smoothing
  // keeps the noise.
  const double r = 300.0;
  model::WheelRailProfile p;
  for (int i = -300; i <= 300; ++i) {
    const double y = 0.1 * i;
    p.points.y.push_back(y);
    p.points.z.push_back(r - std::sqrt(r * r - y * y) + 0.005 * (((i % 3) + 3) % 3 - 1));
  }
  p.points.file = "noisy crown (test)";
  p.smoothing.method = 2;
  p.smoothing.smooth = 2.0;
  const wheelrail::ProfileCurve smooth(p, true);
  p.smoothing.smooth = 0.0;
  const wheelrail::ProfileCurve raw(p, true);
  double worst_smooth = 0.0, worst_raw = 0.0;
  for (double y = -20.0; y <= 20.0; y += 0.037) {
    const double exact = r - std::sqrt(r * r - y * y);
    worst_smooth = std::max(worst_smooth, std::abs(smooth.at_y(y).z - exact));
    worst_raw = std::max(worst_raw, std::abs(raw.at_y(y).z - exact));
  }
  EXPECT_LT(worst_smooth, 1.5e-3);
  EXPECT_GT(worst_raw, 4e-3);
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
