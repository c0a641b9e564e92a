// KPEC and the modified ANALYN (physics.md §7.3) on a Hertzian gap: both are built so that a
// quadratic gap h = A1·x² + B1·y² − PEN gives Hertz' ellipse and pressure back; what remains is
// the discretisation (pressure sampled at element centres, edges interpolated between them), which
// must shrink when the grid is refined.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

#include "geometry/hertz.hpp"
#include "simplified/approximate_normal.hpp"

namespace rollcontact::simplified {
namespace {

constexpr double kA1 = 1.0 / (2.0 * 460.0), kB1 = 1.0 / (2.0 * 80.0);  // wheel on rail [1/mm]
constexpr double kPen = 0.05;                                          // [mm]
const CombinedMaterial kSteel{.g = 82000.0, .nu = 0.28, .k = 0.0};

struct Outcome {
  double fn = 0.0, pmax = 0.0, area = 0.0;  // [N], [N/mm²], [mm²]
};

/// The method on a grid of n × n elements (n odd) covering 1.3 × the Hertz ellipse.
template <class Method>
Outcome run(Method method, const HertzReport& hz, int n) {
  Grid g;
  g.mx = g.my = n;
  g.dx = 2.6 * hz.aa / n;
  g.dy = 2.6 * hz.bb / n;
  g.xl = -0.5 * n * g.dx;
  g.yl = -0.5 * n * g.dy;
  std::vector<double> h(g.size());
  for (int iy = 0; iy < n; ++iy)
    for (int ix = 0; ix < n; ++ix) {
      const double x = g.x_centre(ix), y = g.y_centre(iy);
      h[g.index(ix, iy)] = kA1 * x * x + kB1 * y * y - kPen;
    }
  const ApproximateNormal r = method(g, h, kSteel);
  EXPECT_NEAR(r.pen_total, kPen, 1e-12);  // n odd: an element centre at the deepest point
  Outcome o;
  o.fn = std::accumulate(r.pn.begin(), r.pn.end(), 0.0) * g.element_area();
  o.pmax = *std::max_element(r.pn.begin(), r.pn.end());
  o.area = static_cast<double>(
               std::count_if(r.pn.begin(), r.pn.end(), [](double p) { return p > 0.0; })) *
           g.element_area();
  return o;
}

template <class Method>
void expect_hertz(Method method) {
  const HertzReport hz = geometry::hertz_from_curvatures(kA1, kB1, geometry::HertzLoad::Approach,
                                                         kPen, kSteel.g / (1.0 - kSteel.nu));
  const double area = std::acos(-1.0) * hz.aa * hz.bb;
  const Outcome coarse = run(method, hz, 31), fine = run(method, hz, 91);
  // 31 × 31 elements over the ellipse: within 3 % of Hertz; 91 × 91: within 1 %, and closer.
  EXPECT_NEAR(coarse.fn, hz.fn, 0.03 * hz.fn);
  EXPECT_NEAR(fine.fn, hz.fn, 0.01 * hz.fn);
  EXPECT_LT(std::abs(fine.fn - hz.fn), std::abs(coarse.fn - hz.fn) + 1e-3 * hz.fn);
  EXPECT_NEAR(fine.pmax, hz.pmax, 0.01 * hz.pmax);
  EXPECT_NEAR(fine.area, area, 0.02 * area);
}

TEST(ApproximateNormal, KpecGivesHertzForAQuadraticGap) {
  expect_hertz([](const Grid& g, const std::vector<double>& h, const CombinedMaterial& m) {
    return kpec_pressure(g, h, m);
  });
}

TEST(ApproximateNormal, AnalynGivesHertzForAQuadraticGap) {
  expect_hertz(analyn_pressure);
}

TEST(ApproximateNormal, NoInterpenetrationNoPressure) {
  Grid g;
  g.mx = g.my = 5;
  g.dx = g.dy = 0.1;
  const std::vector<double> h(g.size(), 0.01);
  for (int kpec = 0; kpec < 2; ++kpec) {
    const ApproximateNormal r =
        kpec != 0 ? kpec_pressure(g, h, kSteel) : analyn_pressure(g, h, kSteel);
    EXPECT_EQ(r.pen_total, 0.0);
    EXPECT_EQ(std::count(r.pn.begin(), r.pn.end(), 0.0), 25);
  }
}

}  // namespace
}  // namespace rollcontact::simplified
