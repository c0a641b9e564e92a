// Bilinear traction elements (C=3, spec-additions.md §B7): high-precision references, the far
// field against the constant elements, a uniform load, symmetries and the kernel tabulation.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "elastic/bilinear_kernel.hpp"
#include "elastic/influence.hpp"

namespace rollcontact::elastic {
namespace {

struct Reference {
  Component c;
  int ix, iy;    // offset in elements of 0.1 × 0.07 mm
  double value;  // ν = 0.3, K = 0.1, without 1/G
};

// mpmath at 40 digits from the 9-node closed forms of bilinear_kernel.cpp, which agree with
// adaptive quadrature of the definition I[f] = ∫∫ f(Δ − ξ)(1 − |ξ|/δx)(1 − |η|/δy) to 1e-28.
// Offsets (7, 4) and beyond are evaluated by the quadrature branch.
const Reference kReferences[] = {
    {Component::nn, 0, 0, 0.055001927522237971022},
    {Component::xx, 0, 0, 0.067802485673637121363},
    {Component::yy, 0, 0, 0.065773624023226522548},
    {Component::xy, 0, 0, 0.0},
    {Component::xn, 0, 0, 0.0},
    {Component::yn, 0, 0, 0.0},
    {Component::nn, 1, 0, 0.018447160689897168107},
    {Component::xx, 1, 0, 0.025180630496242227573},
    {Component::yy, 1, 0, 0.019619616893508037829},
    {Component::xy, 1, 0, 0.0},
    {Component::xn, 1, 0, -0.0024036643168630400939},
    {Component::yn, 1, 0, 0.0},
    {Component::nn, -1, 2, 0.0092028033434285923816},
    {Component::xx, -1, 2, 0.010506456460829826843},
    {Component::yy, -1, 2, 0.01184320880178246894},
    {Component::xy, -1, 2, -0.0016576863609710382268},
    {Component::xn, -1, 2, 0.00071668712038884366511},
    {Component::yn, -1, 2, -0.0010641048467504741421},
    {Component::nn, 3, -2, 0.0047566487796217459762},
    {Component::xx, 3, -2, 0.0064097442034130874127},
    {Component::yy, 3, -2, 0.0051421171185254385295},
    {Component::xy, 3, -2, -0.00077444033012604263181},
    {Component::xn, 3, -2, -0.00061124887038012399628},
    {Component::yn, 3, -2, 0.00028966751483251827549},
    {Component::nn, 7, 4, 0.0020727604521622690318},
    {Component::xx, 7, 4, 0.0028368666542977774337},
    {Component::yy, 7, 4, 0.0021969801580963045007},
    {Component::xy, 7, 4, 0.00030596437230829141448},
    {Component::xn, 7, 4, -0.00027458900995664131469},
    {Component::yn, 7, 4, -0.00011016397166763892968},
    {Component::nn, -15, -9, 0.00095907520632988250627},
    {Component::xx, -15, -9, 0.0013083035707279806922},
    {Component::yy, -15, -9, 0.0010208790732160196801},
    {Component::xy, -15, -9, 0.00014670835787482756485},
    {Component::xn, -15, -9, 0.00012628672501166530433},
    {Component::yn, -15, -9, 0.000053074487989094768082},
    {Component::nn, 40, 25, 0.00035725661824558347435},
    {Component::xx, 40, 25, 0.00048575972181983727888},
    {Component::yy, 40, 25, 0.0003818634939194368731},
    {Component::xy, 40, 25, 0.000056221770579211959527},
    {Component::xn, 40, 25, -0.00004675577096320375325},
    {Component::yn, 40, 25, -0.00002045747402422110582},
};

constexpr double kDx = 0.1, kDy = 0.07, kNu = 0.3, kK = 0.1;

TEST(BilinearCoefficients, MatchHighPrecisionReferences) {
  double worst = 0.0;
  for (const Reference& r : kReferences) {
    const double v = bilinear_coefficient(r.c, r.ix * kDx, r.iy * kDy, kDx, kDy, kNu, kK);
    EXPECT_NEAR(v, r.value, 1e-13 * std::abs(r.value) + 1e-18)
        << "component " << static_cast<int>(r.c) << " at " << r.ix << ", " << r.iy;
    if (r.value != 0.0) worst = std::max(worst, std::abs(v / r.value - 1.0));
  }
  RecordProperty("worst_relative_error", std::to_string(worst));
}

/// |C_bilinear / C_constant − 1| at the offset (ix, iy) [elements].
double far_difference(Component c, int ix, int iy) {
  const double b = bilinear_coefficient(c, ix * kDx, iy * kDy, kDx, kDy, kNu, kK);
  const double k = influence_coefficient(c, ix * kDx, iy * kDy, kDx, kDy, kNu, kK);
  return std::abs(b / k - 1.0);
}

TEST(BilinearCoefficients, FarFieldEqualsConstantElementsToSecondOrder) {
  // The hat's second moment (δ²/6 per direction) is twice the constant element's: the
  // coefficients differ by O((δ/r)²), relatively. Halving δ/r must divide the difference by 4.
  for (Component c : {Component::nn, Component::xx, Component::yy, Component::xy, Component::xn,
                      Component::yn, Component::nx, Component::ny, Component::yx}) {
    for (int n : {10, 20, 40}) {
      const double d1 = far_difference(c, n, n / 2 + 3), d2 = far_difference(c, 2 * n, n + 6);
      EXPECT_LT(d1, 1e-2) << static_cast<int>(c) << " n " << n;
      EXPECT_GT(d1 / d2, 3.5) << static_cast<int>(c) << " n " << n;
      EXPECT_LT(d1 / d2, 4.5) << static_cast<int>(c) << " n " << n;
    }
  }
}

/// Normal displacement at the centre of a uniform unit pressure on (2n+1)² elements.
double centre_displacement(bool bilinear, int n) {
  double u = 0.0;
  for (int iy = -n; iy <= n; ++iy)
    for (int ix = -n; ix <= n; ++ix)
      u += bilinear ? bilinear_coefficient(Component::nn, ix * kDx, iy * kDy, kDx, kDy, kNu, 0.0)
                    : influence_coefficient(Component::nn, ix * kDx, iy * kDy, kDx, kDy, kNu, 0.0);
  return u;
}

TEST(BilinearCoefficients, UniformLoadAgreesWithConstantElementsInTheInterior) {
  // Hats of equal height sum to 1 inside the patch and ramp to 0 over one element at its edge,
  // where constant elements stop at half an element: same load, moved by a fraction of an
  // element, so the centre displacements differ by O((δ/L)²) relatively.
  double previous = 0.0;
  for (int n : {8, 16, 32}) {
    const double uc = centre_displacement(false, n), ub = centre_displacement(true, n);
    const double d = std::abs(ub / uc - 1.0);
    EXPECT_LT(d, 2e-2) << n;
    if (previous > 0.0) {
      EXPECT_GT(previous / d, 3.0) << n;
      EXPECT_LT(previous / d, 5.0) << n;
    }
    previous = d;
  }
}

TEST(BilinearCoefficients, EvenAndOddInXAndY) {
  for (int iy = 0; iy <= 6; ++iy)
    for (int ix = 0; ix <= 9; ++ix) {
      const auto at = [&](Component c, int sx, int sy) {
        return bilinear_coefficient(c, sx * ix * kDx, sy * iy * kDy, kDx, kDy, kNu, kK);
      };
      const double nn = at(Component::nn, 1, 1), xy = at(Component::xy, 1, 1);
      const double xn = at(Component::xn, 1, 1), yn = at(Component::yn, 1, 1);
      const double tol_nn = 1e-15 * nn, tol_t = 1e-15 * at(Component::xx, 1, 1);
      for (int sx : {-1, 1})
        for (int sy : {-1, 1}) {
          EXPECT_NEAR(at(Component::nn, sx, sy), nn, tol_nn);
          EXPECT_NEAR(at(Component::xy, sx, sy), sx * sy * xy, tol_t);
          EXPECT_NEAR(at(Component::xn, sx, sy), sx * xn, tol_t);
          EXPECT_NEAR(at(Component::yn, sx, sy), sy * yn, tol_t);
          EXPECT_NEAR(at(Component::nx, sx, sy), -sx * xn, tol_t);
          EXPECT_NEAR(at(Component::yx, sx, sy), sx * sy * xy, tol_t);
        }
      if (ix == 0) {
        EXPECT_NEAR(xy, 0.0, tol_t);
      }
      if (iy == 0) {
        EXPECT_NEAR(yn, 0.0, tol_t);
      }
    }
}

CombinedMaterial bilinear_material(double k) {
  CombinedMaterial m;
  m.g = 2.0;
  m.nu = kNu;
  m.k = k;
  m.elements = model::TractionElements::bilinear;
  return m;
}

TEST(BilinearKernels, TabulateTheCoefficientsExactlyEvenAndOdd) {
  const Grid grid{12, 9, 0.0, 0.0, kDx, kDy};
  const CombinedMaterial m = bilinear_material(kK);
  const std::vector<Component> cs{Component::nn, Component::xx, Component::yy,
                                  Component::xy, Component::xn, Component::yn};
  const std::vector<Kernel> ks = make_kernels(cs, grid, m);
  for (std::size_t q = 0; q < cs.size(); ++q)
    for (int iy = -(grid.my - 1); iy < grid.my; ++iy)
      for (int ix = -(grid.mx - 1); ix < grid.mx; ++ix) {
        const double v = bilinear_coefficient(cs[q], ix * kDx, iy * kDy, kDx, kDy, kNu, kK) / m.g;
        EXPECT_NEAR(ks[q].at(ix, iy), v, 1e-15 * std::abs(ks[0].at(0, 0)));
        EXPECT_EQ(ks[q].at(ix, iy), ks[q].at(-ix, -iy) * (q >= 4 ? -1.0 : 1.0));
      }
  EXPECT_EQ(ks[3].at(0, 4), 0.0);  // C_xy odd in x
  EXPECT_EQ(ks[4].at(0, 4), 0.0);  // C_xn odd in x
  EXPECT_EQ(ks[5].at(3, 0), 0.0);  // C_yn odd in y
  // Rolling: the observation point moves by the shift; continuous where it crosses an axis.
  const std::vector<Kernel> shifted = make_kernels(cs, grid, m, 0.3 * kDx, -0.2 * kDy);
  for (std::size_t q = 0; q < cs.size(); ++q)
    EXPECT_NEAR(shifted[q].at(2, -1),
                bilinear_coefficient(cs[q], 2.3 * kDx, -1.2 * kDy, kDx, kDy, kNu, kK) / m.g,
                1e-15 * std::abs(ks[0].at(0, 0)));
  const Kernel tiny = make_kernel(Component::xn, grid, m, 1e-12 * kDx, 0.0);
  EXPECT_NEAR(tiny.at(0, 2), 0.0, 1e-9 * std::abs(ks[4].at(1, 2)));
  // Uncoupled material: the couplings vanish.
  EXPECT_EQ(make_kernel(Component::xn, grid, bilinear_material(0.0)).at(1, 1), 0.0);
}

}  // namespace
}  // namespace rollcontact::elastic
