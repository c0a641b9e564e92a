// The viscous part of the influence coefficients of standard-linear-solid bodies (M=1); see the
// header for the physics and the choice of quadrature.

#include "elastic/viscous_kernel.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/gauss_legendre.hpp"

namespace rollcontact::elastic {

namespace {

/// e^{−σ} below 4.3e−18 for σ > 40: the history beyond 40 relaxation lengths is forgotten.
constexpr double kForgottenSigma = 40.0;
/// Panels span at most one relaxation length (e^{−σ} is integrated to ~1e-20 by plain 10-point
/// Gauss–Legendre), those with a graded end a quarter of one (the substitution raises the
/// polynomial degree; test_viscous_kernel checks the weights' moments to 1e-13).
constexpr double kMaxPanelSigma = 1.0, kMaxGradedPanelSigma = 0.25;
/// history_corner_rule's panels at the kink: halved this often before the innermost is graded.
constexpr int kGradedLevels = 6;

using core::gauss_legendre;
using core::GaussRule;

using Real = long double;

/// Adds to a CornerXRule the nodes of ∫_a^b e^{−(t−o)/ℓ}/ℓ·F(t) dt for a corner function F of
/// x whose one kink (x·log|x|, x·atan(y/x)) lies at x = 0.
class StretchRules {
 public:
  /// `g`: the rule of panels near the kink; panels far from it take `mid` and `far`, fewer
  /// nodes for the same accuracy (panel()).
  StretchRules(const GaussRule& g, const GaussRule& mid, const GaussRule& far, Real ell, Real dx,
               CornerXRule& rule)
      : g_(g), mid_(mid), far_(far), ell_(ell), dx_(dx), rule_(rule) {}

  /// The integral over [a, b] (from origin o ≤ a of the weight). A kink inside is a panel end,
  /// graded on both sides; a kink closer to the stretch than its length, at distance d from its
  /// nearer end, is approached by panels as long as their distance from it (d, 2d, 4d, …), so
  /// that no panel has a singularity closer than its own length.
  void integral(Real a, Real b, Real o) {
    if (!(b > a)) return;
    const Real length = b - a;
    if (a < 0.0L && b > 0.0L) {
      panels(a, 0.0L, o, false, true);
      panels(0.0L, b, o, true, false);
    } else if (b <= 0.0L && -b < length) {
      if (b == 0.0L) return panels(a, b, o, false, true);
      for (Real d = -b, end = b; end > a; d *= 2.0L) {
        const Real start = std::max(a, end - d);
        panels(start, end, o, false, false);
        end = start;
      }
    } else if (a >= 0.0L && a < length) {
      if (a == 0.0L) return panels(a, b, o, true, false);
      for (Real d = a, start = a; start < b; d *= 2.0L) {
        const Real end = std::min(b, start + d);
        panels(start, end, o, false, false);
        start = end;
      }
    } else {
      panels(a, b, o, false, false);
    }
  }

 private:
  /// [a, b] in panels of at most ℓ, or min(ℓ/4, δx/2) where an end is at the kink. The panel at the
  /// kink is refined towards it geometrically (halving kGradedLevels times) and only the last,
  /// innermost one is graded, t = a + h·u³ (or its mirror): a cubic substitution on a wider panel
  /// would bring the corner function's complex singularity at x = ±i·|y| of a row near y = 0 close
  /// to the panel (10 nodes: 6e-9 of the largest coefficient of C_xy at |y| = 0.16 δx, 5e-15
  /// refined).
  void panels(Real a, Real b, Real o, bool kink_a, bool kink_b) {
    const Real max_width = kink_a || kink_b ? std::min(kMaxGradedPanelSigma * ell_, 0.5L * dx_)
                                            : kMaxPanelSigma * ell_;
    const int pieces = std::max(1, static_cast<int>(std::ceil((b - a) / max_width - 1e-12L)));
    for (int k = 0; k < pieces; ++k) {
      const Real pa = a + (b - a) * k / pieces;
      const Real pb = k + 1 == pieces ? b : a + (b - a) * (k + 1) / pieces;
      if (k == 0 && kink_a) {
        Real inner = pb;
        for (int level = 0; level < kGradedLevels; ++level, inner = pa + 0.5L * (inner - pa))
          panel(pa + 0.5L * (inner - pa), inner, o, false, false);
        panel(pa, inner, o, true, false);
      } else if (k + 1 == pieces && kink_b) {
        Real inner = pa;
        for (int level = 0; level < kGradedLevels; ++level, inner = pb - 0.5L * (pb - inner))
          panel(inner, pb - 0.5L * (pb - inner), o, false, false);
        panel(inner, pb, o, false, true);
      } else {
        panel(pa, pb, o, false, false);
      }
    }
  }

