#include "post/surface_temperature.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rollcontact::post {

namespace {

/// The elements of one grid row, from upstream (the side material enters from) downstream.
struct Row {
  std::vector<std::size_t> elements;  ///< element indices in flow order
  int lead = -1;                      ///< position of the first contact element (-1: none)
  int trail = -1;                     ///< position of the last contact element
  int in_contact = 0;                 ///< contact elements of the row, n_row
};

Row row_in_flow_order(const Solution& s, int iy, bool towards_plus_x) {
  const Grid& g = s.grid;
  Row r;
  r.elements.reserve(static_cast<std::size_t>(g.mx));
  for (int k = 0; k < g.mx; ++k) {
    // Rolling towards +x, the leading edge is at high ix: material flows from high to low ix.
    const int ix = towards_plus_x ? g.mx - 1 - k : k;
    const std::size_t i = g.index(ix, iy);
    if (s.pn[i] > 0.0) {
      if (r.lead < 0) r.lead = k;
      r.trail = k;
      ++r.in_contact;
    }
    r.elements.push_back(i);
  }
  return r;
}

/// Fraction (2/π)·asin√(t_c/t) of the contact temperature step that a half-space surface keeps
/// at time t after the start of a contact of duration t_c (equal surface temperature during the
/// contact, insulated after it). Here t_c/t = 2a_r/x_d with the row's contact length 2a_r and
/// x_d the distance from the leading edge, so it is 1 up to the trailing edge.
double after_contact_fraction(double contact_length_mm, double distance_from_lead_mm) {
  const double ratio = std::min(1.0, contact_length_mm / distance_from_lead_mm);
  return 2.0 / std::numbers::pi * std::asin(std::sqrt(ratio));
}

double maximum_over_contact(const Solution& s, const std::vector<double>& t) {
  double m = -HUGE_VAL;
  for (std::size_t i = 0; i < t.size(); ++i)
    if (s.pn[i] > 0.0) m = std::max(m, t[i]);
  return m == -HUGE_VAL ? 0.0 : m;
}

}  // namespace

double flash_kernel(double distance_mm, double dx_mm) {
  const double h = 0.5 * dx_mm;
  if (distance_mm < 0.0) return 0.0;
  if (distance_mm == 0.0) return 2.0 * std::sqrt(h);
  return std::sqrt(distance_mm + h) - std::sqrt(std::max(0.0, distance_mm - h));
}

std::vector<double> frictional_heat_flux(const Solution& s, double plastic_heat_fraction,
                                         const std::vector<double>& plastic_flow_mm) {
  const std::size_t n = s.grid.size();
  const EffectiveKinematics& k = s.kinematics;
  std::vector<double> q(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const ElementState state = i < s.state.size() ? s.state[i] : ElementState::Exterior;
    if (state != ElementState::Slip && state != ElementState::Plastic) continue;
    const double slip_mm = std::hypot(s.sx[i], s.sy[i]) * k.dq;
    const double flow_mm = i < plastic_flow_mm.size() ? plastic_flow_mm[i] : 0.0;
    const double speed_mm_s = (slip_mm + plastic_heat_fraction * flow_mm) / k.dt;
    q[i] = speed_mm_s * std::hypot(s.px[i], s.py[i]);
  }
  return q;
}

SurfaceTemperatures surface_temperatures(const model::SurfaceHeat& heat, const Solution& s,
                                         bool rolling, const std::vector<double>& plastic_flow_mm) {
  const Grid& g = s.grid;
  const std::size_t n = g.size();
  const double t01 = heat.body1.bulk_temperature_C, t02 = heat.body2.bulk_temperature_C;
  SurfaceTemperatures out;
  out.temp1.assign(n, t01);
  out.temp2.assign(n, t02);
  if (rolling) {
    // In contact both surfaces take the effusivity-weighted mean; frictional heat splits so
    // that both rise equally: ΔT = 2·Σ/((β₁ + β₂)·√(πV)) (docs/decisions.md).
    const double b1 = heat.body1.effusivity(), b2 = heat.body2.effusivity();
    const double t_contact = (b1 * t01 + b2 * t02) / (b1 + b2);
    const double rise = 2.0 / ((b1 + b2) * std::sqrt(std::numbers::pi * s.kinematics.veloc));
    const std::vector<double> q =
        frictional_heat_flux(s, heat.plastic_heat_fraction, plastic_flow_mm);
    const bool towards_plus_x = std::cos(s.kinematics.chi) >= 0.0;
    for (int iy = 0; iy < g.my; ++iy) {
      const Row row = row_in_flow_order(s, iy, towards_plus_x);
      if (row.lead < 0) continue;  // no contact, no heat: bulk temperatures
      const double contact_length = row.in_contact * g.dx;
      for (int k = row.lead; k < g.mx; ++k) {
        const std::size_t i = row.elements[static_cast<std::size_t>(k)];
        double t1 = t_contact, t2 = t_contact;
        if (s.pn[i] <= 0.0) {
          const double f = after_contact_fraction(contact_length, (k - row.lead + 0.5) * g.dx);
          t1 = t01 + (t_contact - t01) * f;
          t2 = t02 + (t_contact - t02) * f;
        }
        double sum = 0.0;  // the row's heat sources upstream of and at element k
        for (int j = row.lead; j <= std::min(k, row.trail); ++j) {
          const double qj = q[row.elements[static_cast<std::size_t>(j)]];
          if (qj != 0.0) sum += qj * flash_kernel(static_cast<double>(k - j) * g.dx, g.dx);
        }
        out.temp1[i] = t1 + rise * sum;
        out.temp2[i] = t2 + rise * sum;
      }
    }
  }
  out.max1 = maximum_over_contact(s, out.temp1);
  out.max2 = maximum_over_contact(s, out.temp2);
  return out;
}

}  // namespace rollcontact::post
