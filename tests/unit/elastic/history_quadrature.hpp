#pragma once
// The per-node reference of the viscous kernels' history integral (tests only): the viscous part
// of a kernel as Σ weight·(continuous kernel at the observation point moved upstream by s), one
// whole kernel per history node. Production integrates along the corner lattice instead
// (history_corner_rule); this independent panel layout is what the tests compare it with.

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/gauss_legendre.hpp"

namespace rollcontact::elastic::reference {

/// One node of a rule ∫₀^∞ e^{−s/ℓ} f(s) ds/ℓ ≈ Σ weight·f(s_mm).
struct HistoryNode {
  double s_mm;    ///< upstream distance of the observation point [mm]
  double weight;  ///< includes e^{−s/ℓ}/ℓ and the panel's Jacobian [-]
};

/// A panel [a, b] of the history integral; an end at a kink gets a graded rule (never both).
struct Panel {
  double a, b;
  bool kink_a, kink_b;
};

/// The history beyond 40 relaxation lengths is forgotten (e^{−40} < 5e−18); panels span at
/// most ℓ, those with a kink end min(ℓ/4, δx/2) — production's limits.
inline constexpr double kForgottenSigma = 40.0, kMaxPanelSigma = 1.0, kMaxGradedPanelSigma = 0.25;

/// Panels covering [0, s_end]: split at the kinks (j + ½)dx − shift_x, where a corner abscissa
/// of some offset passes zero, then growing geometrically from the last one.
inline std::vector<Panel> history_panels(double dx, int mx, double shift_x, double s_end,
                                         double ell) {
  std::vector<Panel> panels;
  double a = 0.0;
  bool kink_a = false;
  auto push = [&](double b, bool kink_b) {
    // Half an element at most next to a kink, so that each panel is graded at one end only.
    const double max_width =
        kink_a || kink_b ? std::min(kMaxGradedPanelSigma * ell, 0.5 * dx) : kMaxPanelSigma * ell;
    const int pieces = std::max(kink_a && kink_b ? 2 : 1,
                                static_cast<int>(std::ceil((b - a) / max_width - 1e-12)));
    for (int k = 0; k < pieces; ++k)
      panels.push_back({a + (b - a) * k / pieces,
                        k + 1 == pieces ? b : a + (b - a) * (k + 1) / pieces, k == 0 && kink_a,
                        k + 1 == pieces && kink_b});
    a = b;
    kink_a = kink_b;
  };
  const double last_kink = (mx - 0.5) * dx - shift_x;
  for (int j = std::max(-mx, static_cast<int>(std::floor(shift_x / dx - 0.5)) + 1); j < mx; ++j) {
    const double s = (j + 0.5) * dx - shift_x;
    if (s <= a + 1e-12 * dx) continue;
    if (s >= s_end) break;
    push(s, true);
  }
  const double origin = std::max(0.0, last_kink);
  while (a < s_end) push(std::min(s_end, a + std::max(dx, a - origin)), false);
  return panels;
}

/// Nodes for the relaxation integral of a kernel on mx elements of length dx [mm] whose
/// observation points are already moved by shift_x [mm], relaxation length ell [mm] > 0:
/// `nodes` Gauss–Legendre points per panel, after s = a + (b−a)·u³ (or its mirror) at a kink
/// end (the Jacobian 3u² turns t·log t into u⁵·log u). Inaccurate where a corner sits on a kink
/// (shift −δx/2): there the first panel starts on the kink ungraded.
inline std::vector<HistoryNode> history_quadrature(double ell_mm, double dx_mm, int mx,
                                                   double shift_x_mm, int nodes = 10) {
  const core::GaussRule g = core::gauss_legendre(nodes);
  std::vector<HistoryNode> rule;
  for (const Panel& p : history_panels(dx_mm, mx, shift_x_mm, kForgottenSigma * ell_mm, ell_mm)) {
    const double h = p.b - p.a;
    for (std::size_t q = 0; q < g.u.size(); ++q) {
      const double u = g.u[q], v = 1.0 - u;
      double phi = u, dphi = 1.0;
      if (p.kink_a) {
        phi = u * u * u;
        dphi = 3.0 * u * u;
      } else if (p.kink_b) {
        phi = 1.0 - v * v * v;
        dphi = 3.0 * v * v;
      }
      const double s = p.a + h * phi;
      rule.push_back({s, g.w[q] * h * dphi * std::exp(-s / ell_mm) / ell_mm});
    }
  }
  return rule;
}

}  // namespace rollcontact::elastic::reference
