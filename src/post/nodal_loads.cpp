#include "post/nodal_loads.hpp"

#include <algorithm>

namespace rollcontact::post {

double nodal_weight(const Grid& grid, const std::vector<double>& p, int i, int j) {
  auto at = [&](int ix, int iy) {
    if (ix < 0 || iy < 0 || ix >= grid.mx || iy >= grid.my || p.empty()) return 0.0;
    return p[grid.index(ix, iy)];
  };
  return at(i, j) - at(i, j - 1) - at(i - 1, j) + at(i - 1, j - 1);
}

NodalLoads::NodalLoads(const Grid& grid, const std::vector<double>& px,
                       const std::vector<double>& py, const std::vector<double>& pn)
    : min_depth_(kMinimumRelativeDepth * std::max(grid.dx, grid.dy)) {
  for (int j = 0; j <= grid.my; ++j) {
    for (int i = 0; i <= grid.mx; ++i) {
      const Traction w{nodal_weight(grid, px, i, j), nodal_weight(grid, py, i, j),
                       nodal_weight(grid, pn, i, j)};
      if (w.px == 0.0 && w.py == 0.0 && w.pn == 0.0) continue;
      nodes_.push_back({grid.xl + i * grid.dx, grid.yl + j * grid.dy, w});
    }
  }
}

CornerSums NodalLoads::sums(double x, double y, double z) const {
  CornerSums s;
  for (const Node& n : nodes_) add_corner(s, x - n.x, y - n.y, z, n.w);
  return s;
}

}  // namespace rollcontact::post
