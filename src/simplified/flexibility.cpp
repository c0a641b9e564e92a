// Flexibilities of the simplified theory (spec/physics.md §11.2).

#include "simplified/flexibility.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rollcontact::simplified {

namespace {
constexpr double pi = std::numbers::pi;
}

Ellipse equivalent_ellipse(const Grid& grid, std::span<const double> pn) {
  int n = 0;
  int ix_lo = grid.mx, ix_hi = -1, iy_lo = grid.my, iy_hi = -1;
  for (int iy = 0; iy < grid.my; ++iy) {
    for (int ix = 0; ix < grid.mx; ++ix) {
      if (!(pn[grid.index(ix, iy)] > 0.0)) continue;
      ++n;
      ix_lo = std::min(ix_lo, ix);
      ix_hi = std::max(ix_hi, ix);
      iy_lo = std::min(iy_lo, iy);
      iy_hi = std::max(iy_hi, iy);
    }
  }
  if (n == 0) return {};
  const double area = n * grid.element_area();
  const double length = (ix_hi - ix_lo + 1) * grid.dx;
  const double width = (iy_hi - iy_lo + 1) * grid.dy;
  const double r = std::sqrt(area / pi);
  return {r * std::sqrt(length / width), r * std::sqrt(width / length)};
}

Flexibilities kalker_flexibilities(const Ellipse& e, const KalkerCoefficients& c, double g) {
  return {8.0 * e.a / (3.0 * c.c11 * g), 8.0 * e.a / (3.0 * c.c22 * g),
          pi * e.a * std::sqrt(e.a / e.b) / (4.0 * c.c23 * g)};
}

Flexibilities blend_flexibilities(const Flexibilities& l, const Ellipse& e,
                                  const KalkerCoefficients& c, double g, double mu, double fn,
                                  const Creepages& cr) {
  // L_c gives the right total force in full sliding, where each creepage contributes in
  // proportion to its square; the three separate values fit the linear (small creepage) regime.
  const double c3phi = 3.0 * pi * e.a / 32.0 * cr.phi;
  const double num = cr.ksi * cr.ksi + cr.eta * cr.eta + c3phi * c3phi;
  const double den =
      std::max(1e-14, cr.ksi * cr.ksi / l.l1 + cr.eta * cr.eta / l.l2 + c3phi * c3phi / l.l3);
  const double lc = num / den;
  const double cc = e.a * e.b;  // c² = ab
  const double ksi_c = mu * fn / (cc * g * c.c11);
  const double eta_c = mu * fn / (cc * g * c.c22);
  const double f = std::max(
      1e-10, std::sqrt((cr.ksi * cr.ksi + cr.eta * cr.eta) / (ksi_c * ksi_c + eta_c * eta_c)));
  const double w = std::clamp(f / 3.0, 0.0, 1.0);
  return {(1.0 - w) * l.l1 + w * lc, (1.0 - w) * l.l2 + w * lc, (1.0 - w) * l.l3 + w * lc};
}

double slope_reduction_factor(const SlopeReduction& s, const Ellipse& e, double c11, double g,
                              double mu, double fn, const Creepages& cr) {
  double nu_phi = cr.eta + cr.phi * e.a;
  if (std::abs(nu_phi) < std::abs(cr.eta)) nu_phi = cr.eta;
  const double nu_tot = std::sqrt(cr.ksi * cr.ksi + nu_phi * nu_phi);
  const double eps =
      mu * fn > 0.0 ? g * pi * e.a * e.b * s.k0 * c11 * nu_tot / (4.0 * mu * fn) : 0.0;
  return s.k0 * (s.alpha + (1.0 - s.alpha) / (1.0 + s.beta * eps));
}

}  // namespace rollcontact::simplified
