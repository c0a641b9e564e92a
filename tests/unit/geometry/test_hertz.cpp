// Analytic Hertz solutions: classical closed forms, round trips, and the Hertz blocks printed in
// CONTACT's reference outputs (values compared to half a unit of the last printed digit).

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "geometry/hertz.hpp"
#include "printed.hpp"
#include "rollcontact/errors.hpp"

namespace rollcontact::geometry {
namespace {

constexpr double pi = std::numbers::pi;

double estar_of(double g, double nu) {
  return g / (1.0 - nu);
}

// ---------------------------------------------------------------------------------------------
// Reference blocks "3D HERTZIAN GEOMETRY WITH PRESCRIBED NORMAL FORCE"

TEST(HertzReference, CattaneoSemiaxes) {
  // cattaneo.inp case 1: IPOTCN −3, AA = BB = 1, FN = 9.1954, G = 200, ν = 0.42.
  const HertzReport h =
      hertz_from_semiaxes(1.0, 1.0, HertzLoad::Force, 9.1954, estar_of(200, 0.42));
  EXPECT_TRUE(h.present);
  EXPECT_FALSE(h.two_dimensional);
  EXPECT_PRINTED(h.aa, "1.000");
  EXPECT_PRINTED(h.bb, "1.000");
  EXPECT_PRINTED(h.a1, "0.1000E-01");
  EXPECT_PRINTED(h.b1, "0.1000E-01");
  EXPECT_PRINTED(h.rho, "100.0");
  EXPECT_PRINTED(h.cp, "1.000");
  // The printed APPROACH 1.998E-02 and PMAX 4.393 are those of the discrete (19×19) solution.
  // Hertz itself gives PEN = a²/R = 1/50 and p0 = 3FN/(2π); the discrete values lie within
  // 0.1 % of them, which is the discretisation error, not a Hertz error.
  EXPECT_NEAR(h.pen, 0.02, 1e-6);
  EXPECT_NEAR(h.pmax, 3.0 * 9.1954 / (2.0 * pi), 1e-12);
  EXPECT_NEAR(h.pen / 1.998e-2, 1.0, 1.5e-3);
  EXPECT_NEAR(h.pmax / 4.393, 1.0, 1.5e-3);
}

TEST(HertzReference, FastsimSemiaxes) {
  // fastsim.inp: IPOTCN −3, AA = 8, BB = 4, FN = 82000, G = 82000, ν = 0.28.
  const HertzReport h =
      hertz_from_semiaxes(8.0, 4.0, HertzLoad::Force, 82000.0, estar_of(82000, 0.28));
  EXPECT_PRINTED(h.a1, "0.8464E-03");
  EXPECT_PRINTED(h.b1, "0.2406E-02");
  EXPECT_PRINTED(h.rho, "614.9");
  EXPECT_PRINTED(h.cp, "5.657");
  // Cases with prescribed Hertz pressure (B = 2, 3) print the Hertz approach (cases 2-5:
  // 9.267E-02; the full solution of case 1 gives 9.266E-02). With B = 2 (cases 3, 4) PMAX is the
  // largest element value of the elliptic Hertz pressure: on the 44×44 grid (DX 0.4, DY 0.2)
  // the centre-most element is at (0.2, 0.1), so 1223. and not p0 = 3FN/(2πab) = 1223.50.
  EXPECT_PRINTED(h.pen, "9.267E-02");
  EXPECT_NEAR(h.pmax, 3.0 * 82000.0 / (2.0 * pi * 32.0), 1e-9);
  EXPECT_PRINTED(hertz_pressure(h, 0.2, 0.1), "1223.");
}

TEST(HertzReference, Plastic3blSemiaxes) {
  // plastic_3bl.inp: IPOTCN −3, AA = BB = 0.5, FN = 900, G = 82000, ν = 0.28.
  const HertzReport h =
      hertz_from_semiaxes(0.5, 0.5, HertzLoad::Force, 900.0, estar_of(82000, 0.28));
  EXPECT_PRINTED(h.a1, "0.2371E-01");
  EXPECT_PRINTED(h.b1, "0.2371E-01");
  EXPECT_PRINTED(h.rho, "42.18");
  EXPECT_PRINTED(h.cp, "0.5000");
}

TEST(HertzReference, TractcurvCurvatureAndRatio) {
  // tractcurv.inp: IPOTCN −2, A1 = 0.0008, AOB = 0.5, FN = 106700, G = 82000, ν = 0.28.
  const HertzReport h =
      hertz_from_a1_and_ratio(0.0008, 0.5, HertzLoad::Force, 106700.0, estar_of(82000, 0.28));
  EXPECT_PRINTED(h.a1, "0.8000E-03");
  EXPECT_PRINTED(h.b1, "0.2814E-03");
  EXPECT_PRINTED(h.aa, "6.304");
  EXPECT_PRINTED(h.bb, "12.61");
  EXPECT_PRINTED(h.aa / h.bb, "0.5000");
  EXPECT_PRINTED(h.rho, "1849.");
  EXPECT_PRINTED(h.cp, "8.915");
}

// ---------------------------------------------------------------------------------------------
// Classical closed forms

TEST(Hertz3d, SphereClosedForm) {
  // Sphere of radius R on a plane: h = r²/(2R), A1 = B1 = 1/(2R), ρ = 2R; a³ = 3FR/(4E*),
  // δ = a²/R, p0 = 3F/(2πa²). Only rounding differs, hence 1e-13.
  const double r = 50.0, fn = 1234.5, estar = estar_of(82000, 0.28);
  const HertzReport h = hertz_from_curvatures(0.5 / r, 0.5 / r, HertzLoad::Force, fn, estar);
  const double a = std::cbrt(3.0 * fn * r / (4.0 * estar));
  EXPECT_NEAR(h.aa / a, 1.0, 1e-13);
  EXPECT_NEAR(h.bb / a, 1.0, 1e-13);
  EXPECT_NEAR(h.pen / (a * a / r), 1.0, 1e-13);
  EXPECT_NEAR(h.rho / (2.0 * r), 1.0, 1e-14);
  EXPECT_NEAR(h.cp / a, 1.0, 1e-13);
  EXPECT_NEAR(h.pmax / (3.0 * fn / (2.0 * pi * a * a)), 1.0, 1e-13);
  // Prescribed approach: F = 4E* √R δ^{3/2} / 3.
  const double pen = 0.01;
  const HertzReport hp = hertz_from_curvatures(0.5 / r, 0.5 / r, HertzLoad::Approach, pen, estar);
  EXPECT_NEAR(hp.fn / (4.0 * estar * std::sqrt(r) * std::pow(pen, 1.5) / 3.0), 1.0, 1e-13);
  EXPECT_NEAR(hp.aa / std::sqrt(pen * r), 1.0, 1e-13);
}

TEST(Hertz3d, CurvatureRatioMatchesHighPrecision) {
  // m_c·D/B at g = 0.5, 0.25, 1e-3 from mpmath 1.3 (40 digits); 1e-14 relative.
  EXPECT_NEAR(hertz_curvature_ratio(0.5) / 0.35177164228418607105, 1.0, 1e-14);
  EXPECT_NEAR(hertz_curvature_ratio(0.25) / 0.12043375760273162932, 1.0, 1e-14);
  EXPECT_NEAR(hertz_curvature_ratio(1e-3) / 7.2940796388419188061e-6, 1.0, 1e-14);
  EXPECT_DOUBLE_EQ(hertz_curvature_ratio(1.0), 1.0);
}

TEST(Hertz3d, AxisRatioInvertsCurvatureRatio) {
  // Bisection to adjacent doubles: the round trip g → r → g is limited by the conditioning
  // d ln g / d ln r, which is ≤ ~1/(1.4) for small g and grows near g = 1 where r ≈ 1 − c(1−g):
  // an error of one ulp in r (1e-16) moves g by ~1e-16/c, so 1e-13 relative is generous.
  for (double g : {1e-6, 1e-4, 0.01, 0.1, 0.3, 0.5, 0.8, 0.99, 0.999999}) {
    const double r = hertz_curvature_ratio(g);
    EXPECT_NEAR(hertz_axis_ratio(r) / g, 1.0, 1e-13) << "g=" << g;
  }
  EXPECT_EQ(hertz_axis_ratio(1.0), 1.0);
  EXPECT_THROW(hertz_axis_ratio(0.0), ProblemError);
  EXPECT_THROW(hertz_axis_ratio(1.5), ProblemError);
}

TEST(Hertz3d, OrientationSmallerAxisAlongLargerCurvature) {
  const double estar = estar_of(82000, 0.28);
  const HertzReport h1 = hertz_from_curvatures(0.004, 0.001, HertzLoad::Force, 1e4, estar);
  EXPECT_LT(h1.aa, h1.bb);  // A1 > B1: short axis along x
  const HertzReport h2 = hertz_from_curvatures(0.001, 0.004, HertzLoad::Force, 1e4, estar);
  EXPECT_GT(h2.aa, h2.bb);
  // Swapping the curvatures swaps the axes and nothing else.
  EXPECT_NEAR(h1.aa, h2.bb, 1e-13 * h1.aa);
  EXPECT_NEAR(h1.bb, h2.aa, 1e-13 * h1.bb);
  EXPECT_NEAR(h1.pen, h2.pen, 1e-13 * h1.pen);
}

TEST(Hertz3d, RoundTripsBetweenOptions) {
  // Every option solves the same two Hertz relations, so going curvatures → semi-axes →
  // curvatures and force → approach → force must reproduce the input to ~10 ulp (1e-12).
  const double estar = estar_of(82000, 0.28);
  for (double ratio : {1.0, 0.7, 0.2, 1e-3, 1e-6}) {
    for (bool a_larger : {true, false}) {
      const double a1 = a_larger ? 0.002 : 0.002 * ratio;
      const double b1 = a_larger ? 0.002 * ratio : 0.002;
      const double fn = 5e4;
      const HertzReport f = hertz_from_curvatures(a1, b1, HertzLoad::Force, fn, estar);
      const HertzReport p = hertz_from_curvatures(a1, b1, HertzLoad::Approach, f.pen, estar);
      EXPECT_NEAR(p.fn / fn, 1.0, 1e-12) << ratio;
      EXPECT_NEAR(p.aa / f.aa, 1.0, 1e-12) << ratio;
      EXPECT_NEAR(p.bb / f.bb, 1.0, 1e-12) << ratio;

      const HertzReport s = hertz_from_semiaxes(f.aa, f.bb, HertzLoad::Force, fn, estar);
      EXPECT_NEAR(s.a1 / a1, 1.0, 1e-12) << ratio;
      EXPECT_NEAR(s.b1 / b1, 1.0, 1e-12) << ratio;
      EXPECT_NEAR(s.pen / f.pen, 1.0, 1e-12) << ratio;
      const HertzReport sp = hertz_from_semiaxes(f.aa, f.bb, HertzLoad::Approach, f.pen, estar);
      EXPECT_NEAR(sp.fn / fn, 1.0, 1e-12) << ratio;
      EXPECT_NEAR(sp.a1 / a1, 1.0, 1e-12) << ratio;

      const HertzReport r = hertz_from_a1_and_ratio(a1, f.aa / f.bb, HertzLoad::Force, fn, estar);
      EXPECT_NEAR(r.b1 / b1, 1.0, 1e-12) << ratio;
      EXPECT_NEAR(r.aa / f.aa, 1.0, 1e-12) << ratio;
      EXPECT_NEAR(r.bb / f.bb, 1.0, 1e-12) << ratio;
    }
  }
}

TEST(Hertz3d, PressureIntegratesToForce) {
  // ∫∫ p0 √(1 − x²/a² − y²/b²) = (2π/3) p0 a b = FN. Midpoint rule on 800² points: the square-
  // root edge limits the error to O(h^{1.5}) ≈ 1e-4 relative; 1e-3 is the assertion.
  const HertzReport h = hertz_from_semiaxes(8.0, 4.0, HertzLoad::Force, 82000.0, 1e5);
  const int n = 800;
  const double dx = 2.0 * h.aa / n, dy = 2.0 * h.bb / n;
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      sum += hertz_pressure(h, -h.aa + (i + 0.5) * dx, -h.bb + (j + 0.5) * dy);
    }
  }
  EXPECT_NEAR(sum * dx * dy / h.fn, 1.0, 1e-3);
  EXPECT_DOUBLE_EQ(hertz_pressure(h, 0.0, 0.0), h.pmax);
  EXPECT_EQ(hertz_pressure(h, 8.0001, 0.0), 0.0);
  EXPECT_EQ(hertz_pressure(h, 0.0, -4.0001), 0.0);
  EXPECT_EQ(hertz_pressure(HertzReport{}, 0.0, 0.0), 0.0);
}

