// Fastsim against Kalker's simplified theory in closed form, and its basic properties.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "simplified/fastsim.hpp"
#include "simplified_fixture.hpp"

namespace rollcontact::simplified {
namespace {

constexpr double pi = std::numbers::pi;

// Simplified theory, one flexibility L, circle of radius a, elliptic traction bound μp₀√(1−r²/a²),
// pure creepage ξ. In a strip of half length a_y the adhesion solution u = ξ(x − a_y), p = u/L
// starts at the leading edge and meets the bound after t* = 2a_y/(1+κ²), κ = |ξ|a/(Lμp₀), the
// same fraction in every strip; behind it the traction follows the bound. Integrating,
//   F/(μFN) = −(2/π)·[κt²/2 + π/4 − (u√(1−u²) + asin u)/2],  t = 2/(1+κ²), u = t − 1,
// which gives F = −(8a³/3L)ξ for small ξ (Kalker's linear simplified theory) and −μFN at
// large ξ.
double simplified_theory_force(double kappa) {
  const double t = 2.0 / (1.0 + kappa * kappa), u = t - 1.0;
  return -(2.0 / pi) *
         (kappa * t * t / 2.0 + pi / 4.0 - (u * std::sqrt(1.0 - u * u) + std::asin(u)) / 2.0);
}

struct CreepRun {
  SimplifiedFields f;
  test::Patch patch;
};

CreepRun run_pure_creepage(double ksi, double flx, double mu, int m) {
  CreepRun r;
  r.patch = test::elliptic_patch(1.0, 1.0, 10.0, m, m);
  FastsimInput in;
  in.grid = r.patch.grid;
  in.pn = r.patch.pn;
  in.mu = mu;
  const auto w = test::steady_shift(in.grid, {ksi, 0.0, 0.0});
  in.wx = w.wx;
  in.wy = w.wy;
  in.flex = {flx, flx, flx};
  r.f = fastsim(in);
  return r;
}

TEST(Fastsim, ReproducesTheSimplifiedTheoryForPureCreepage) {
  const double a = 1.0, fn = 10.0, mu = 0.3, flx = 1e-4;
  const double p0 = 1.5 * fn / (pi * a * a);
  for (double kappa : {0.05, 0.2, 0.5, 1.0, 2.0, 5.0}) {
    const double ksi = kappa * flx * mu * p0 / a;
    const CreepRun r = run_pure_creepage(ksi, flx, mu, 201);
    const double fx = test::sum(r.f.px, r.patch.grid) / (mu * r.patch.fn_discrete());
    const double exact = simplified_theory_force(kappa);
    // The particles enter each row at the first element centre instead of the exact edge: an
    // error of order δx/a = 1 %.
    EXPECT_NEAR(fx, exact, 0.012 * std::abs(exact)) << "kappa " << kappa;
    EXPECT_NEAR(test::sum(r.f.py, r.patch.grid), 0.0, 1e-12);
  }
  // The closed form itself: linear theory at small κ, saturation at large κ.
  EXPECT_NEAR(simplified_theory_force(1e-4), -4.0 * 1e-4 / pi, 1e-10);
  EXPECT_NEAR(simplified_theory_force(1e4), -1.0, 1e-7);
}

TEST(Fastsim, AdhesionTractionIsLinearInX) {
  const double ksi = 2e-4, flx = 1e-4;
  const CreepRun r = run_pure_creepage(ksi, flx, 0.3, 41);
  const Grid& g = r.patch.grid;
  const int iy = g.my / 2;
  int checked = 0;
  for (int ix = g.mx - 2; ix >= 0; --ix) {
    const std::size_t i = g.index(ix, iy), up = g.index(ix + 1, iy);
    if (r.f.state[i] != ElementState::Adhesion || r.f.state[up] != ElementState::Adhesion) continue;
    // p(x) = ξ(x − x_lead)/L: one element further from the leading edge adds −ξδx/L.
    EXPECT_NEAR(r.f.px[i] - r.f.px[up], -ksi * g.dx / flx, 1e-9 * ksi * g.dx / flx);
    EXPECT_EQ(r.f.sx[i], 0.0);
    ++checked;
  }
  EXPECT_GT(checked, 5);
  // The leading element: u′ = 0, u = −W.
  int lead = g.mx - 1;
  while (!(r.patch.pn[g.index(lead, iy)] > 0.0)) --lead;
  EXPECT_NEAR(r.f.ux[g.index(lead, iy)], -ksi * g.dx, 1e-15);
}

TEST(Fastsim, SaturatesAtLargeCreepage) {
  const double mu = 0.3;
  const CreepRun r = run_pure_creepage(0.1, 1e-4, mu, 31);
  const Grid& g = r.patch.grid;
  EXPECT_NEAR(test::sum(r.f.px, g), -mu * r.patch.fn_discrete(), 1e-12 * r.patch.fn);
  for (std::size_t i = 0; i < g.size(); ++i) {
    if (!(r.patch.pn[i] > 0.0)) {
      EXPECT_EQ(r.f.state[i], ElementState::Exterior);
      EXPECT_EQ(r.f.px[i], 0.0);
      continue;
    }
    // Entering particles are loaded at once (u′ = 0, W large): everything slips.
    EXPECT_EQ(r.f.state[i], ElementState::Slip);
    EXPECT_LT(r.f.sx[i] * r.f.px[i], 0.0);  // friction opposes slip
  }
}

TEST(Fastsim, TransientStartsFromThePreviousDisplacement) {
  // With u′ = the steady solution shifted one element upstream, a transient step reproduces it.
  const CreepRun steady = run_pure_creepage(3e-4, 1e-4, 0.3, 21);
  const Grid& g = steady.patch.grid;
  FastsimInput in;
  in.grid = g;
  in.pn = steady.patch.pn;
  in.mu = 0.3;
  const auto w = test::steady_shift(g, {3e-4, 0.0, 0.0});
  in.wx = w.wx;
  in.wy = w.wy;
  in.flex = {1e-4, 1e-4, 1e-4};
  in.steady = false;
  const auto ux_prev = upstream_field(g, steady.f.ux, 0.0, g.dx);
  const auto uy_prev = upstream_field(g, steady.f.uy, 0.0, g.dx);
  in.ux_prev = ux_prev;
  in.uy_prev = uy_prev;
  const SimplifiedFields t = fastsim(in);
  for (std::size_t i = 0; i < g.size(); ++i) EXPECT_NEAR(t.px[i], steady.f.px[i], 1e-9);
}

TEST(Fastsim, UpstreamFieldInterpolatesAndZeroesOutside) {
  Grid g;
  g.mx = 4;
  g.my = 1;
  const std::vector<double> u{1.0, 2.0, 3.0, 4.0};
  const auto half = upstream_field(g, u, 0.0, 0.5);
  EXPECT_DOUBLE_EQ(half[0], 1.5);
  EXPECT_DOUBLE_EQ(half[2], 3.5);
  EXPECT_DOUBLE_EQ(half[3], 0.0);  // beyond the last centre: outside the potential contact
  const auto back = upstream_field(g, u, std::numbers::pi, 1.0);
  EXPECT_DOUBLE_EQ(back[0], 0.0);
  EXPECT_NEAR(back[1], 1.0, 1e-12);
}

}  // namespace
}  // namespace rollcontact::simplified
