// Influence coefficients (spec/physics.md §3.2): high-precision references, closed forms,
// symmetries, far-field (Boussinesq–Cerruti) limits and the kernel tabulation.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "elastic/influence.hpp"
#include "rollcontact/errors.hpp"

namespace rollcontact::elastic {
namespace {

constexpr double kPi = std::numbers::pi;

struct Reference {
  Component c;
  int ix, iy;  // offset in elements
  double dx, dy;
  double value;  // ν = 0.3, K = 0.1
};

// Computed with mpmath at 40 significant digits from the corner-sum formulas of §3.2 (exact
// decimal dx, dy). Includes 2-D strips (dy/dx = 5e3 and, as in bentall, 1e6) where the four
// corner terms are up to 1e6 times larger than the coefficient.
const Reference kReferences[] = {
    {Component::nn, 0, 0, 0.04, 200, 0.18200292783470193645},
    {Component::xx, 0, 0, 0.04, 200, 0.18964236505218333169},
    {Component::yy, 0, 0, 0.04, 200, 0.25236474540352137111},
    {Component::xy, 0, 0, 0.04, 200, 0.0},
    {Component::xn, 0, 0, 0.04, 200, 0.0},
    {Component::yn, 0, 0, 0.04, 200, 0.0},
    {Component::nn, 3, 0, 0.04, 200, 0.1323220562119169807},
    {Component::xx, 3, 0, 0.04, 200, 0.13996148792900981313},
    {Component::yy, 3, 0, 0.04, 200, 0.18139207715707428285},
    {Component::xy, 3, 0, 0.04, 200, 0.0},
    {Component::xn, 3, 0, 0.04, 200, -0.0039969442266001498449},
    {Component::yn, 3, 0, 0.04, 200, 0.0},
    {Component::nn, 50, 0, 0.04, 200, 0.082090866500042238708},
    {Component::xx, 50, 0, 0.04, 200, 0.089728776288375049471},
    {Component::yy, 50, 0, 0.04, 200, 0.10963475664029895882},
    {Component::xy, 50, 0, 0.04, 200, 0.0},
    {Component::xn, 50, 0, 0.04, 200, -0.0039490772078707357777},
    {Component::yn, 50, 0, 0.04, 200, 0.0},
    {Component::nn, -7, 0, 0.04, 200, 0.11715065987614002406},
    {Component::xx, -7, 0, 0.04, 200, 0.12479006714720520872},
    {Component::yy, -7, 0, 0.04, 200, 0.15971867826627770685},
    {Component::xy, -7, 0, 0.04, 200, 0.0},
    {Component::xn, -7, 0, 0.04, 200, 0.0039928698772778988215},
    {Component::yn, -7, 0, 0.04, 200, 0.0},
    {Component::nn, 0, 0, 0.001, 1000, 0.0069111827114582493304},
    {Component::xx, 0, 0, 0.001, 1000, 0.0071021686431684919023},
    {Component::yy, 0, 0, 0.001, 1000, 0.0096821322275158279001},
    {Component::xy, 0, 0, 0.001, 1000, 0.0},
    {Component::xn, 0, 0, 0.001, 1000, 0.0},
    {Component::yn, 0, 0, 0.001, 1000, 0.0},
    {Component::nn, 1, 0, 0.001, 1000, 0.0061768144910699694304},
    {Component::xx, 1, 0, 0.001, 1000, 0.0063678004227798300305},
    {Component::yy, 1, 0, 0.001, 1000, 0.0086330347698186671577},
    {Component::xy, 1, 0, 0.001, 1000, 0.0},
    {Component::xn, 1, 0, 0.001, 1000, -0.000099999872676045526696},
    {Component::yn, 1, 0, 0.001, 1000, 0.0},
    {Component::nn, 100, 0, 0.001, 1000, 0.0041044412150027664535},
    {Component::xx, 100, 0, 0.001, 1000, 0.0042954271428932905058},
    {Component::yy, 100, 0, 0.001, 1000, 0.0056725015221134280241},
    {Component::xy, 100, 0, 0.001, 1000, 0.0},
    {Component::xn, 100, 0, 0.001, 1000, -0.000099987267604722417886},
    {Component::yn, 100, 0, 0.001, 1000, 0.0},
    {Component::nn, -215, 0, 0.001, 1000, 0.0037633214016216464658},
    {Component::xx, -215, 0, 0.001, 1000, 0.0039543073156752420997},
    {Component::yy, -215, 0, 0.001, 1000, 0.0051851875168344707458},
    {Component::xy, -215, 0, 0.001, 1000, 0.0},
    {Component::xn, -215, 0, 0.001, 1000, 0.000099972625351475393881},
    {Component::yn, -215, 0, 0.001, 1000, 0.0},
    {Component::nn, 0, 0, 0.5, 0.25, 0.26805534221377898185},
    {Component::xx, 0, 0, 0.5, 0.25, 0.33698385878303643433},
    {Component::yy, 0, 0, 0.5, 0.25, 0.31400768659328395017},
    {Component::xy, 0, 0, 0.5, 0.25, 0.0},
    {Component::xn, 0, 0, 0.5, 0.25, 0.0},
    {Component::yn, 0, 0, 0.5, 0.25, 0.0},
    {Component::nn, 2, -1, 0.5, 0.25, 0.027459008367775262472},
    {Component::xx, 2, -1, 0.5, 0.25, 0.038432819995481097192},
    {Component::yy, 2, -1, 0.5, 0.25, 0.028253343183401683097},
    {Component::xy, 2, -1, 0.5, 0.25, -0.0028052313785368243925},
    {Component::xn, 2, -1, 0.5, 0.25, -0.0037871500298267764925},
    {Component::yn, 2, -1, 0.5, 0.25, 0.00097480617803257911244},
    {Component::nn, -3, 4, 0.5, 0.25, 0.015502196621954815342},
    {Component::xx, -3, 4, 0.5, 0.25, 0.020066755061161465389},
    {Component::yy, -3, 4, 0.5, 0.25, 0.017581436735014514728},
    {Component::xy, -3, 4, 0.5, 0.25, -0.0030584880624065962701},
    {Component::xn, -3, 4, 0.5, 0.25, 0.0018343295088284707374},
    {Component::yn, -3, 4, 0.5, 0.25, -0.001234690437981215925},
    {Component::nn, 10, 7, 0.5, 0.25, 0.0052606287687177309383},
    {Component::xx, 10, 7, 0.5, 0.25, 0.007268218020418609502},
    {Component::yy, 10, 7, 0.5, 0.25, 0.0055075947036101656339},
    {Component::xy, 10, 7, 0.5, 0.25, 0.00070324371369769583262},
    {Component::xn, 10, 7, 0.5, 0.25, -0.00070915310416089589953},
    {Component::yn, 10, 7, 0.5, 0.25, -0.00024848007177205409705},
    {Component::nn, 1, 1, 1, 1, 0.16147485133515627296},
    {Component::xx, 1, 1, 1, 1, 0.19607660519268976002},
    {Component::yy, 1, 1, 1, 1, 0.19607660519268976002},
    {Component::xy, 1, 1, 1, 1, 0.031880377779790389351},
    {Component::xn, 1, 1, 1, 1, -0.01598323477727467937},
    {Component::yn, 1, 1, 1, 1, -0.01598323477727467937},
    {Component::nn, -5, 2, 1, 1, 0.041435760568060592798},
    {Component::xx, -5, 2, 1, 1, 0.056707817196694680585},
    {Component::yy, -5, 2, 1, 1, 0.043921887040023901926},
    {Component::xy, -5, 2, 1, 1, -0.0060879362128460779849},
    {Component::xn, -5, 2, 1, 1, 0.0054881396253406156628},
    {Component::yn, -5, 2, 1, 1, -0.0021951298381187381132},
};

TEST(InfluenceCoefficient, MatchesHighPrecisionReference) {
  // Long-double corner sums: even for the bentall strip (terms ~3e3, result ~4e-3) the error is
  // ~1e-19 · 1e6 = 1e-13 relative at worst; a plain double evaluation is off by ~1e-10 there.
  // Zero references (odd components at symmetric offsets) are compared against the scale of the
  // row (the C_nn value of the same offset).
  for (const Reference& r : kReferences) {
    const double got = influence_coefficient(r.c, r.ix * r.dx, r.iy * r.dy, r.dx, r.dy, 0.3, 0.1);
    const double scale = std::max(
        std::abs(r.value), std::abs(influence_coefficient(Component::nn, r.ix * r.dx, r.iy * r.dy,
                                                          r.dx, r.dy, 0.3, 0.1)));
    EXPECT_NEAR(got, r.value, 1e-13 * scale)
        << "component " << static_cast<int>(r.c) << " offset " << r.ix << "," << r.iy << " dx "
        << r.dx << " dy " << r.dy;
  }
}

/// ⟦J₁⟧ and ⟦J₂⟧ at offset 0 in closed form: with a = δx/2, b = δy/2, R = √(a²+b²),
/// ⟦Y ln(X+R)⟧ = 2b ln((R+a)/(R−a)) = 4b ln((R+a)/b), ⟦X ln(Y+R)⟧ = 4a ln((R+b)/a).
struct SelfTerms {
  double j1, j2;
};
SelfTerms self_terms(double dx, double dy) {
  const double a = 0.5 * dx, b = 0.5 * dy, r = std::hypot(a, b);
  // log1p of (R+a−b)/b with R−b = a²/(R+b): no cancellation for any aspect ratio.
  return {4.0 * b * std::log1p((a + a * a / (r + b)) / b),
          4.0 * a * std::log1p((b + b * b / (r + a)) / a)};
}

TEST(InfluenceCoefficient, SelfCoefficientsMatchClosedForm) {
  const double nu = 0.28;
  for (const auto& [dx, dy] : {std::pair{1.0, 1.0}, std::pair{0.1, 0.3}, std::pair{2.0, 0.05},
                               std::pair{0.04, 200.0}, std::pair{0.001, 1000.0}}) {
    const SelfTerms t = self_terms(dx, dy);
    const double nn = (1 - nu) / kPi * (t.j1 + t.j2);
    const double xx = (t.j1 + (1 - nu) * t.j2) / kPi;
    const double yy = (t.j2 + (1 - nu) * t.j1) / kPi;
    EXPECT_NEAR(influence_coefficient(Component::nn, 0, 0, dx, dy, nu, 0), nn, 2e-14 * nn) << dx;
    EXPECT_NEAR(influence_coefficient(Component::xx, 0, 0, dx, dy, nu, 0), xx, 2e-14 * xx) << dx;
    EXPECT_NEAR(influence_coefficient(Component::yy, 0, 0, dx, dy, nu, 0), yy, 2e-14 * yy) << dx;
    // Odd components vanish at the element's own centre.
    EXPECT_NEAR(influence_coefficient(Component::xy, 0, 0, dx, dy, nu, 0.3), 0.0, 1e-15 * nn);
    EXPECT_NEAR(influence_coefficient(Component::xn, 0, 0, dx, dy, nu, 0.3), 0.0, 1e-15 * nn);
    EXPECT_NEAR(influence_coefficient(Component::yn, 0, 0, dx, dy, nu, 0.3), 0.0, 1e-15 * nn);
  }
  // Square element: ∫∫ dA/r over the square = 4δx ln(1+√2), the classical Love result.
  const double dx = 0.7;
  EXPECT_NEAR(influence_coefficient(Component::nn, 0, 0, dx, dx, nu, 0),
              (1 - nu) / kPi * 4 * dx * std::log(1 + std::sqrt(2.0)), 1e-14);
}

TEST(InfluenceCoefficient, Symmetries) {
  const double dx = 0.3, dy = 0.7, nu = 0.27, k = 0.12;
  const double tol = 1e-15 * influence_coefficient(Component::nn, 0, 0, dx, dy, nu, k);
  auto c = [&](Component comp, double ox, double oy) {
    return influence_coefficient(comp, ox, oy, dx, dy, nu, k);
  };
  for (int ix = -4; ix <= 4; ++ix) {
    for (int iy = -3; iy <= 3; ++iy) {
      // Include off-grid offsets (rolling shifts).
      for (double frac : {0.0, 0.37}) {
        const double x = (ix + frac) * dx, y = (iy - frac) * dy;
        for (Component e : {Component::nn, Component::xx, Component::yy}) {
          EXPECT_NEAR(c(e, x, y), c(e, -x, y), tol);
          EXPECT_NEAR(c(e, x, y), c(e, x, -y), tol);
        }
        EXPECT_NEAR(c(Component::xy, x, y), -c(Component::xy, -x, y), tol);  // odd in x
        EXPECT_NEAR(c(Component::xy, x, y), -c(Component::xy, x, -y), tol);  // odd in y
        EXPECT_NEAR(c(Component::xn, x, y), -c(Component::xn, -x, y), tol);  // odd in x
        EXPECT_NEAR(c(Component::xn, x, y), c(Component::xn, x, -y), tol);   // even in y
        EXPECT_NEAR(c(Component::yn, x, y), c(Component::yn, -x, y), tol);   // even in x
        EXPECT_NEAR(c(Component::yn, x, y), -c(Component::yn, x, -y), tol);  // odd in y
        EXPECT_EQ(c(Component::nx, x, y), -c(Component::xn, x, y));
        EXPECT_EQ(c(Component::ny, x, y), -c(Component::yn, x, y));
        EXPECT_EQ(c(Component::yx, x, y), c(Component::xy, x, y));
        // Exchanging the roles of x and y (element dimensions too) maps xx ↔ yy, xn ↔ yn.
        auto swapped = [&](Component comp) {
          return influence_coefficient(comp, y, x, dy, dx, nu, k);
        };
        EXPECT_NEAR(c(Component::xx, x, y), swapped(Component::yy), tol);
        EXPECT_NEAR(c(Component::nn, x, y), swapped(Component::nn), tol);
        EXPECT_NEAR(c(Component::xy, x, y), swapped(Component::xy), tol);
        EXPECT_NEAR(c(Component::xn, x, y), swapped(Component::yn), tol);
      }
    }
  }
}

TEST(InfluenceCoefficient, SignsOfThePointLoadSolutions) {
  // Normal pressure pushes body 1 up (u_n > 0 everywhere); a traction p_x moves the surface in
  // +x; in the quadrant x, y > 0 a p_x load gives u_y > 0 (Cerruti, ν > 0); for K > 0 a
  // pressure pulls body 1's surface towards the load: u_x < 0 for x > 0.
  const double dx = 1.0, dy = 1.0, nu = 0.3, k = 0.1;
  EXPECT_GT(influence_coefficient(Component::nn, 3, 2, dx, dy, nu, k), 0.0);
  EXPECT_GT(influence_coefficient(Component::xx, 3, 2, dx, dy, nu, k), 0.0);
  EXPECT_GT(influence_coefficient(Component::xy, 3, 2, dx, dy, nu, k), 0.0);
  EXPECT_LT(influence_coefficient(Component::xn, 3, 0, dx, dy, nu, k), 0.0);
  EXPECT_LT(influence_coefficient(Component::yn, 0, 3, dx, dy, nu, k), 0.0);
}

TEST(InfluenceCoefficient, FarFieldIsThePointLoadSolution) {
  // Far away the element acts as a point force dx·dy; the midpoint rule's relative error is
  // O((δ/r)²)/24 ≈ 1e-6 at r = 100 δ, so 2e-5 leaves room but still fails for a wrong term
  // (every term of the Cerruti formula contributes at least 5 % of the value here).
  const double dx = 0.5, dy = 0.3, nu = 0.3, k = 0.2, area = dx * dy;
  for (const auto& [x, y] : {std::pair{50.0, 0.3}, std::pair{-40.0, 30.0}, std::pair{1.5, -60.0},
                             std::pair{35.5, 35.4}}) {
    const double r = std::hypot(x, y);
    const struct {
      Component c;
      double expected;
    } cases[] = {
        {Component::nn, (1 - nu) / (kPi * r) * area},
        {Component::xx, (1 - nu + nu * x * x / (r * r)) / (kPi * r) * area},
        {Component::yy, (1 - nu + nu * y * y / (r * r)) / (kPi * r) * area},
        {Component::xy, nu * x * y / (kPi * r * r * r) * area},
        {Component::xn, -k * x / (kPi * r * r) * area},
        {Component::yn, -k * y / (kPi * r * r) * area},
        {Component::nx, k * x / (kPi * r * r) * area},
    };
    const double scale = area / (kPi * r);
    for (const auto& e : cases) {
      EXPECT_NEAR(influence_coefficient(e.c, x, y, dx, dy, nu, k), e.expected, 2e-5 * scale)
          << "component " << static_cast<int>(e.c) << " at " << x << "," << y;
    }
  }
}

TEST(InfluenceCoefficient, CouplingVanishesForQuasiIdenticalBodies) {
  EXPECT_EQ(influence_coefficient(Component::xn, 2, 1, 1, 1, 0.3, 0.9e-6), 0.0);
  EXPECT_EQ(influence_coefficient(Component::ny, 2, 1, 1, 1, 0.3, -0.9e-6), 0.0);
  EXPECT_NE(influence_coefficient(Component::xn, 2, 1, 1, 1, 0.3, 2e-6), 0.0);
}

TEST(InfluenceCoefficient, ContinuousWhereCornersCrossTheAxes) {
  // An observation shift of δx/2 puts corners on X = 0, where the atan and log guards act.
  const double dx = 0.2, dy = 0.4, nu = 0.3, k = 0.3, eps = 1e-9;
  for (Component c :
       {Component::nn, Component::xx, Component::yy, Component::xy, Component::xn, Component::yn}) {
    for (double oy : {0.0, 0.2, -1.2}) {
      const double at = influence_coefficient(c, 0.5 * dx, oy, dx, dy, nu, k);
      const double near = influence_coefficient(c, 0.5 * dx + eps, oy, dx, dy, nu, k);
      ASSERT_TRUE(std::isfinite(at));
      EXPECT_NEAR(at, near, 1e-7) << static_cast<int>(c) << " oy " << oy;
      const double at_y = influence_coefficient(c, 0.3, 0.5 * dy, dx, dy, nu, k);
      const double near_y = influence_coefficient(c, 0.3, 0.5 * dy - eps, dx, dy, nu, k);
      ASSERT_TRUE(std::isfinite(at_y));
      EXPECT_NEAR(at_y, near_y, 1e-7) << static_cast<int>(c);
    }
  }
}

TEST(MakeKernel, AgreesWithCoefficientsDividedByG) {
  const Grid grid{.mx = 5, .my = 4, .xl = -1.0, .yl = 2.0, .dx = 0.3, .dy = 0.45};
  const CombinedMaterial m{.g = 2.5, .nu = 0.29, .k = -0.15};
  for (const auto& [sx, sy] : {std::pair{0.0, 0.0}, std::pair{0.07, -0.11}, std::pair{0.15, 0.0}}) {
    for (Component c : {Component::nn, Component::xx, Component::yy, Component::xy, Component::xn,
                        Component::yn, Component::nx, Component::ny, Component::yx}) {
      const Kernel kern = make_kernel(c, grid, m, sx, sy);
      ASSERT_EQ(kern.mx(), 5);
      ASSERT_EQ(kern.my(), 4);
      ASSERT_EQ(kern.data().size(), 9u * 7u);
      const double scale = influence_coefficient(Component::nn, 0, 0, grid.dx, grid.dy, m.nu, 0);
      for (int diy = -3; diy <= 3; ++diy) {
        for (int dix = -4; dix <= 4; ++dix) {
          // C′(offset) = C(offset + shift), divided by G.
          const double expected = influence_coefficient(c, dix * grid.dx + sx, diy * grid.dy + sy,
                                                        grid.dx, grid.dy, m.nu, m.k) /
                                  m.g;
          EXPECT_NEAR(kern.at(dix, diy), expected, 1e-14 * scale)
              << static_cast<int>(c) << " " << dix << "," << diy;
        }
      }
    }
  }
}

TEST(MakeKernel, SharingMirroredCornersChangesNoBit) {
  // The tabulation shares r and the logarithms between mirrored corners; the kernels must be
  // those of the corner function evaluated at every corner, bit for bit: square, elongated and
  // strip elements, with and without rolling shifts, odd and even grids, all components.
  const CombinedMaterial m{.g = 82000.0, .nu = 0.28, .k = 0.07};
  struct Case {
    int mx, my;
    double dx, dy, sx, sy;
  };
  const Case cases[] = {{9, 11, 0.1, 0.1, 0.0, 0.0},     {12, 7, 0.2, 0.05, 0.0, 0.0},
                        {8, 8, 0.1, 0.1, 0.1, 0.0},      {10, 9, 0.1, 0.1, 0.0, 0.03},
                        {7, 6, 0.1, 0.3, 0.05, 0.02},    {20, 1, 0.001, 1000.0, 0.0, 0.0},
                        {16, 1, 0.04, 200.0, 0.01, 0.0}, {1, 1, 0.1, 0.1, 0.0, 0.0}};
  for (const Case& k : cases)
    for (Component c : {Component::nn, Component::xx, Component::yy, Component::xy, Component::yx,
                        Component::xn, Component::yn, Component::nx, Component::ny}) {
      const Grid grid{.mx = k.mx, .my = k.my, .xl = 0, .yl = 0, .dx = k.dx, .dy = k.dy};
      const Kernel shared = make_kernel(c, grid, m, k.sx, k.sy);
      const Kernel plain = make_unshared_kernel(c, grid, m, k.sx, k.sy);
      EXPECT_EQ(shared.data(), plain.data())
          << static_cast<int>(c) << " " << k.mx << "x" << k.my << " dx " << k.dx << " dy " << k.dy
          << " shift " << k.sx << "," << k.sy;
    }
  // Several components on one lattice (shared logarithms), couplings in between.
  const std::vector<Component> cs{Component::xx, Component::xn, Component::xy, Component::yy,
                                  Component::nn, Component::ny, Component::yx};
  for (const Case& k : cases) {
    const Grid grid{.mx = k.mx, .my = k.my, .xl = 0, .yl = 0, .dx = k.dx, .dy = k.dy};
    const std::vector<Kernel> together = make_kernels(cs, grid, m, k.sx, k.sy);
    ASSERT_EQ(together.size(), cs.size());
    for (std::size_t q = 0; q < cs.size(); ++q)
      EXPECT_EQ(together[q].data(), make_unshared_kernel(cs[q], grid, m, k.sx, k.sy).data())
          << static_cast<int>(cs[q]) << " " << k.mx << "x" << k.my << " shift " << k.sx << ","
          << k.sy;
  }
}

TEST(MakeKernel, StripKernelMatchesReference) {
  // bentall-like strip: 216 × 1 elements of 0.001 × 1000 mm, G = 35924.
  const Grid grid{.mx = 216, .my = 1, .xl = -0.108, .yl = -500.0, .dx = 0.001, .dy = 1000.0};
  const CombinedMaterial m{.g = 35924.0, .nu = 0.3, .k = 0.1};
  const Kernel nn = make_kernel(Component::nn, grid, m);
  const Kernel xn = make_kernel(Component::xn, grid, m);
  EXPECT_NEAR(nn.at(0, 0) * m.g, 0.0069111827114582493304, 1e-13 * 0.0069);
  EXPECT_NEAR(nn.at(100, 0) * m.g, 0.0041044412150027664535, 1e-13 * 0.0041);
  // Mirror offsets are evaluated by different (cancellation-free) branches of X + R, so they
  // agree only to the corner-sum accuracy (~1e-19 · 1e6 relative for this strip).
  EXPECT_NEAR(nn.at(-100, 0), nn.at(100, 0), 1e-13 * nn.at(100, 0));
  EXPECT_NEAR(nn.at(-215, 0) * m.g, 0.0037633214016216464658, 1e-13 * 0.0038);
  EXPECT_NEAR(xn.at(1, 0) * m.g, -0.000099999872676045526696, 1e-13 * 0.0069);
  EXPECT_NEAR(xn.at(-215, 0) * m.g, 0.000099972625351475393881, 1e-13 * 0.0069);
}

TEST(MakeKernel, SumOverABlockIsTheCoefficientOfTheBlock) {
  // Corner sums telescope: the displacement at an element centre due to uniform pressure on an
  // n × m block of elements equals the coefficient of one big element covering the block.
  const Grid grid{.mx = 7, .my = 5, .xl = 0, .yl = 0, .dx = 0.2, .dy = 0.1};
  const CombinedMaterial m{.g = 1.0, .nu = 0.25, .k = 0.2};
  for (Component c : {Component::nn, Component::xx, Component::xy, Component::xn}) {
    const Kernel kern = make_kernel(c, grid, m);
    // Observation element (2, 1); source block: all 7 × 5 elements.
    double sum = 0;
    for (int jy = 0; jy < 5; ++jy) {
      for (int jx = 0; jx < 7; ++jx) sum += kern.at(2 - jx, 1 - jy);
    }
    // Block centre (0.7, 0.25), observation centre (0.5, 0.15).
    const double big = influence_coefficient(c, 0.5 - 0.7, 0.15 - 0.25, 1.4, 0.5, m.nu, m.k);
    EXPECT_NEAR(sum, big, 1e-13 * std::abs(big)) << static_cast<int>(c);
  }
}

TEST(MakeKernel, DividesByGAndDropsWeakCoupling) {
  const Grid grid{.mx = 3, .my = 2, .xl = 0, .yl = 0, .dx = 1, .dy = 1};
  const Kernel a = make_kernel(Component::xx, grid, {.g = 1.0, .nu = 0.3, .k = 0});
  const Kernel b = make_kernel(Component::xx, grid, {.g = 4.0, .nu = 0.3, .k = 0});
  for (std::size_t i = 0; i < a.data().size(); ++i) EXPECT_DOUBLE_EQ(a.data()[i], 4 * b.data()[i]);
  const Kernel none = make_kernel(Component::xn, grid, {.g = 1.0, .nu = 0.3, .k = 5e-7});
  for (double v : none.data()) EXPECT_EQ(v, 0.0);
  EXPECT_THROW(make_kernel(Component::nn, grid, {.g = 0.0, .nu = 0.3, .k = 0}), ProblemError);
}

}  // namespace
}  // namespace rollcontact::elastic

