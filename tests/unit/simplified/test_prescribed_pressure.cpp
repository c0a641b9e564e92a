// Prescribed elliptic and parabolic pressures (B = 2, 3), 3-D and 2-D, and SDEC (B = 4).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

#include "rollcontact/errors.hpp"
#include "simplified/prescribed_pressure.hpp"

namespace rollcontact::simplified {
namespace {

constexpr double pi = std::numbers::pi;

HertzReport ellipse_report(double a, double b, bool two_d = false) {
  HertzReport h;
  h.present = true;
  h.two_dimensional = two_d;
  h.aa = a;
  h.bb = b;
  return h;
}

Grid grid_over(double a, double b, int mx, int my, double scale) {
  Grid g;
  g.mx = mx;
  g.my = my;
  g.dx = 2.0 * scale * a / mx;
  g.dy = 2.0 * scale * b / my;
  g.xl = -scale * a;
  g.yl = -scale * b;
  return g;
}

double total(const Grid& g, const std::vector<double>& p) {
  return std::accumulate(p.begin(), p.end(), 0.0) * g.element_area();
}

TEST(PrescribedPressure, Elliptic3D) {
  const double a = 8.0, b = 4.0, fn = 82000.0;
  const Grid g = grid_over(a, b, 101, 101, 1.1);
  const auto p = prescribed_pressure(g, ellipse_report(a, b), PressureShape::Elliptic, fn);
  const double p0 = 1.5 * fn / (pi * a * b);
  // Odd grid: the centre element sits at (0, 0).
  EXPECT_NEAR(*std::max_element(p.begin(), p.end()), p0, 1e-12 * p0);
  EXPECT_NEAR(total(g, p), fn, 2e-3 * fn);
  for (int iy = 0; iy < g.my; ++iy)
    for (int ix = 0; ix < g.mx; ++ix) {
      const double x = g.x_centre(ix) / a, y = g.y_centre(iy) / b;
      const double v = p[g.index(ix, iy)];
      const double t = 1.0 - x * x - y * y;
      EXPECT_NEAR(v, t > 0.0 ? p0 * std::sqrt(t) : 0.0, 1e-12 * p0);
    }
}

TEST(PrescribedPressure, Parabolic3DCarriesTheSameForceWithAHigherPeak) {
  const double a = 8.0, b = 4.0, fn = 82000.0;
  const Grid g = grid_over(a, b, 101, 101, 1.1);
  const auto p = prescribed_pressure(g, ellipse_report(a, b), PressureShape::Parabolic, fn);
  const double p0 = 2.0 * fn / (pi * a * b);  // 4/3 of the elliptic peak
  EXPECT_NEAR(*std::max_element(p.begin(), p.end()), p0, 1e-12 * p0);
  EXPECT_NEAR(total(g, p), fn, 2e-3 * fn);
}

TEST(PrescribedPressure, TwoDimensionalIsUniformAcrossTheStrip) {
  const double a = 1.0, b = 100.0, fn = 3.578e4;
  Grid g = grid_over(a, b, 99, 1, 1.2);
  g.dy = 2.0 * b;
  g.yl = -b;
  for (PressureShape shape : {PressureShape::Elliptic, PressureShape::Parabolic}) {
    const auto p = prescribed_pressure(g, ellipse_report(a, b, true), shape, fn);
    const double length = 2.0 * b;
    const double p0 = shape == PressureShape::Elliptic ? 2.0 * fn / (pi * a * length)
                                                       : 3.0 * fn / (4.0 * a * length);
    EXPECT_NEAR(*std::max_element(p.begin(), p.end()), p0, 1e-12 * p0);
    EXPECT_NEAR(total(g, p), fn, 3e-3 * fn);
  }
  // Rows outside |y| ≤ b carry nothing.
  Grid wide = grid_over(a, b, 11, 3, 1.2);
  wide.dy = 2.0 * b;
  wide.yl = -3.0 * b;
  const auto p = prescribed_pressure(wide, ellipse_report(a, b, true), PressureShape::Elliptic, fn);
  for (int ix = 0; ix < wide.mx; ++ix) {
    EXPECT_EQ(p[wide.index(ix, 0)], 0.0);
    EXPECT_EQ(p[wide.index(ix, 2)], 0.0);
  }
}

TEST(SdecPressure, EqualHalvesAreTheEllipticHertzPressure) {
  const double a = 8.0, b = 4.0, fn = 82000.0;
  const Grid g = grid_over(a, b, 41, 41, 1.1);
  const auto sdec = sdec_pressure(g, a, b, b, fn);
  const auto hertz = prescribed_pressure(g, ellipse_report(a, b), PressureShape::Elliptic, fn);
  const double p0 = 1.5 * fn / (pi * a * b);
  for (std::size_t i = 0; i < sdec.size(); ++i) EXPECT_NEAR(sdec[i], hertz[i], 1e-12 * p0) << i;
}

TEST(SdecPressure, TwoHalfEllipsesCarryTheForce) {
  // b_neg = 2, b_pos = 6: b = 4, the widest row at y0 = -2, the patch spans |y| <= 4.
  const double a = 8.0, b_neg = 2.0, b_pos = 6.0, fn = 82000.0;
  const Grid g = grid_over(a, 4.0, 161, 161, 1.05);
  const auto p = sdec_pressure(g, a, b_neg, b_pos, fn);
  EXPECT_NEAR(total(g, p), fn, 2e-3 * fn);
  const double p0 = 1.5 * fn / (pi * a * 4.0);
  EXPECT_NEAR(*std::max_element(p.begin(), p.end()), p0, 2e-3 * p0);  // at (0, y0)
  double below = 0.0, above = 0.0, y_extent_low = 0.0, y_extent_high = 0.0;
  for (int iy = 0; iy < g.my; ++iy)
    for (int ix = 0; ix < g.mx; ++ix) {
      const double v = p[g.index(ix, iy)], y = g.y_centre(iy);
      if (v <= 0.0) continue;
      (y > -2.0 ? above : below) += v;
      y_extent_low = std::min(y_extent_low, y);
      y_extent_high = std::max(y_extent_high, y);
    }
  // Each half carries FN·b_±/(b_neg + b_pos): 1/4 below y0, 3/4 above.
  EXPECT_NEAR(below / (below + above), 0.25, 3e-3);
  EXPECT_NEAR(y_extent_low, -4.0, g.dy);
  EXPECT_NEAR(y_extent_high, 4.0, g.dy);
  EXPECT_THROW(sdec_pressure(g, a, 0.0, b_pos, fn), ProblemError);
  EXPECT_THROW(sdec_pressure(g, a, b_neg, b_pos, -1.0), ProblemError);
}

TEST(PrescribedPressure, NeedsHertzSemiAxesAndAForce) {
  const Grid g = grid_over(1.0, 1.0, 5, 5, 1.0);
  EXPECT_THROW(prescribed_pressure(g, HertzReport{}, PressureShape::Elliptic, 1.0), ProblemError);
  EXPECT_THROW(prescribed_pressure(g, ellipse_report(1.0, 1.0), PressureShape::Elliptic, 0.0),
               ProblemError);
}

}  // namespace
}  // namespace rollcontact::simplified
