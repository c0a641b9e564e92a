#pragma once
// Small helpers over element fields (std::vector<double> with one value per element).

#include <cstddef>
#include <vector>

#include "rollcontact/grid.hpp"

namespace rollcontact::grid {

/// A field of one value per element of `grid`, initialised to `value`.
inline std::vector<double> make_field(const Grid& grid, double value = 0.0) {
  return std::vector<double>(grid.size(), value);
}

/// Σ over elements of field·dx·dy (a force from a traction) [N for N/mm²].
double integrate(const Grid& grid, const std::vector<double>& field);

}  // namespace rollcontact::grid
