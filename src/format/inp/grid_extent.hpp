#pragma once
// The element grid an IPOTCN > 0 block describes, for the readers' consistency checks (element
// size limits, sequences that keep the element size and an integer offset). The solver builds
// the same grid with geometry::rectangular_grid, which rejects what the readers report first.

#include "format/inp/case_record.hpp"

namespace rollcontact::format {

/// Lower-left corner and element size [mm]; known = false for Hertzian IPOTCN < 0, whose grid
/// follows from the Hertz solution at solve time.
struct GridExtent {
  bool known = false;
  double xl = 0.0, yl = 0.0, dx = 0.0, dy = 0.0;
};

inline GridExtent grid_extent(const PotentialContact& pc) {
  const auto& v = pc.values;
  const double mx = pc.mx;
  const double my = pc.my;
  switch (pc.ipotcn) {
    case 1:
      return {true, v[0], v[1], v[2], v[3]};
    case 2:
      return {true, v[0], v[1], (v[2] - v[0]) / mx, (v[3] - v[1]) / my};
    case 3:
      return {true, v[0] - 0.5 * v[2], v[1] - 0.5 * v[3], v[2], v[3]};
    case 4: {
      const double dx = pc.mx > 1 ? (v[2] - v[0]) / (mx - 1.0) : 0.0;
      const double dy = pc.my > 1 ? (v[3] - v[1]) / (my - 1.0) : 0.0;
      return {true, v[0] - 0.5 * dx, v[1] - 0.5 * dy, dx, dy};
    }
    default:
      return {};
  }
}

}  // namespace rollcontact::format