  void panel(Real a, Real b, Real o, bool kink_a, bool kink_b) {
    const Real h = b - a;
    // Gauss–Legendre's error on a panel whose nearest singularity lies d away falls like ρ^{−2n},
    // ρ = a′ + √(a′² − 1), a′ = 1 + 2d/h, and for the weight e^{−t/ℓ} like (h/ℓ)^{2n}/(2n)!·…:
    // at d ≥ 4h 6 nodes (ρ^{−12} < 1e-15; 2e-16 for e^{−t/ℓ} on h = ℓ), at d ≥ 20h and h ≤ ℓ/4
    // 4 nodes (ρ^{−8} < 1e-15, 1e-14 for the weight) do what 10 do next to the kink.
    const Real distance = a >= 0.0L ? a : b <= 0.0L ? -b : 0.0L;
    const bool far = distance >= 20.0L * h && h <= 0.25L * ell_;
    const GaussRule& g = kink_a || kink_b ? g_ : far ? far_ : distance >= 4.0L * h ? mid_ : g_;
    for (std::size_t q = 0; q < g.u.size(); ++q) {
      const Real u = g.u[q], v = 1.0L - u;
      Real phi = u, dphi = 1.0L;
      if (kink_a) {
        phi = u * u * u;
        dphi = 3.0L * u * u;
      } else if (kink_b) {
        phi = 1.0L - v * v * v;
        dphi = 3.0L * v * v;
      }
      const Real t = a + h * phi;
      rule_.x_mm.push_back(t);
      rule_.weight.push_back(Real(g.w[q]) * h * dphi * std::exp(-(t - o) / ell_) / ell_);
    }
  }

  const GaussRule &g_, &mid_, &far_;
  const Real ell_, dx_;
  CornerXRule& rule_;
};

}  // namespace

CornerXRule history_corner_rule(double ell_mm, double dx_mm, int mx, double shift_x_mm, int nodes) {
  // Fewer nodes far from the kink only at the default order: more nodes (the tests'
  // convergence checks) take them everywhere.
  const GaussRule g = gauss_legendre(nodes);
  const GaussRule mid = nodes == 10 ? gauss_legendre(6) : g,
                  far = nodes == 10 ? gauss_legendre(4) : g;
  CornerXRule rule;
  const Real ell = ell_mm, dx = dx_mm, span = kForgottenSigma * ell;
  StretchRules stretch(g, mid, far, ell, dx, rule);
  // The corner abscissae of corner_sum_kernels, bit for bit.
  const auto corner_x = [&](int i) { return (Real(i - mx) + 0.5L) * dx + Real(shift_x_mm); };
  const int n = 2 * mx;
  for (int i = 0; i < n; ++i) {
    rule.begin.push_back(rule.x_mm.size());
    const Real a = corner_x(i);
    if (i + 1 < n) {
      // G_i = ∫ over [X_i, X_{i+1}] + e^{−δx/ℓ}·G_{i+1}; beyond 40ℓ the history is forgotten.
      const Real b = corner_x(i + 1);
      stretch.integral(a, std::min(b, a + span), a);
      rule.carry.push_back(b - a < span ? std::exp(-(b - a) / ell) : 0.0L);
    } else {
      // The last corner's whole history: panels growing with the distance from it (or from the
      // kink, should that lie ahead), at most ℓ long.
      const Real origin = std::max(0.0L, a);
      for (Real t = a; t < a + span;) {
        const Real next = std::min(a + span, t + std::max(dx, t - origin));
        stretch.integral(t, next, a);
        t = next;
      }
      rule.carry.push_back(0.0L);
    }
  }
  rule.begin.push_back(rule.x_mm.size());
  return rule;
}

void add_viscous_parts(const std::vector<Component>& cs, const Grid& grid,
                       const CombinedMaterial& material, double shift_x, double shift_y,
                       std::vector<Kernel>& kernels) {
  for (const ViscousCompliance& v : material.viscous) {
    if (v.weight == 0.0) continue;
    // One body's elastic coefficients with its own ν and coupling, scaled by weight/G.
    CombinedMaterial body;
    body.g = material.g / v.weight;
    body.nu = v.nu;
    body.k = v.k;
    if (v.relaxation_length_mm == 0.0) {
      for (std::size_t q = 0; q < cs.size(); ++q)
        kernels[q].add_scaled(make_kernel(cs[q], grid, body, shift_x, shift_y), 1.0);
      continue;
    }
    const std::vector<Kernel> parts = make_integrated_kernels(
        cs, grid, body, shift_y,
        history_corner_rule(v.relaxation_length_mm, grid.dx, grid.mx, shift_x));
    for (std::size_t q = 0; q < cs.size(); ++q) kernels[q].add_scaled(parts[q], 1.0);
  }
}

}  // namespace rollcontact::elastic
