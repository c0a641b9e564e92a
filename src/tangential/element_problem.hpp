#pragma once
// The local problem of one element with all others fixed (spec/physics.md §9.3):
// S = c + D·p with the 2×2 diagonal block D of A; find p with Coulomb's law and |p| ≤ g.

namespace rollcontact::tangential {

struct ElementSolution {
  double px = 0.0, py = 0.0;  ///< traction [N/mm²]
  double sx = 0.0, sy = 0.0;  ///< slip S = c + D p
  bool slip = false;
};

/// c: slip at p = 0 of this element (others fixed); d = {D_xx, D_xy, D_yx, D_yy}; g ≥ 0 bound.
/// Adhesion when the solution of S = 0 lies within the bound, otherwise slip with p = −g S/|S|
/// (Newton on the angle of p).
ElementSolution solve_element(double cx, double cy, const double d[4], double g);

}  // namespace rollcontact::tangential
