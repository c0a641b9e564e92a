// The viscous part of the influence coefficients of standard-linear-solid bodies (M=1,
// spec-additions §B5): the quadrature over the relaxation history, its limits, and the far field
// against the point-load history integral in closed form.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "elastic/kernel_library.hpp"
#include "elastic/material.hpp"
#include "elastic/viscous_kernel.hpp"
#include "unit/elastic/history_quadrature.hpp"

namespace rollcontact::elastic {
namespace {

using reference::history_quadrature;
using reference::HistoryNode;

/// Identical bodies with glassy G = 1143 N/mm², ν = 0.4 (visc_cylindr's PA6) and one merged
/// viscous part of weight FG and relaxation length ℓ.
CombinedMaterial pa6(double fg, double ell_mm) {
  CombinedMaterial m{1143.0, 0.4, 0.0};
  m.viscous[0] = {fg, 0.4, 0.0, ell_mm};
  return m;
}

double max_abs(const Kernel& k) {
  double m = 0.0;
  for (double v : k.data()) m = std::max(m, std::abs(v));
  return m;
}

double max_difference(const Kernel& a, const Kernel& b) {
  double m = 0.0;
  for (std::size_t i = 0; i < a.data().size(); ++i)
    m = std::max(m, std::abs(a.data()[i] - b.data()[i]));
  return m;
}

/// The corner rule's history G_i of every corner for the function f of x (the recursion of
/// make_integrated_kernels).
template <class F>
std::vector<long double> corner_histories(const CornerXRule& rule, F f) {
  const std::size_t n = rule.carry.size();
  std::vector<long double> g(n);
  for (std::size_t i = n; i-- > 0;) {
    long double sum = 0.0L;
    for (std::size_t k = rule.begin[i]; k < rule.begin[i + 1]; ++k)
      sum += rule.weight[k] * f(rule.x_mm[k]);
    g[i] = sum + (i + 1 < n ? rule.carry[i] * g[i + 1] : 0.0L);
  }
  return g;
}

TEST(HistoryCornerRule, IntegratesTheRelaxationWeightExactly) {
  // Every corner's history of f = 1 is ∫₀^∞ e^{−s/ℓ} ds/ℓ = 1, of f(x) = x it is X + ℓ; for ℓ
  // below, near and far above the element size and the grid length (visc_cylindr's 0.16 mm ×
  // 99), with the kink between corners and on one.
  const int mx = 99;
  for (double shift_x : {0.16, -0.08})
    for (double ell : {0.01, 0.16, 9.0, 45.0, 2000.0}) {
      const CornerXRule rule = history_corner_rule(ell, 0.16, mx, shift_x);
      const auto g0 = corner_histories(rule, [](long double) { return 1.0L; });
      const auto g1 = corner_histories(rule, [](long double x) { return x; });
      for (int i = 0; i < 2 * mx; ++i) {
        const double x = (i - mx + 0.5) * 0.16 + shift_x;
        EXPECT_NEAR(static_cast<double>(g0[static_cast<std::size_t>(i)]), 1.0, 1e-13)
            << "ell " << ell << " corner " << i;
        EXPECT_NEAR(static_cast<double>(g1[static_cast<std::size_t>(i)]), x + ell,
                    1e-12 * (std::abs(x) + ell))
            << "ell " << ell << " corner " << i;
      }
    }
}

TEST(HistoryQuadrature, IntegratesTheRelaxationWeightExactly) {
  // The tests' per-node reference likewise.
  // ∫₀^∞ e^{−s/ℓ} ds/ℓ = 1 and ∫₀^∞ s e^{−s/ℓ} ds/ℓ = ℓ, for ℓ below, near and far above the
  // element size and the grid length (0.16 mm × 99 elements: visc_cylindr).
  for (double ell : {0.01, 0.16, 9.0, 45.0, 2000.0}) {
    const auto rule = history_quadrature(ell, 0.16, 99, 0.16);
    double w0 = 0.0, w1 = 0.0;
    for (const HistoryNode& n : rule) {
      EXPECT_GE(n.s_mm, 0.0);
      w0 += n.weight;
      w1 += n.weight * n.s_mm;
    }
    EXPECT_NEAR(w0, 1.0, 1e-13) << "ell " << ell;
    EXPECT_NEAR(w1, ell, 1e-12 * ell) << "ell " << ell;
  }
}

TEST(ViscousKernel, QuadratureConvergedToTheDigitsThatMatter) {
  // The default rule (10 nodes per panel) against 16 nodes per panel, on a 2-D strip (the
  // visc_cylindr grid, shifted by one rolling step as C′) and a 3-D grid: the difference stays
  // below 1e-12 of the largest coefficient for every relaxation length.
  const Grid strip{99, 1, -7.92, -500.0, 0.16, 1000.0};
  const Grid square{15, 15, -7.5, -7.5, 1.0, 1.0};
  const CombinedMaterial body{1143.0, 0.4, 0.0};
  for (const Grid& grid : {strip, square})
    for (double ell : {0.05, 9.0, 2000.0})
      for (Component c : {Component::nn, Component::xx, Component::yy}) {
        const double shift = grid.dx;
        Kernel fine = make_kernel(c, grid, body, shift);
        for (const HistoryNode& n : history_quadrature(ell, grid.dx, grid.mx, shift, 16))
          fine.add_scaled(make_continuous_kernel(c, grid, body, shift + n.s_mm), n.weight);
        const Kernel k = make_kernel(c, grid, pa6(1.0, ell), shift);
        EXPECT_LT(max_difference(k, fine), 1e-11 * max_abs(k))
            << "my " << grid.my << " ell " << ell << " component " << static_cast<int>(c);
      }
}

TEST(ViscousKernel, CornerRuleIsTheKernelOfEveryHistoryNode) {
  // make_kernel's viscous part (history_corner_rule: F integrated along x once per corner row)
  // against a kernel per history node (history_quadrature, 16 nodes per panel, an independent
  // panel layout with a kink at every element edge): 3-D grids and the visc_cylindr strip, rolling
  // shifts that put the corner function's kink inside an element, 1e-9 δx after a corner, and on
  // a centre, a lateral shift, relaxation lengths below, near and far above δx, all components
  // (coupled: dissimilar bodies). Not on or just before a corner (shift −δx/2 + [0, 1e-9] δx):
  // there history_quadrature's first panel starts at or next to the kink ungraded (16 nodes
  // are 3e-7 off 60 there, converging slowly; the corner rule's 10 nodes agree with its 30 to
  // 5e-15, and HistoryCornerRule.IntegratesTheKinkOfTheCornerFunction checks it in closed form).
  const Grid square{12, 9, -6.0, -4.5, 1.0, 0.8};
  const Grid strip{40, 1, -3.2, -500.0, 0.16, 1000.0};
  CombinedMaterial body{1143.0, 0.4, 0.2};
  CombinedMaterial visco = body;
  visco.viscous[0] = {0.6, 0.35, 0.15, 0.0};
  double worst = 0.0;
  for (const Grid& grid : {square, strip})
    for (double shift_x : {0.0, 0.37 * grid.dx, 0.5 * grid.dx - 1e-9 * grid.dx, -2.3 * grid.dx})
      for (double ell : {0.03, 0.7, 9.0, 2000.0})
        for (Component c : {Component::nn, Component::yy, Component::xy, Component::ny}) {
          const double shift_y = grid.my > 1 ? 0.3 * grid.dy : 0.0;
          visco.viscous[0].relaxation_length_mm = ell;
          CombinedMaterial part = body;
          part.g = body.g / 0.6;
          part.nu = 0.35;
          part.k = 0.15;
          Kernel reference = make_kernel(c, grid, body, shift_x, shift_y);
          for (const HistoryNode& n : history_quadrature(ell, grid.dx, grid.mx, shift_x, 16))
            reference.add_scaled(make_continuous_kernel(c, grid, part, shift_x + n.s_mm, shift_y),
                                 n.weight);
          const Kernel k = make_kernel(c, grid, visco, shift_x, shift_y);
          const double scale = max_abs(reference);
          worst = std::max(worst, max_difference(k, reference) / scale);
          EXPECT_LE(max_difference(k, reference), 2e-12 * scale)
              << "my " << grid.my << " shift " << shift_x << " ell " << ell << " component "
              << static_cast<int>(c);
        }
  std::printf("largest difference: %.3g of the largest coefficient\n", worst);
}

/// e^z·E₁(z) for z > 0: the power series of E₁ for z ≤ 1, else the continued fraction
/// e^z·E₁(z) = 1/(z + 1 − 1²/(z + 3 − 2²/(z + 5 − …))) (std::expint loses digits at z ~ 100).
double scaled_e1(double z) {
  if (z <= 1.0) {
    double sum = 0.0, term = 1.0;
    for (int k = 1; k < 40; ++k) {
      term *= -z / k;
      sum += term / k;
    }
    return std::exp(z) * (-0.57721566490153286 - std::log(z) - sum);
  }
  double value = 0.0;  // evaluated from the tail of the fraction upwards
  for (int k = 200; k >= 1; --k) value = -static_cast<double>(k) * k / (z + 2.0 * k + 1.0 + value);
  return 1.0 / (z + 1.0 + value);
}

TEST(HistoryCornerRule, IntegratesTheKinkOfTheCornerFunction) {
  // The rule's recursion for f(t) = t·log|t| (the corner functions' kink at 0) against the
  // closed form for a corner X > 0 (the history runs away from the kink):
  //   ∫₀^∞ e^{−s/ℓ} f(X + s) ds/ℓ = X·log X + ℓ·(1 + log X) + ℓ·e^{X/ℓ}·E₁(X/ℓ).
  // Corners on the kink (shift −δx/2), 1e-9 δx past it (the panels approaching it
  // geometrically) and in between; relaxation lengths below, near and above δx.
  const double dx = 1.0;
  const int mx = 12;
  for (double shift_x : {-0.5, -0.5 + 1e-9, 0.37})
    for (double ell : {0.03, 0.7, 9.0}) {
      const CornerXRule rule = history_corner_rule(ell, dx, mx, shift_x);
      const auto g = corner_histories(
          rule, [](long double t) { return t == 0.0L ? 0.0L : t * std::log(std::abs(t)); });
      for (int i = 0; i < 2 * mx; ++i) {
        const double x = (i - mx + 0.5) * dx + shift_x;
        if (!(x > 0.0)) continue;
        const double exact = x * std::log(x) + ell * (1.0 + std::log(x)) + ell * scaled_e1(x / ell);
        const double scale = std::abs(x * std::log(x)) + ell * (1.0 + std::abs(std::log(x)));
        EXPECT_NEAR(static_cast<double>(g[static_cast<std::size_t>(i)]), exact, 1e-13 * scale)
            << "shift " << shift_x << " ell " << ell << " corner x " << x;
      }
    }
}

TEST(ViscousKernel, QuadratureAgreesWithBruteForce) {
  // An independent rule: uniform panels of 4 µm (40 per element, plain Gauss–Legendre) over
  // 40ℓ, on a 3-element strip of the visc_cylindr elements, for a relaxation length below and
  // one far above the element length. Every offset's history crosses kinks.
  const double dx = 0.16, dy = 1000.0, shift = dx;
  const Grid strip{3, 1, -0.24, -500.0, dx, dy};
  const CombinedMaterial body{1143.0, 0.4, 0.0};
  // 10-point Gauss–Legendre on [−1, 1] (Abramowitz & Stegun 25.4.30), positive half.
  const double x5[5] = {0.1488743389816312, 0.4333953941292472, 0.6794095682990244,
                        0.8650633666889845, 0.9739065285171717};
  const double w5[5] = {0.2955242247147529, 0.2692667193099963, 0.2190863625159820,
                        0.1494513491505806, 0.0666713443086881};
  for (double ell : {0.05, 9.0}) {
    const Kernel k = make_kernel(Component::nn, strip, pa6(1.0, ell), shift);
    const Kernel e = make_kernel(Component::nn, strip, body, shift);
    Kernel brute(3, 1);
    const double h = 0.004;
    for (long p = 0; p < static_cast<long>(40.0 * ell / h + 0.5); ++p)
      for (int q = 0; q < 5; ++q)
        for (double sign : {-1.0, 1.0}) {
          const double s = (static_cast<double>(p) + 0.5 * (1.0 + sign * x5[q])) * h;
          brute.add_scaled(make_continuous_kernel(Component::nn, strip, body, shift + s),
                           0.5 * h * w5[q] * std::exp(-s / ell) / ell);
        }
    for (int dix = -2; dix <= 2; ++dix)
      EXPECT_NEAR(k.at(dix, 0) - e.at(dix, 0), brute.at(dix, 0), 1e-11 * brute.at(dix, 0))
          << dix << " ell " << ell;
  }
}

TEST(ViscousKernel, FarFieldIsThePointLoadHistory) {
  // Far from the loaded element C_nn → (1−ν)/π·δxδy/r, and for an observation point downstream
  // of the load (x > 0, moving away as σ grows) the history integral has a closed form:
  // ∫₀^∞ e^{−σ} dσ/(x + ℓσ) = e^{x/ℓ}·E₁(x/ℓ)/ℓ, E₁(z) = −Ei(−z).
  const Grid grid{81, 1, -40.5, -0.5, 1.0, 1.0};
  const double nu = 0.4, g = 1143.0, fg = 0.7, x = 60.0;
  for (double ell : {3.0, 30.0, 300.0}) {
    CombinedMaterial glassy{g, nu, 0.0};
    const Kernel elastic = make_kernel(Component::nn, grid, glassy);
    const Kernel visco = make_kernel(Component::nn, grid, pa6(fg, ell));
    const double viscous = visco.at(60, 0) - elastic.at(60, 0);
    const double z = x / ell;
    const double expected =
        fg * (1.0 - nu) / std::numbers::pi / g * std::exp(z) * -std::expint(-z) / ell;
    // Point-load approximation: relative error ~ (δx/x)²/8 ≈ 3.5e-5.
    EXPECT_NEAR(viscous, expected, 1e-4 * expected) << "ell " << ell;
  }
}

TEST(ViscousKernel, UpstreamLoadsWeighMoreThanDownstreamOnes) {
  // The observation point remembers the load it passed: a source upstream (dix < 0, the
  // observation point passed over it) acts more than the mirrored one downstream. The elastic
  // kernel is even in dix; the viscoelastic one is not.
  const Grid grid{31, 1, -15.5, -500.0, 1.0, 1000.0};
  const Kernel k = make_kernel(Component::nn, grid, pa6(1.0, 5.0));
  for (int dix = 1; dix < 30; ++dix) EXPECT_GT(k.at(-dix, 0), k.at(dix, 0)) << dix;
  const Kernel e = make_kernel(Component::nn, grid, CombinedMaterial{1143.0, 0.4, 0.0});
  for (int dix = 1; dix < 30; ++dix)
    EXPECT_NEAR(e.at(-dix, 0), e.at(dix, 0), 1e-15 * e.at(0, 0)) << dix;
}

TEST(ViscousKernel, LimitsAreTheRubberyAndGlassyKernels) {
  // τ → 0 (ℓ → 0): the body relaxes at once, C·(1 + FG)/G = C/G_r. ℓ = 0 is that exactly (no
  // quadrature), ℓ = 1e-6·δx within O(ℓ/δx·log) of it. τ → ∞ on a 3-D grid: the viscous part
  // vanishes like (L/ℓ)·log(ℓ/L), L = 15 mm the grid length: 1e-4 relative at ℓ = 1e6 mm.
  const Grid grid{15, 15, -7.5, -7.5, 1.0, 1.0};
  const double fg = 1.0;
  const CombinedMaterial glassy{1143.0, 0.4, 0.0};
  const CombinedMaterial rubbery{1143.0 / (1.0 + fg), 0.4, 0.0};
  for (Component c : {Component::nn, Component::xx, Component::xy}) {
    const Kernel r = make_kernel(c, grid, rubbery);
    EXPECT_LT(max_difference(make_kernel(c, grid, pa6(fg, 0.0)), r), 1e-14 * max_abs(r));
    EXPECT_LT(max_difference(make_kernel(c, grid, pa6(fg, 1e-6)), r), 1e-5 * max_abs(r));
    const Kernel gl = make_kernel(c, grid, glassy);
    EXPECT_LT(max_difference(make_kernel(c, grid, pa6(fg, 1e6)), gl), 1e-4 * max_abs(gl));
  }
}

TEST(ViscousKernel, NoCreepIsTheElasticKernelBitForBit) {
  model::Bodies b;
  b.body1 = b.body2 = {0.4, 1143.0};
  b.viscoelastic = true;
  b.viscous1 = b.viscous2 = {0.0, 0.045};
  const CombinedMaterial m = combine_bodies(b, 1000.0);
  EXPECT_FALSE(m.viscoelastic());
  const Grid grid{9, 1, -4.5, -500.0, 1.0, 1000.0};
  EXPECT_EQ(make_kernel(Component::nn, grid, m, 1.0).data(),
            make_kernel(Component::nn, grid, CombinedMaterial{1143.0, 0.4, 0.0}, 1.0).data());
}

TEST(ViscousKernel, LibraryMakesViscoelasticKernelsDirectly) {
  // Their quadrature follows the grid, so none is cut from a larger grid's kernel.
  KernelLibrary lib;
  const Grid small{9, 9, -4.5, -4.5, 1.0, 1.0}, large{13, 13, -6.5, -6.5, 1.0, 1.0};
  const CombinedMaterial m = pa6(1.0, 4.0);
  (void)lib.kernel(Component::nn, large, m);
  EXPECT_EQ(lib.kernel(Component::nn, small, m).data(),
            make_kernel(Component::nn, small, m).data());
  EXPECT_EQ(lib.computed(), 2u);
}

TEST(CombineBodies, ViscousPartsPerBodyMergedWhenIdentical) {
  model::Bodies b;
  b.body1 = b.body2 = {0.4, 1143.0};
  b.viscoelastic = true;
  b.viscous1 = b.viscous2 = {1.0, 0.009};
  CombinedMaterial m = combine_bodies(b, 1000.0);
  EXPECT_DOUBLE_EQ(m.g, 1143.0);
  EXPECT_DOUBLE_EQ(m.viscous[0].weight, 1.0);  // ½·G·FG/G_a per body, both bodies: FG
  EXPECT_EQ(m.viscous[0].k, 0.0);
  EXPECT_DOUBLE_EQ(m.viscous[0].relaxation_length_mm, 9.0);
  EXPECT_EQ(m.viscous[1].weight, 0.0);
  EXPECT_FALSE(is_coupled(m));

  // Dissimilar bodies: one part each, with its ν and its share ±½(1−2ν) of the coupling.
  b.body2 = {0.25, 3000.0};
  b.viscous2 = {0.5, 0.002};
  m = combine_bodies(b, 1000.0);
  EXPECT_DOUBLE_EQ(m.viscous[0].weight, 0.5 * m.g * 1.0 / 1143.0);
  EXPECT_DOUBLE_EQ(m.viscous[0].k, 0.5 * (1.0 - 0.8));
  EXPECT_DOUBLE_EQ(m.viscous[1].weight, 0.5 * m.g * 0.5 / 3000.0);
  EXPECT_DOUBLE_EQ(m.viscous[1].k, -0.5 * (1.0 - 0.5));
  EXPECT_DOUBLE_EQ(m.viscous[1].relaxation_length_mm, 2.0);
}

TEST(CombineBodies, EffectiveConstantsUseTheRubberyComplianceOfInstantBodies) {
  // visc_cylindr: GV = 571.5 with TC = 0 (both bodies rubbery), 1143 with TC > 0 (glassy).
  model::Bodies b;
  b.body1 = b.body2 = {0.4, 1143.0};
  b.viscoelastic = true;
  b.viscous1 = b.viscous2 = {1.0, 0.0};
  EXPECT_DOUBLE_EQ(effective_viscoelastic_constants(b).g, 571.5);
  b.viscous1 = b.viscous2 = {1.0, 0.009};
  EXPECT_DOUBLE_EQ(effective_viscoelastic_constants(b).g, 1143.0);
  // One rubbery body among dissimilar ones: P§3.1 with c₁ = (1 + FG₁)/G₁.
  b.viscous1 = {1.0, 0.0};
  b.body2 = {0.25, 3000.0};
  const CombinedMaterial e = effective_viscoelastic_constants(b);
  const double c1 = 2.0 / 1143.0, c2 = 1.0 / 3000.0;
  EXPECT_DOUBLE_EQ(e.g, 2.0 / (c1 + c2));
  EXPECT_DOUBLE_EQ(e.nu, 0.5 * e.g * (0.4 * c1 + 0.25 * c2));
  EXPECT_DOUBLE_EQ(e.k, 0.25 * e.g * (0.2 * c1 - 0.5 * c2));
}

}  // namespace
}  // namespace rollcontact::elastic
