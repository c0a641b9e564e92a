// The composed simplified solver: continuity of the blended creep curve, FaStrip properties.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "rollcontact/errors.hpp"
#include "simplified/simplified_solver.hpp"
#include "simplified_fixture.hpp"

namespace rollcontact::simplified {
namespace {

constexpr double pi = std::numbers::pi;
constexpr double g_mod = 82000.0, nu = 0.28, mu = 0.3;

struct Outcome {
  SimplifiedOutcome out;
  double fx = 0.0, fy = 0.0;
};

Outcome solve_patch(const test::Patch& p, int m, const Creepages& cr, double chi = 0.0) {
  SimplifiedCase c;
  c.grid = p.grid;
  c.pn = p.pn;
  c.ellipse = {p.hertz.aa, p.hertz.bb};
  c.g = g_mod;
  c.nu = nu;
  c.mu = mu;
  c.fn = p.fn;
  c.model.m = m;
  c.model.blend = m != 2;
  c.model.flx = 5e-5;
  c.creepages = cr;
  // Mirrored grids (χ = π) need the spin part at mirrored x as well: steady_shift uses x itself.
  const RigidShiftParts w = test::steady_shift(p.grid, cr);
  c.shift = &w;
  c.chi = chi;
  Outcome o;
  o.out = solve_simplified(c);
  o.fx = test::sum(o.out.fields.px, p.grid) / (mu * p.fn);
  o.fy = test::sum(o.out.fields.py, p.grid) / (mu * p.fn);
  return o;
}

TEST(SimplifiedSolver, BlendedCreepCurveIsContinuousAcrossFullBlending) {
  // Mixed creepages (blending changes the flexibilities only when they are not pure ξ or η).
  const test::Patch p = test::elliptic_patch(8.0, 4.0, 8.2e4, 44, 44);
  const KalkerCoefficients c = kalker_coefficients(2.0, nu);
  const double ksi_c = mu * p.fn / (32.0 * g_mod * c.c11),
               eta_c = mu * p.fn / (32.0 * g_mod * c.c22);
  const Creepages dir{0.6, 0.8, 0.5 / 8.0};          // |(ξ, η)| = 1
  const double s3 = 3.0 * std::hypot(ksi_c, eta_c);  // f/3 = 1 at this scale
  std::vector<double> f;
  const int n = 400;
  for (int k = 0; k <= n; ++k) {
    const double s = s3 * (0.8 + 0.4 * k / n);
    f.push_back(solve_patch(p, 3, {s * dir.ksi, s * dir.eta, s * dir.phi}).fy);
  }
  double mean = 0.0, worst = 0.0;
  for (int k = 1; k <= n; ++k) {
    const double d = std::abs(f[static_cast<std::size_t>(k)] - f[static_cast<std::size_t>(k - 1)]);
    mean += d / n;
    worst = std::max(worst, d);
  }
  // Elements change from adhesion to slip one at a time: the curve is continuous with a slope
  // that varies only a little between samples.
  EXPECT_LT(worst, 3.0 * mean);
  // Right at f/3 = 1 there is no jump.
  const double below =
      solve_patch(p, 3,
                  {s3 * (1 - 1e-9) * dir.ksi, s3 * (1 - 1e-9) * dir.eta, s3 * (1 - 1e-9) * dir.phi})
          .fy;
  const double above =
      solve_patch(p, 3,
                  {s3 * (1 + 1e-9) * dir.ksi, s3 * (1 + 1e-9) * dir.eta, s3 * (1 + 1e-9) * dir.phi})
          .fy;
  EXPECT_NEAR(below, above, 1e-7);
}

TEST(SimplifiedSolver, OneFlexibilityIgnoresTheKalkerCoefficients) {
  const test::Patch p = test::elliptic_patch(8.0, 4.0, 8.2e4, 22, 22);
  const Outcome o = solve_patch(p, 2, {1e-4, 0.0, 2e-4});
  EXPECT_DOUBLE_EQ(o.out.flex.l1, 5e-5);
  EXPECT_DOUBLE_EQ(o.out.flex.l3, 5e-5);
  EXPECT_DOUBLE_EQ(o.out.k_eff, 1.0);
}

TEST(SimplifiedSolver, FastripRespectsTheBoundAndPutsAdhesionAtTheLeadingEdge) {
  const test::Patch p = test::elliptic_patch(8.0, 4.0, 8.2e4, 60, 40);
  const Outcome o = solve_patch(p, 5, {-3e-4, 1e-4, 0.0});
  const Grid& g = p.grid;
  for (int iy = 0; iy < g.my; ++iy) {
    bool seen_slip = false;
    for (int ix = g.mx - 1; ix >= 0; --ix) {
      const std::size_t i = g.index(ix, iy);
      if (!(p.pn[i] > 0.0)) continue;
      EXPECT_LE(std::hypot(o.out.fields.px[i], o.out.fields.py[i]), mu * p.pn[i] * (1 + 1e-12));
      if (o.out.fields.state[i] == ElementState::Slip) seen_slip = true;
      // Pure creepage: one adhesion zone at the leading edge, slip behind it.
      if (seen_slip) {
        EXPECT_EQ(o.out.fields.state[i], ElementState::Slip) << ix << " " << iy;
      }
    }
  }
  EXPECT_GT(o.fx, 0.0);  // negative creepage, positive force
  EXPECT_LT(o.fy, 0.0);
}

TEST(SimplifiedSolver, FastripForPureCreepageIsCarterInEveryStrip) {
  // Per strip the adhesion zone is Carter's: half slip length d = |ξ′|a/(1−ν) with
  // ξ′ = 2G(1−ν)C11ξ/(μp₀π²), strip force −μ(p₀/a)(π/2)(a_y² − (a_y − d)²).
  const double a = 8.0, b = 4.0, fn = 8.2e4, ksi = 1e-4;
  const test::Patch p = test::elliptic_patch(a, b, fn, 200, 60, 1.02);
  const Outcome o = solve_patch(p, 5, {ksi, 0.0, 0.0});
  const Ellipse eq = equivalent_ellipse(p.grid, p.pn);
  const double p0 = 1.5 * fn / (pi * eq.a * eq.b);
  const double c11 = kalker_coefficients(eq.a / eq.b, nu).c11;
  const double d = 2.0 * g_mod * c11 * ksi * eq.a / (mu * p0 * pi * pi);
  double expected = 0.0;
  for (int iy = 0; iy < p.grid.my; ++iy) {
    const double y = p.grid.y_centre(iy);
    if (std::abs(y) >= b) continue;
    const double ay = a * std::sqrt(1.0 - y * y / (b * b));
    const double dd = std::min(d, ay);
    expected -= mu * p0 / eq.a * pi / 2.0 * (ay * ay - (ay - dd) * (ay - dd)) * p.grid.dy;
  }
  EXPECT_NEAR(o.fx * mu * fn, expected, 0.01 * std::abs(expected));
}

TEST(SimplifiedSolver, ReversedRollingIsTheMirrorImage) {
  // χ = π with (ξ, η, φ) is the mirror image x → −x of χ = 0 with (−ξ, η, −φ), p_x reversed.
  const test::Patch p = test::elliptic_patch(8.0, 4.0, 8.2e4, 40, 20);
  const Grid& g = p.grid;
  for (int m : {3, 5}) {
    const Outcome fwd = solve_patch(p, m, {-2e-4, 3e-4, -4e-4}, 0.0);
    const Outcome rev = solve_patch(p, m, {2e-4, 3e-4, 4e-4}, pi);
    for (int iy = 0; iy < g.my; ++iy)
      for (int ix = 0; ix < g.mx; ++ix) {
        const std::size_t i = g.index(ix, iy), j = g.index(g.mx - 1 - ix, iy);
        EXPECT_NEAR(rev.out.fields.px[i], -fwd.out.fields.px[j], 1e-9) << "M=" << m;
        EXPECT_NEAR(rev.out.fields.py[i], fwd.out.fields.py[j], 1e-9) << "M=" << m;
        EXPECT_EQ(rev.out.fields.state[i], fwd.out.fields.state[j]) << "M=" << m;
      }
  }
}

TEST(SimplifiedSolver, RejectsAPatchWithoutContact) {
  test::Patch p = test::elliptic_patch(8.0, 4.0, 8.2e4, 10, 10);
  p.hertz.aa = 0.0;
  EXPECT_THROW(solve_patch(p, 3, {1e-4, 0.0, 0.0}), ProblemError);
}

}  // namespace
}  // namespace rollcontact::simplified
