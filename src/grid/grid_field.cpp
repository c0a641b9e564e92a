#include "grid/grid_field.hpp"

#include <numeric>

namespace rollcontact::grid {

double integrate(const Grid& grid, const std::vector<double>& field) {
  return std::accumulate(field.begin(), field.end(), 0.0) * grid.element_area();
}

}  // namespace rollcontact::grid
