#pragma once
// Coordinates of a block of subsurface points (spec/inp-format.md §6).

#include <vector>

#include "rollcontact/grid.hpp"
#include "rollcontact/model/geometry.hpp"

namespace rollcontact::post {

/// The tensor-product coordinate lists of one block [mm], each ascending.
struct PointLists {
  std::vector<double> x, y, z;
};

/// ISUBS 1/5: all element centres; 2/6: columns ixl:ixinc:ixh and rows iyl:iyinc:iyh (1-based,
/// indices outside the grid ignored); 3/7: the listed columns and rows (outside ignored);
/// 9: the given x and y. z: the block's depths (ZL + k·DZ or the list).
PointLists block_points(const model::SubsurfaceBlock& block, const Grid& grid);

}  // namespace rollcontact::post
