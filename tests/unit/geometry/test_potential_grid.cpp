// Grids of the potential contact area: IPOTCN 1..4 conversions, Hertzian layouts, validation.

#include <gtest/gtest.h>

#include "geometry/discretisation.hpp"
#include "rollcontact/errors.hpp"

namespace rollcontact::geometry {
namespace {

PotentialContact pot(int ipotcn, int mx, int my, double v0, double v1, double v2, double v3) {
  PotentialContact p;
  p.ipotcn = ipotcn;
  p.mx = mx;
  p.my = my;
  p.values = {v0, v1, v2, v3};
  return p;
}

// Conversions are one or two floating-point operations: 1e-14 absolute on O(1) numbers.
constexpr double tol = 1e-14;

TEST(RectangularGrid, CornerAndSize) {
  const Grid g = rectangular_grid(pot(1, 19, 19, -1.26667, -1.26667, 0.13333, 0.13333));
  EXPECT_EQ(g.mx, 19);
  EXPECT_EQ(g.my, 19);
  EXPECT_NEAR(g.xl, -1.26667, tol);
  EXPECT_NEAR(g.dx, 0.13333, tol);
  // Middle column of cattaneo case 2: x = −1.26667 + 9.5·0.13333 = −0.35e-4 (printed
  // "-0.3500E-04" in cattaneo.ref_out).
  EXPECT_NEAR(g.x_centre(9), -0.35e-4, tol);
}

TEST(RectangularGrid, TwoCorners) {
  const Grid g = rectangular_grid(pot(2, 10, 4, -1.0, -2.0, 3.0, 2.0));
  EXPECT_NEAR(g.xl, -1.0, tol);
  EXPECT_NEAR(g.yl, -2.0, tol);
  EXPECT_NEAR(g.dx, 0.4, tol);
  EXPECT_NEAR(g.dy, 1.0, tol);
  EXPECT_NEAR(g.x_centre(9), 2.8, tol);
}

TEST(RectangularGrid, FirstCentreAndSize) {
  // carter2d.inp: IPOTCN 3, 55 × 1, XC1 = −1.05, YC1 = 0, DX = 0.04, DY = 200.
  const Grid g = rectangular_grid(pot(3, 55, 1, -1.05, 0.0, 0.04, 200.0));
  EXPECT_NEAR(g.xl, -1.07, tol);
  EXPECT_NEAR(g.yl, -100.0, tol);
  EXPECT_NEAR(g.x_centre(0), -1.05, tol);
  EXPECT_NEAR(g.x_centre(54), 1.11, 1e-13);
  EXPECT_NEAR(g.y_centre(0), 0.0, tol);
}

TEST(RectangularGrid, FirstAndLastCentres) {
  const Grid g = rectangular_grid(pot(4, 11, 3, -1.0, -0.5, 1.0, 0.5));
  EXPECT_NEAR(g.dx, 0.2, tol);
  EXPECT_NEAR(g.dy, 0.5, tol);
  EXPECT_NEAR(g.x_centre(0), -1.0, tol);
  EXPECT_NEAR(g.x_centre(10), 1.0, tol);
  EXPECT_NEAR(g.y_centre(2), 0.5, tol);
  EXPECT_THROW(rectangular_grid(pot(4, 11, 1, -1.0, 0.0, 1.0, 0.0)), ProblemError);
}

TEST(RectangularGrid, Validation) {
  EXPECT_THROW(rectangular_grid(pot(1, 0, 5, 0, 0, 1, 1)), ProblemError);
  EXPECT_THROW(rectangular_grid(pot(1, 5, -1, 0, 0, 1, 1)), ProblemError);
  EXPECT_THROW(rectangular_grid(pot(1, 2000, 1001, 0, 0, 1, 1)), ProblemError);  // 2 002 000
  EXPECT_NO_THROW(rectangular_grid(pot(1, 2000, 1000, 0, 0, 1, 1)));             // exactly 2e6
  EXPECT_THROW(rectangular_grid(pot(1, 5, 5, 0, 0, 1e-9, 1)), ProblemError);
  EXPECT_THROW(rectangular_grid(pot(1, 5, 5, 0, 0, 1, -1)), ProblemError);
  EXPECT_THROW(rectangular_grid(pot(2, 5, 5, 1, 0, 0, 1)), ProblemError);  // XH < XL
  EXPECT_THROW(rectangular_grid(pot(7, 5, 5, 0, 0, 1, 1)), ProblemError);
  EXPECT_THROW(rectangular_grid(pot(-3, 5, 5, 1, 1, 1, 0)), ProblemError);  // Hertzian
  try {
    rectangular_grid(pot(1, 5, 5, 0, 0, 0.0, 1));
    FAIL() << "expected ProblemError";
  } catch (const ProblemError& e) {
    EXPECT_NE(std::string(e.what()).find("DX"), std::string::npos) << e.what();
  }
}

HertzReport report(bool two_d, double aa, double bb, double scale) {
  HertzReport h;
  h.present = true;
  h.two_dimensional = two_d;
  h.aa = aa;
  h.bb = bb;
  h.scale = scale;
  return h;
}

TEST(HertzianGrid, ThreeDimensional) {
  // cattaneo: a = b = 1, SCALE 1.26667, 19 × 19 → DX = 2·1.26667/19 = 0.13333.
  const Grid g = hertzian_grid(pot(-3, 19, 19, 1, 1, 1.26667, 0), report(false, 1, 1, 1.26667));
  EXPECT_NEAR(g.xl, -1.26667, tol);
  EXPECT_NEAR(g.yl, -1.26667, tol);
  EXPECT_NEAR(g.dx, 2.0 * 1.26667 / 19, tol);
  EXPECT_NEAR(g.x_centre(9), 0.0, tol);  // odd MX: an element centred on x = 0
}

TEST(HertzianGrid, TwoDimensionalRowRule) {
  // n_int = MY (s ≤ 1) or round(MY/s), made to differ from MY by an even number; the strip
  // [−b, b] is covered by exactly n_int rows and the grid is symmetric about y = 0.
  struct Case {
    int my;
    double s;
    int n_int;
  };
  for (const Case& c :
       {Case{1, 1.0, 1}, Case{1, 3.0, 1}, Case{10, 1.0, 10}, Case{10, 1.25, 8}, Case{10, 1.5, 8},
        Case{9, 1.5, 7}, Case{9, 1.1, 9}, Case{2, 5.0, 2}, Case{20, 0.5, 20}}) {
    const Grid g = hertzian_grid(pot(-5, 4, c.my, 1, 2, c.s, 0), report(true, 1.0, 2.0, c.s));
    EXPECT_NEAR(g.dy, 4.0 / c.n_int, tol) << "MY=" << c.my << " s=" << c.s;
    EXPECT_NEAR(g.yl, -0.5 * c.my * g.dy, tol);
    EXPECT_NEAR(g.xl, -c.s, tol);
    EXPECT_NEAR(g.dx, 2.0 * c.s / 4, tol);
  }
}

TEST(HertzianGrid, RejectsBadScale) {
  EXPECT_THROW(hertzian_grid(pot(-3, 5, 5, 1, 1, 0, 0), report(false, 1, 1, 0.0)), ProblemError);
  EXPECT_THROW(hertzian_grid(pot(-3, 5, 5, 1, 1, 1, 0), HertzReport{}), ProblemError);
}

}  // namespace
}  // namespace rollcontact::geometry
