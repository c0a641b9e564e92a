#pragma once
// Piecewise-constant surface tractions on the element grid, rewritten as weights on the grid
// nodes so that a field point costs one corner evaluation per loaded node instead of four per
// loaded element.

#include <vector>

#include "post/half_space_response.hpp"
#include "rollcontact/grid.hpp"

namespace rollcontact::post {

/// Weight of grid node (i, j), 0 ≤ i ≤ mx, 0 ≤ j ≤ my, for element values p (ix + mx·iy):
/// p(i, j) − p(i, j−1) − p(i−1, j) + p(i−1, j−1), elements outside the grid taken as 0.
double nodal_weight(const Grid& grid, const std::vector<double>& p, int i, int j);

/// Σ_e p_e ⟦F⟧_e = Σ_nodes w_node F(x − x_node, y − y_node): node (i, j) gets
/// w = p(i, j) − p(i, j−1) − p(i−1, j) + p(i−1, j−1) of its four adjacent elements (zero outside
/// the grid). Nodes with all weights zero are dropped (exterior area).
class NodalLoads {
 public:
  /// px, py, pn: tractions on the half-space per element [N/mm²], element order ix + mx·iy.
  NodalLoads(const Grid& grid, const std::vector<double>& px, const std::vector<double>& py,
             const std::vector<double>& pn);

  /// Corner sums at (x, y) and depth z > 0 [mm].
  CornerSums sums(double x, double y, double z) const;

  /// Number of loaded nodes (the direct sum's cost per point).
  std::size_t node_count() const noexcept { return nodes_.size(); }

  /// Depth used for a requested depth z ≥ 0 (surface points slightly below the surface).
  double effective_depth(double z) const noexcept { return z > min_depth_ ? z : min_depth_; }

 private:
  struct Node {
    double x, y;
    Traction w;
  };
  std::vector<Node> nodes_;
  double min_depth_ = 0.0;
};

}  // namespace rollcontact::post
