// The viscous part of the influence coefficients of standard-linear-solid bodies (M=1); see the
// header for the physics and the choice of quadrature.

#include "elastic/viscous_kernel.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rollcontact::elastic {

namespace {

/// e^{−σ} below 4.3e−18 for σ > 40: the history beyond 40 relaxation lengths is forgotten.
constexpr double kForgottenSigma = 40.0;
/// Panels span at most one relaxation length (e^{−σ} is integrated to ~1e-20 by plain 10-point
/// Gauss–Legendre), those with a graded end a quarter of one (the substitution raises the
/// polynomial degree; test_viscous_kernel checks Σ weights = 1 to 1e-13).
constexpr double kMaxPanelSigma = 1.0, kMaxGradedPanelSigma = 0.25;

struct GaussRule {
  std::vector<double> u, w;  ///< nodes and weights on [0, 1]
};

/// n-point Gauss–Legendre rule on [0, 1] (Newton iteration on P_n from Chebyshev guesses).
GaussRule gauss_legendre(int n) {
  GaussRule r;
  r.u.resize(static_cast<std::size_t>(n));
  r.w.resize(r.u.size());
  for (int i = 0; i < n; ++i) {
    double x = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5));
    double dp = 1.0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = x;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (x * p1 - p0) / (x * x - 1.0);
      const double dx = p1 / dp;
      x -= dx;
      if (std::abs(dx) < 1e-16) break;
    }
    r.u[static_cast<std::size_t>(i)] = 0.5 * (1.0 - x);
    r.w[static_cast<std::size_t>(i)] = 1.0 / ((1.0 - x * x) * dp * dp);  // (2/((1−x²)P′²))/2
  }
  return r;
}

/// A panel [a, b] of the history integral; an end at a kink gets a graded rule (never both).
struct Panel {
  double a, b;
  bool kink_a, kink_b;
};

/// Panels covering [0, s_end]: between the kinks (j + ½)dx − shift_x, then growing
/// geometrically from the last one; no panel longer than `max_width`. A stretch between two
/// kinks split for that keeps the grading at its kink ends only.
std::vector<Panel> history_panels(double dx, int mx, double shift_x, double s_end, double ell) {
  std::vector<Panel> panels;
  double a = 0.0;
  bool kink_a = false;
  auto push = [&](double b, bool kink_b) {
    // Panels with a kink end are at most half an element long (so graded at that end only): one
    // panel per element graded at both ends leaves the middle under-resolved (measured in
    // test_viscous_kernel: 1e-5 of the largest coefficient of a 3-D grid, against 3e-12).
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
  // Smallest j ≥ −mx with a kink beyond 0: (j + ½)dx − shift_x > 0.
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

}  // namespace

std::vector<HistoryNode> history_quadrature(double ell_mm, double dx_mm, int mx, double shift_x_mm,
                                            int nodes) {
  const GaussRule g = gauss_legendre(nodes);
  const std::vector<Panel> panels =
      history_panels(dx_mm, mx, shift_x_mm, kForgottenSigma * ell_mm, ell_mm);
  std::vector<HistoryNode> rule;
  rule.reserve(panels.size() * g.u.size());
  for (const Panel& p : panels) {
    const double h = p.b - p.a;
    for (std::size_t q = 0; q < g.u.size(); ++q) {
      const double u = g.u[q], v = 1.0 - u;
      // s = a + h·φ(u): φ′ vanishes to second order at a graded (kink) end.
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

void add_viscous_parts(Component c, const Grid& grid, const CombinedMaterial& material,
                       double shift_x, double shift_y, Kernel& kernel) {
  for (const ViscousCompliance& v : material.viscous) {
    if (v.weight == 0.0) continue;
    // One body's elastic coefficients with its own ν and coupling, scaled by weight/G.
    CombinedMaterial body;
    body.g = material.g / v.weight;
    body.nu = v.nu;
    body.k = v.k;
    if (v.relaxation_length_mm == 0.0) {
      kernel.add_scaled(make_kernel(c, grid, body, shift_x, shift_y), 1.0);
      continue;
    }
    for (const HistoryNode& node :
         history_quadrature(v.relaxation_length_mm, grid.dx, grid.mx, shift_x))
      kernel.add_scaled(make_continuous_kernel(c, grid, body, shift_x + node.s_mm, shift_y),
                        node.weight);
  }
}

}  // namespace rollcontact::elastic
