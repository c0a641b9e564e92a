// build_discretisation on the reference examples: grids and undeformed distances compared with
// what CONTACT printed (POTENTIAL CONTACT / DISCRETISATION lines, element tables).

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "geometry/discretisation.hpp"
#include "printed.hpp"
#include "rollcontact/errors.hpp"

namespace rollcontact::geometry {
namespace {

CombinedMaterial material(double g, double nu) {
  return CombinedMaterial{g, nu, 0.0};
}

model::PatchProblem hertzian(int ipotcn, int mx, int my, std::array<double, 4> values, double fn) {
  model::PatchProblem p;
  p.normal.kind = model::NormalLoadKind::Force;
  p.normal.force_N = fn;
  p.potential.ipotcn = ipotcn;
  p.potential.mx = mx;
  p.potential.my = my;
  p.potential.values = values;
  return p;
}

model::PatchProblem quadratic(int ipotcn, int mx, int my, std::array<double, 4> values, double b1,
                              double b3) {
  model::PatchProblem p;
  p.potential.ipotcn = ipotcn;
  p.potential.mx = mx;
  p.potential.my = my;
  p.potential.values = values;
  p.gap.ibase = 1;
  p.gap.iplan = 1;
  p.gap.coeffs = {b1, 0.0, b3, 0.0, 0.0, 0.0};
  return p;
}

TEST(Discretisation, CattaneoHertzianCase) {
  // cattaneo.ref_out case 1: POTENTIAL CONTACT, SCALE: -1.267 -1.267 1.267;
  // DISCRETISATION MX,MY, DX,DY: 19 19 0.1333 0.1333.
  const Discretisation d = build_discretisation(
      hertzian(-3, 19, 19, {1.0, 1.0, 1.26667, 0.0}, 9.1954), material(200.0, 0.42));
  EXPECT_TRUE(d.hertz.present);
  EXPECT_EQ(d.hertz.scale, 1.26667);
  EXPECT_PRINTED(d.grid.xl, "-1.267");
  EXPECT_PRINTED(d.grid.yl, "-1.267");
  EXPECT_EQ(d.grid.mx, 19);
  EXPECT_EQ(d.grid.my, 19);
  EXPECT_PRINTED(d.grid.dx, "0.1333");
  EXPECT_PRINTED(d.grid.dy, "0.1333");
  // h = A1 x² + B1 y² at centres; centre element (9, 9) sits at the origin.
  ASSERT_EQ(d.h.size(), 361u);
  EXPECT_NEAR(d.h[d.grid.index(9, 9)], 0.0, 1e-18);
  const double x = d.grid.x_centre(2), y = d.grid.y_centre(15);
  EXPECT_NEAR(d.h[d.grid.index(2, 15)], d.hertz.a1 * x * x + d.hertz.b1 * y * y, 1e-16);
}

TEST(Discretisation, CattaneoQuadraticCase) {
  // cattaneo.inp case 2: IPOTCN 1 with the same grid, IBASE 1 B1 = B3 = 0.01. The element table
  // prints, in row 3 (Y = -0.9333), X = -0.2667, -0.1334, -0.3500E-04 with H-PEN
  // -0.106E-01, -0.111E-01, -0.113E-01 at APPROACH 1.998E-02. H-PEN combines our h with the
  // printed approach, so its tolerance adds the approach's half unit (5e-6).
  const Discretisation d =
      build_discretisation(quadratic(1, 19, 19, {-1.26667, -1.26667, 0.13333, 0.13333}, 0.01, 0.01),
                           material(200.0, 0.42));
  EXPECT_FALSE(d.hertz.present);
  EXPECT_PRINTED(d.grid.y_centre(2), "-0.9333");
  EXPECT_PRINTED(d.grid.x_centre(7), "-0.2667");
  EXPECT_PRINTED(d.grid.x_centre(8), "-0.1334");
  EXPECT_PRINTED(d.grid.x_centre(9), "-0.3500E-04");
  const double pen = 1.998e-2;
  EXPECT_NEAR(d.h[d.grid.index(7, 2)] - pen, -0.106e-1, 5e-5 + 5e-6);
  EXPECT_NEAR(d.h[d.grid.index(8, 2)] - pen, -0.111e-1, 5e-5 + 5e-6);
  EXPECT_NEAR(d.h[d.grid.index(9, 2)] - pen, -0.113e-1, 5e-5 + 5e-6);
}

TEST(Discretisation, FastsimHertzianGrids) {
  // fastsim.ref_out: POTENTIAL CONTACT, SCALE: -8.800 -4.400 1.100; 44 44 0.4000 0.2000, and
  // 220 220 0.8000E-01 0.4000E-01 for the fine cases.
  const CombinedMaterial m = material(82000.0, 0.28);
  const Discretisation d = build_discretisation(hertzian(-3, 44, 44, {8, 4, 1.1, 0}, 82000.0), m);
  EXPECT_PRINTED(d.grid.xl, "-8.800");
  EXPECT_PRINTED(d.grid.yl, "-4.400");
  EXPECT_PRINTED(d.hertz.scale, "1.100");
  EXPECT_PRINTED(d.grid.dx, "0.4000");
  EXPECT_PRINTED(d.grid.dy, "0.2000");
  EXPECT_PRINTED(d.hertz.a1, "0.8464E-03");
  EXPECT_PRINTED(d.hertz.b1, "0.2406E-02");
  const Discretisation f = build_discretisation(hertzian(-3, 220, 220, {8, 4, 1.1, 0}, 82000.0), m);
  EXPECT_PRINTED(f.grid.dx, "0.8000E-01");
  EXPECT_PRINTED(f.grid.dy, "0.4000E-01");
}

TEST(Discretisation, TractcurvHertzianGrid) {
  // tractcurv.ref_out: -6.934 -13.87 1.100; 48 44 0.2889 0.6304 (IPOTCN −2, A1 = 0.0008,
  // AOB = 0.5, FN = 106700).
  const Discretisation d = build_discretisation(
      hertzian(-2, 48, 44, {0.0008, 0.5, 1.1, 0}, 106700.0), material(82000.0, 0.28));
  EXPECT_PRINTED(d.grid.xl, "-6.934");
  EXPECT_PRINTED(d.grid.yl, "-13.87");
  EXPECT_PRINTED(d.grid.dx, "0.2889");
  EXPECT_PRINTED(d.grid.dy, "0.6304");
  EXPECT_PRINTED(d.hertz.b1, "0.2814E-03");
}

TEST(Discretisation, Plastic3blSingleElement) {
  // plastic_3bl.ref_out: -0.5000 -0.5000 1.000; 1 1 1.000 1.000.
  const Discretisation d =
      build_discretisation(hertzian(-3, 1, 1, {0.5, 0.5, 1.0, 0}, 900.0), material(82000.0, 0.28));
  EXPECT_PRINTED(d.grid.xl, "-0.5000");
  EXPECT_PRINTED(d.grid.yl, "-0.5000");
  EXPECT_PRINTED(d.grid.dx, "1.000");
  EXPECT_PRINTED(d.grid.dy, "1.000");
  EXPECT_NEAR(d.h[0], 0.0, 1e-18);
}

TEST(Discretisation, Carter2dLineContact) {
  // carter2d.inp: IPOTCN 3, 55 × 1, XC1 = −1.05, DX = 0.04, DY = 200, h = 0.001 x². Element
  // table: X = -0.9700 with H-PEN -0.555E-02 at APPROACH 6.492E-03 (tolerance 5e-6 + 5e-7).
  const Discretisation d = build_discretisation(
      quadratic(3, 55, 1, {-1.05, 0.0, 0.04, 200.0}, 0.001, 0.0), material(82000.0, 0.28));
  EXPECT_PRINTED(d.grid.x_centre(2), "-0.9700");
  EXPECT_PRINTED(d.grid.y_centre(0), "0.000");
  EXPECT_NEAR(d.h[2] - 6.492e-3, -0.555e-2, 5e-6 + 5e-7);
}

TEST(Discretisation, SubsurfSingleElement) {
  // subsurf.inp case 1: IPOTCN 1, 1 × 1, XL −0.4999, YL −0.4998, DX = DY = 1, B1 = B3 = 2.16.
  // Printed: Y = 0.2000E-03, X = 0.1000E-03, H-PEN -0.8080 at APPROACH 0.807984.
  const Discretisation d = build_discretisation(
      quadratic(1, 1, 1, {-0.4999, -0.4998, 1.0, 1.0}, 2.16, 2.16), material(1.0, 0.28));
  EXPECT_PRINTED(d.grid.x_centre(0), "0.1000E-03");
  EXPECT_PRINTED(d.grid.y_centre(0), "0.2000E-03");
  EXPECT_PRINTED(d.h[0] - 0.807984, "-0.8080");
}

TEST(Discretisation, ConformalPerElementDistanceCount) {
  // conformal.inp case 2: IBASE 9 on the 51 × 39 grid; the file lists one h per element, and
  // the count must equal MX·MY = 1989 (read here directly from the example).
  std::ifstream in(std::string(ROLLCONTACT_EXAMPLES_DIR) + "/conformal.inp");
  if (!in) GTEST_SKIP() << "conformal.inp not available";
  std::string line;
  int lineno = 0;
  std::vector<double> values;
  bool reading = false;
  while (std::getline(in, line)) {
    ++lineno;
    if (lineno == 48) {  // "    9    1     IBASE, IPLAN"
      ASSERT_NE(line.find("IBASE"), std::string::npos) << "conformal.inp changed";
      reading = true;
      continue;
    }
    if (!reading || line.empty() || line[0] == '%') continue;
    if (line.find("MODULE") != std::string::npos) break;
    std::istringstream ss(line);
    double v = 0.0;
    while (ss >> v) values.push_back(v);
  }
  model::PatchProblem p = quadratic(1, 51, 39, {-10.2, -7.8, 0.4, 0.4}, 0.0, 0.0);
  p.gap.ibase = 9;
  p.gap.values = values;
  const Discretisation d = build_discretisation(p, material(82000.0, 0.28));
  EXPECT_EQ(d.h, values);
  EXPECT_NEAR(d.h[0], 0.06625925, 1e-15);  // first value in the file
}

TEST(Discretisation, TwoDimensionalHertz) {
  // IPOTCN −4 (A1, half width b) and −5 (half length a, b): same contact both ways; grid rows
  // follow the n_int rule, h = A1 x² (B1 = 0).
  const CombinedMaterial m = material(82000.0, 0.28);
  const Discretisation d4 =
      build_discretisation(hertzian(-4, 40, 10, {0.005, 5.0, 1.25, 0}, 5e4), m);
  EXPECT_TRUE(d4.hertz.two_dimensional);
  const Discretisation d5 =
      build_discretisation(hertzian(-5, 40, 10, {d4.hertz.aa, 5.0, 1.25, 0}, 5e4), m);
  EXPECT_NEAR(d5.hertz.a1 / 0.005, 1.0, 1e-13);
  EXPECT_NEAR(d4.grid.dx, 2.0 * 1.25 * d4.hertz.aa / 40, 1e-15);
  EXPECT_NEAR(d4.grid.dy, 10.0 / 8, 1e-15);  // n_int = round(10/1.25) = 8
  EXPECT_NEAR(d4.grid.yl, -5.0 * 1.25, 1e-14);
  const double x = d4.grid.x_centre(3);
  EXPECT_NEAR(d4.h[d4.grid.index(3, 7)], 0.005 * x * x, 1e-16);
  // 2-D Hertz defines no approach: N = 0 is refused.
  model::PatchProblem p0 = hertzian(-4, 40, 10, {0.005, 5.0, 1.25, 0}, 5e4);
  p0.normal.kind = model::NormalLoadKind::Approach;
  p0.normal.approach_mm = 0.01;
  EXPECT_THROW(build_discretisation(p0, m), ProblemError);
}

TEST(Discretisation, HertzWithPrescribedApproach) {
  // N = 0: PEN from the kinematics; sphere R = 50 → a = √(PEN·R).
  model::PatchProblem p = hertzian(-1, 21, 21, {0.01, 0.01, 1.2, 0}, 0.0);
  p.normal.kind = model::NormalLoadKind::Approach;
  p.normal.approach_mm = 0.02;
  const Discretisation d = build_discretisation(p, material(200.0, 0.42));
  EXPECT_NEAR(d.hertz.aa, 1.0, 1e-13);
  EXPECT_NEAR(d.grid.dx, 2.4 / 21, 1e-14);
}

TEST(Discretisation, SdecUsesMeanHalfWidth) {
  // IPOTCN −6: AA BNEG BPOS SCALE; the grid uses b = (BNEG + BPOS)/2.
  const Discretisation d = build_discretisation(hertzian(-6, 20, 30, {6.0, 2.0, 4.0, 1.1}, 5e4),
                                                material(82000.0, 0.28));
  EXPECT_NEAR(d.hertz.bb, 3.0, 1e-15);
  EXPECT_NEAR(d.hertz.scale, 1.1, 0.0);
  EXPECT_NEAR(d.grid.yl, -3.3, 1e-14);
  EXPECT_NEAR(d.grid.dy, 6.6 / 30, 1e-15);
  EXPECT_NEAR(d.grid.xl, -6.6, 1e-14);
}

TEST(Discretisation, GeometryErrorsSayWhatIsWrong) {
  // Where the case came from is added by the front end (batch::solve_case, tested there).
  model::PatchProblem p = quadratic(1, 3, 3, {0, 0, 1, 1}, 1, 1);
  p.gap.iplan = 2;
  p.gap.planform = {0, 0, 0, 0, 0, 1.0};  // form ≥ 0 everywhere
  try {
    build_discretisation(p, material(1.0, 0.3));
    FAIL() << "expected GeometryError";
  } catch (const GeometryError& e) {
    const std::string what = e.what();
    EXPECT_EQ(e.code(), ErrorCode::Discretisation);
    EXPECT_NE(what.find("excludes every element"), std::string::npos) << what;
  }
  // Hertzian options need a positive load and modulus.
  EXPECT_THROW(build_discretisation(hertzian(-3, 5, 5, {1, 1, 1, 0}, 0.0), material(1.0, 0.3)),
               ProblemError);
  EXPECT_THROW(build_discretisation(hertzian(-3, 5, 5, {1, 1, 1, 0}, 1.0), material(0.0, 0.3)),
               ProblemError);
  EXPECT_THROW(build_discretisation(hertzian(-3, 5, 5, {1, 1, 0.0, 0}, 1.0), material(1.0, 0.3)),
               ProblemError);
  EXPECT_THROW(build_discretisation(hertzian(-3, 0, 5, {1, 1, 1, 0}, 1.0), material(1.0, 0.3)),
               ProblemError);
}

}  // namespace
}  // namespace rollcontact::geometry
