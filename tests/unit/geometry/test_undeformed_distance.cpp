// Undeformed distance of IBASE 1/2/3/9 with planforms IPLAN 1/2/3.

#include <gtest/gtest.h>

#include <cmath>

#include "geometry/discretisation.hpp"
#include "rollcontact/errors.hpp"

namespace rollcontact::geometry {
namespace {

Grid grid(int mx, int my, double xl, double yl, double dx, double dy) {
  Grid g;
  g.mx = mx;
  g.my = my;
  g.xl = xl;
  g.yl = yl;
  g.dx = dx;
  g.dy = dy;
  return g;
}

// Formulas are evaluated directly at the centres; 1e-14 absolute covers the rounding of a few
// operations on O(1) values.
constexpr double tol = 1e-14;

TEST(UndeformedDistance, QuadraticAllSixTerms) {
  const Grid g = grid(4, 3, -2.0, -1.5, 1.0, 1.0);
  UndeformedDistance u;
  u.ibase = 1;
  u.coeffs = {0.5, -0.25, 2.0, 0.1, -0.2, 0.03};
  const std::vector<double> h = undeformed_distance(g, u);
  ASSERT_EQ(h.size(), 12u);
  for (int iy = 0; iy < 3; ++iy) {
    for (int ix = 0; ix < 4; ++ix) {
      const double x = g.x_centre(ix), y = g.y_centre(iy);
      EXPECT_NEAR(h[g.index(ix, iy)],
                  0.5 * x * x - 0.25 * x * y + 2.0 * y * y + 0.1 * x - 0.2 * y + 0.03, tol);
    }
  }
}

TEST(UndeformedDistance, TabulatedProfileInterpolatesAndExtrapolates) {
  // Samples at y = −1, 0, 1: p = 1, 0, 2; outside, the end segments are extended.
  const Grid g = grid(1, 6, 0.0, -2.5, 1.0, 1.0);  // x = 0.5, y = −2 … 3
  UndeformedDistance u;
  u.ibase = 2;
  u.coeffs = {1.0, 0.0, 2.0};
  u.y1 = -1.0;
  u.dy1 = 1.0;
  u.xm = 0.5;
  u.rm = 100.0;
  const std::vector<double> h = undeformed_distance(g, u);
  const double expected[] = {2.0, 1.0, 0.0, 2.0, 4.0, 6.0};
  for (int iy = 0; iy < 6; ++iy) EXPECT_NEAR(h[static_cast<std::size_t>(iy)], expected[iy], tol);

  // Off-centre x adds (x − xm)²/(2 rm); mid-segment y interpolates.
  const Grid g2 = grid(1, 1, 1.5, -0.75, 1.0, 0.5);  // (x, y) = (2, −0.5)
  EXPECT_NEAR(undeformed_distance(g2, u)[0], 0.5 + 1.5 * 1.5 / 200.0, tol);
}

TEST(UndeformedDistance, VeldepFricProfileIsCircularInX) {
  // veldep_fric.inp: IBASE 2 with NN = 2, XM = 0, RM = 460, Y1 = −10, DY1 = 20, B = (0, 0):
  // h = x²/920 on the 92 × 1 grid with XC1 = −4.6, DX = 0.1.
  PotentialContact p;
  p.ipotcn = 3;
  p.mx = 92;
  p.my = 1;
  p.values = {-4.6, 0.0, 0.1, 200.0};
  const Grid g = rectangular_grid(p);
  UndeformedDistance u;
  u.ibase = 2;
  u.coeffs = {0.0, 0.0};
  u.xm = 0.0;
  u.rm = 460.0;
  u.y1 = -10.0;
  u.dy1 = 20.0;
  const std::vector<double> h = undeformed_distance(g, u);
  EXPECT_NEAR(h[0], 4.6 * 4.6 / 920.0, tol);
  EXPECT_NEAR(h[46], 0.0, tol);  // x = 0
  EXPECT_NEAR(h[91], 4.5 * 4.5 / 920.0, tol);
}

TEST(UndeformedDistance, Sines) {
  const Grid g = grid(3, 2, -1.0, -1.0, 0.7, 1.0);
  UndeformedDistance u;
  u.ibase = 3;
  u.coeffs = {0.01, 2.0, 0.1, 0.02, 5.0, -0.3, 100.0, 50.0};
  const std::vector<double> h = undeformed_distance(g, u);
  for (int iy = 0; iy < 2; ++iy) {
    for (int ix = 0; ix < 3; ++ix) {
      const double x = g.x_centre(ix), y = g.y_centre(iy);
      const double e = 0.01 * std::sin(2.0 * (x - 0.1)) - 0.02 * std::sin(5.0 * (x + 0.3)) +
                       x * x / 100.0 + y * y / 50.0;
      EXPECT_NEAR(h[g.index(ix, iy)], e, tol);
    }
  }
  u.coeffs[6] = 0.0;
  EXPECT_THROW(undeformed_distance(g, u), ProblemError);
}

TEST(UndeformedDistance, PerElementValues) {
  const Grid g = grid(3, 2, 0.0, 0.0, 1.0, 1.0);
  UndeformedDistance u;
  u.ibase = 9;
  u.values = {1, 2, 3, 4, 5, 6};
  EXPECT_EQ(undeformed_distance(g, u), u.values);
  u.values.pop_back();
  EXPECT_THROW(undeformed_distance(g, u), ProblemError);
}

TEST(UndeformedDistance, QuadraticPlanformExcludesNonNegativeForm) {
  // Planform x² + y² − 1 < 0 (open unit disc); centres at 0, ±0.5, ±1 in x and y.
  const Grid g = grid(5, 5, -1.25, -1.25, 0.5, 0.5);
  UndeformedDistance u;
  u.ibase = 1;
  u.coeffs = {0, 0, 0, 0, 0, 0.5};
  u.iplan = 2;
  u.planform = {1, 0, 1, 0, 0, -1};
  const std::vector<double> h = undeformed_distance(g, u);
  int kept = 0;
  for (int iy = 0; iy < 5; ++iy) {
    for (int ix = 0; ix < 5; ++ix) {
      const double x = g.x_centre(ix), y = g.y_centre(iy);
      const bool inside = x * x + y * y - 1.0 < 0.0;
      EXPECT_EQ(h[g.index(ix, iy)], inside ? 0.5 : excluded_distance) << ix << "," << iy;
      kept += inside ? 1 : 0;
    }
  }
  EXPECT_EQ(kept, 9);  // the 3 × 3 block |x|, |y| ≤ 0.5; (±1, 0) lie on the border: excluded
  // A form ≥ 0 everywhere excludes every element.
  u.planform = {0, 0, 0, 0, 0, 0.0};
  EXPECT_THROW(undeformed_distance(g, u), ProblemError);
}

TEST(UndeformedDistance, TwoRectanglesBordersInclusive) {
  // Centres at x = 0, 1, 2, 3 and y = 0, 1. Rectangle 1 = [0, 1] × [0, 0] (touches centres on
  // its borders), rectangle 2 = [3, 3] × [1, 1].
  const Grid g = grid(4, 2, -0.5, -0.5, 1.0, 1.0);
  UndeformedDistance u;
  u.ibase = 1;
  u.coeffs = {0, 0, 0, 0, 0, 0.25};
  u.iplan = 3;
  u.planform = {0.0, 1.0, 0.0, 0.0, 3.0, 3.0, 1.0, 1.0};
  const std::vector<double> h = undeformed_distance(g, u);
  const bool keep[8] = {true, true, false, false, false, false, false, true};
  for (std::size_t i = 0; i < 8; ++i) EXPECT_EQ(h[i], keep[i] ? 0.25 : excluded_distance) << i;
  u.planform = {1.0, 0.0, 0.0, 0.0, 3.0, 3.0, 1.0, 1.0};  // XL1 > XH1
  EXPECT_THROW(undeformed_distance(g, u), ProblemError);
}

TEST(UndeformedDistance, PatchesWithFactors) {
  // IPLAN=4: three rectangles over x = 0..3, y = 0 and 1; the element (2, 1) lies in none.
  const Grid g = grid(4, 2, -0.5, -0.5, 1.0, 1.0);
  UndeformedDistance u;
  u.ibase = 1;
  u.coeffs = {0, 0, 0, 0, 0, 0.25};
  u.iplan = 4;
  u.npatch = 3;
  u.planform = {0, 1, 0, 1, 2, 3, 0, 0, 3, 3, 1, 1};
  u.patch_factors = {0.5, 0.0, 1.0};  // f12 f13 f23
  const std::vector<double> h = undeformed_distance(g, u);
  for (std::size_t i = 0; i < 8; ++i) EXPECT_EQ(h[i], i == 6 ? excluded_distance : 0.25) << i;
  const PlanformParts parts = planform_parts(g, u);
  ASSERT_EQ(parts.n_parts, 3);
  EXPECT_EQ(parts.part, (std::vector<std::uint8_t>{0, 0, 1, 1, 0, 0, 0, 2}));
  EXPECT_EQ(parts.factor, (std::vector<double>{1, 0.5, 0, 0.5, 1, 1, 0, 1, 1}));
  // All factors 1: full interaction, no parts.
  u.patch_factors = {1, 1, 1};
  EXPECT_EQ(planform_parts(g, u).n_parts, 1);
  // Factors outside [0, 1] would make the operator indefinite; too few limits or factors.
  u.patch_factors = {1.5, 1, 1};
  EXPECT_THROW(undeformed_distance(g, u), ProblemError);
  u.patch_factors = {1, 1};
  EXPECT_THROW(undeformed_distance(g, u), ProblemError);
  u.patch_factors = {1, 1, 1};
  u.planform.pop_back();
  EXPECT_THROW(undeformed_distance(g, u), ProblemError);
}

TEST(UndeformedDistance, RejectsIncompleteData) {
  const Grid g = grid(2, 2, 0.0, 0.0, 1.0, 1.0);
  UndeformedDistance u;
  u.ibase = 1;
  u.coeffs = {1, 0, 1};
  EXPECT_THROW(undeformed_distance(g, u), ProblemError);
  u.ibase = 2;
  u.coeffs = {1.0};
  u.dy1 = 1.0;
  u.rm = 1.0;
  EXPECT_THROW(undeformed_distance(g, u), ProblemError);  // NN < 2
  u.coeffs = {1.0, 2.0};
  u.dy1 = 0.0;
  EXPECT_THROW(undeformed_distance(g, u), ProblemError);  // DY1 ≤ 0
  u.dy1 = 1.0;
  u.rm = 0.0;
  EXPECT_THROW(undeformed_distance(g, u), ProblemError);  // RM = 0
  u.ibase = 5;
  EXPECT_THROW(undeformed_distance(g, u), ProblemError);
  u.ibase = 1;
  u.coeffs = {1, 0, 1, 0, 0, 0};
  u.iplan = 2;
  u.planform = {1, 2};
  EXPECT_THROW(undeformed_distance(g, u), ProblemError);
  u.iplan = 4;  // NPATCH missing
  EXPECT_THROW(undeformed_distance(g, u), ProblemError);
  u.iplan = 0;
  EXPECT_THROW(undeformed_distance(g, u), ProblemError);
}

}  // namespace
}  // namespace rollcontact::geometry