TEST(Hertz3d, RejectsInadmissibleData) {
  EXPECT_THROW(hertz_from_curvatures(0.0, 0.01, HertzLoad::Force, 1.0, 1e5), ProblemError);
  EXPECT_THROW(hertz_from_curvatures(0.01, -0.01, HertzLoad::Force, 1.0, 1e5), ProblemError);
  EXPECT_THROW(hertz_from_curvatures(0.01, 0.01, HertzLoad::Force, 0.0, 1e5), ProblemError);
  EXPECT_THROW(hertz_from_curvatures(0.01, 0.01, HertzLoad::Approach, -1e-3, 1e5), ProblemError);
  EXPECT_THROW(hertz_from_semiaxes(1.0, 1.0, HertzLoad::Force, 1.0, 0.0), ProblemError);
  EXPECT_THROW(hertz_from_a1_and_ratio(0.01, 0.0, HertzLoad::Force, 1.0, 1e5), ProblemError);
  EXPECT_THROW(hertz_from_semiaxes(std::nan(""), 1.0, HertzLoad::Force, 1.0, 1e5), ProblemError);
}

// ---------------------------------------------------------------------------------------------
// 2-D line contact

TEST(Hertz2d, CylinderClosedForm) {
  // Cylinder of radius R on a plane, load per length P = FN/L, L = 2b:
  // a = √(4PR/(πE*)), p0 = 2P/(πa) (Johnson, Contact Mechanics, §4.2). A1 = 1/(2R).
  const double r = 50.0, fn = 2000.0, b = 5.0, estar = estar_of(82000, 0.28);
  const HertzReport h = hertz_2d_from_curvature(0.5 / r, b, fn, estar);
  const double p = fn / (2.0 * b);
  const double a = std::sqrt(4.0 * p * r / (pi * estar));
  EXPECT_TRUE(h.present);
  EXPECT_TRUE(h.two_dimensional);
  EXPECT_NEAR(h.aa / a, 1.0, 1e-14);
  EXPECT_EQ(h.bb, b);
  EXPECT_EQ(h.b1, 0.0);
  EXPECT_EQ(h.pen, 0.0);
  EXPECT_NEAR(h.pmax / (2.0 * p / (pi * a)), 1.0, 1e-14);
  EXPECT_NEAR(h.rho / (2.0 / h.a1), 1.0, 1e-15);

  // −5 inverts −4.
  const HertzReport h5 = hertz_2d_from_half_length(h.aa, b, fn, estar);
  EXPECT_NEAR(h5.a1 / h.a1, 1.0, 1e-14);
  EXPECT_NEAR(h5.pmax / h.pmax, 1.0, 1e-14);
}

