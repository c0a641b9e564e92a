#include "tangential/element_problem.hpp"

#include <cmath>

namespace rollcontact::tangential {

ElementSolution solve_element(double cx, double cy, const double d[4], double g) {
  ElementSolution e;
  const double dxx = d[0], dxy = d[1], dyx = d[2], dyy = d[3];
  if (g <= 0.0) {
    e.sx = cx;
    e.sy = cy;
    e.slip = true;
    return e;
  }
  // Adhesion: D p = −c.
  const double det = dxx * dyy - dxy * dyx;
  const double ax = (-dyy * cx + dxy * cy) / det;
  const double ay = (dyx * cx - dxx * cy) / det;
  if (ax * ax + ay * ay <= g * g) {
    e.px = ax;
    e.py = ay;
    return e;  // S = 0
  }
  // Slip: p = g (cos θ, sin θ) antiparallel to S = c + D p, i.e. f(θ) = p × S = 0 with p·S < 0.
  // For an isotropic D the answer is θ = angle(−c); Newton corrects for the anisotropy.
  double theta = std::atan2(-cy, -cx);
  for (int it = 0; it < 50; ++it) {
    const double co = std::cos(theta), si = std::sin(theta);
    const double f =
        co * cy - si * cx + g * (dyx * co * co + (dyy - dxx) * co * si - dxy * si * si);
    const double df =
        -si * cy - co * cx +
        g * (-2.0 * dyx * co * si + (dyy - dxx) * (co * co - si * si) - 2.0 * dxy * si * co);
    if (df == 0.0) break;
    const double step = f / df;
    theta -= step;
    if (std::abs(step) < 1e-15) break;
  }
  e.px = g * std::cos(theta);
  e.py = g * std::sin(theta);
  e.sx = cx + dxx * e.px + dxy * e.py;
  e.sy = cy + dyx * e.px + dyy * e.py;
  e.slip = true;
  return e;
}

}  // namespace rollcontact::tangential