namespace rollcontact::elastic {
namespace {

TEST(LayerCompliance, AddsToTheElementUnderTheObservationPointOnly) {
  // An interfacial layer (M=4) shears by (h/G₃)·p_t under the loaded element alone: the
  // tangential kernels change by h/G₃ at one offset — (0,0), or the neighbour's offset when the
  // observation point is moved by one rolling step — and C_nn, C_xy not at all.
  const Grid grid{6, 5, -3.0, -2.5, 0.5, 0.4};
  CombinedMaterial plain{82000.0, 0.28, 0.0}, layered = plain;
  layered.layer_compliance = 0.02 / 176.63;
  for (const double shift : {0.0, 0.5, -0.5}) {
    const int expected_dix = shift > 0 ? -1 : shift < 0 ? 1 : 0;
    for (const Component c : {Component::xx, Component::yy, Component::xy, Component::nn}) {
      const Kernel a = make_kernel(c, grid, plain, shift, 0.0);
      const Kernel b = make_kernel(c, grid, layered, shift, 0.0);
      for (int diy = -(grid.my - 1); diy < grid.my; ++diy)
        for (int dix = -(grid.mx - 1); dix < grid.mx; ++dix) {
          const bool diagonal = c == Component::xx || c == Component::yy;
          const double added =
              diagonal && dix == expected_dix && diy == 0 ? layered.layer_compliance : 0.0;
          EXPECT_NEAR(b.at(dix, diy) - a.at(dix, diy), added, 1e-18) << dix << ' ' << diy;
        }
    }
  }
}

}  // namespace
}  // namespace rollcontact::elastic
