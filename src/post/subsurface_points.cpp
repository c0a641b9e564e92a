#include "post/subsurface_points.hpp"

namespace rollcontact::post {

namespace {

/// Centres of the 1-based indices in `ids` that lie in 1..n, in the given (ascending) order.
template <typename Centre>
std::vector<double> centres(const std::vector<int>& ids, int n, Centre centre) {
  std::vector<double> out;
  for (int i : ids) {
    if (i >= 1 && i <= n) out.push_back(centre(i - 1));
  }
  return out;
}

std::vector<int> range(int lo, int step, int hi) {
  std::vector<int> ids;
  if (step < 1) step = 1;
  for (int i = lo; i <= hi; i += step) ids.push_back(i);
  return ids;
}

}  // namespace

PointLists block_points(const model::SubsurfaceBlock& block, const Grid& grid) {
  PointLists p;
  auto xc = [&](int ix) { return grid.x_centre(ix); };
  auto yc = [&](int iy) { return grid.y_centre(iy); };
  switch (block.isubs) {
    case 1:
    case 5:
      p.x = centres(range(1, 1, grid.mx), grid.mx, xc);
      p.y = centres(range(1, 1, grid.my), grid.my, yc);
      break;
    case 2:
    case 6:
      p.x = centres(range(block.ixl, block.ixinc, block.ixh), grid.mx, xc);
      p.y = centres(range(block.iyl, block.iyinc, block.iyh), grid.my, yc);
      break;
    case 3:
    case 7:
      p.x = centres(block.ix, grid.mx, xc);
      p.y = centres(block.iy, grid.my, yc);
      break;
    default:  // 9
      p.x = block.x;
      p.y = block.y;
      break;
  }
  p.z = block.z;
  return p;
}

}  // namespace rollcontact::post
