#include "tangential/leading_edge.hpp"

#include <cmath>
#include <numbers>

namespace rollcontact::tangential {

std::vector<LeadingEdgeEntry> leading_edge_entries(const Grid& grid,
                                                   const std::vector<char>& contact, double chi_rad,
                                                   double dq_mm) {
  std::vector<LeadingEdgeEntry> entries;
  if (!(dq_mm > grid.dx * (1.0 + 1e-9))) return entries;
  constexpr double along_row = 0.01;  // [rad], CONTACT's tolerance for χ = 0 or π
  const double c = std::remainder(chi_rad, 2.0 * std::numbers::pi);
  const bool forward = std::abs(c) < along_row;  // χ = 0: leading edge at high ix
  const bool backward = std::abs(std::abs(c) - std::numbers::pi) < along_row;
  if (!forward && !backward) return entries;
  const int step = forward ? 1 : -1;  // from the contact towards the leading edge
  for (int iy = 0; iy < grid.my; ++iy) {
    int lead = -1;  // the leading contact element of the row
    for (int k = 0; k < grid.mx; ++k) {
      const int ix = forward ? grid.mx - 1 - k : k;
      if (contact[grid.index(ix, iy)]) {
        lead = ix;
        break;
      }
    }
    if (lead < 0) continue;
    const int edge = lead + step;
    const int second = lead + 2 * step;
    if (second < 0 || second >= grid.mx) continue;  // fewer than two exterior columns
    for (int ix = lead; ix >= 0 && ix < grid.mx; ix -= step) {
      const double factor = std::abs(edge - ix) * grid.dx / dq_mm;
      if (factor >= 1.0) break;
      if (contact[grid.index(ix, iy)])
        entries.push_back({grid.index(ix, iy), grid.index(edge, iy), factor});
    }
  }
  return entries;
}

}  // namespace rollcontact::tangential
