#pragma once
// The rectangular element grid of the potential contact area.

#include <cstddef>

namespace rollcontact {

/// mx × my rectangular elements of size dx × dy [mm]; (xl, yl) is the lower-left corner of the
/// potential contact area [mm]. Element (ix, iy), 0-based, has linear index ix + mx*iy and its
/// centre at (xl + (ix + 1/2) dx, yl + (iy + 1/2) dy). Fields are piecewise constant per element.
struct Grid {
  int mx = 1;
  int my = 1;
  double xl = 0.0;  ///< lower-left corner x [mm]
  double yl = 0.0;  ///< lower-left corner y [mm]
  double dx = 1.0;  ///< element size in x (rolling direction) [mm]
  double dy = 1.0;  ///< element size in y (lateral) [mm]

  std::size_t size() const noexcept {
    return static_cast<std::size_t>(mx) * static_cast<std::size_t>(my);
  }
  std::size_t index(int ix, int iy) const noexcept {
    return static_cast<std::size_t>(ix) +
           static_cast<std::size_t>(mx) * static_cast<std::size_t>(iy);
  }
  double x_centre(int ix) const noexcept { return xl + (ix + 0.5) * dx; }
  double y_centre(int iy) const noexcept { return yl + (iy + 0.5) * dy; }
  double element_area() const noexcept { return dx * dy; }  ///< [mm²]
};

}  // namespace rollcontact