TEST(Hertz2d, PressureIntegratesToForce) {
  // ∫ p0 √(1 − x²/a²) dx · L = (π/2) p0 a L = FN; midpoint rule with 2e5 points (1e-6).
  const HertzReport h = hertz_2d_from_half_length(0.5, 2.0, 300.0, 1e5);
  const int n = 200000;
  const double dx = 2.0 * h.aa / n;
  double sum = 0.0;
  for (int i = 0; i < n; ++i) sum += hertz_pressure(h, -h.aa + (i + 0.5) * dx, 1.9);
  EXPECT_NEAR(sum * dx * 2.0 * h.bb / h.fn, 1.0, 1e-6);
  EXPECT_EQ(hertz_pressure(h, 0.0, 2.0001), 0.0);  // outside the strip |y| ≤ b
  EXPECT_DOUBLE_EQ(hertz_pressure(h, 0.0, -2.0), h.pmax);
}

TEST(Hertz2d, RejectsInadmissibleData) {
  EXPECT_THROW(hertz_2d_from_curvature(0.01, 0.0, 1.0, 1e5), ProblemError);
  EXPECT_THROW(hertz_2d_from_curvature(0.01, 1.0, 0.0, 1e5), ProblemError);
  EXPECT_THROW(hertz_2d_from_half_length(-1.0, 1.0, 1.0, 1e5), ProblemError);
}

}  // namespace
}  // namespace rollcontact::geometry
