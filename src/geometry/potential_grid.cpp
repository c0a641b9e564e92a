// Element grid of the potential contact area (spec/physics.md §2): the IPOTCN 1..4 conversions
// to (xl, yl, dx, dy) and the Hertzian layouts derived from the semi-axes and SCALE.

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "geometry/discretisation.hpp"
#include "rollcontact/errors.hpp"

namespace rollcontact::geometry {

namespace {

void require_counts(const PotentialContact& pot) {
  if (pot.mx < 1 || pot.my < 1) {
    throw ProblemError("potential contact needs MX, MY >= 1, got MX=" + std::to_string(pot.mx) +
                       ", MY=" + std::to_string(pot.my));
  }
}

}  // namespace

void validate_grid(const Grid& grid) {
  if (grid.mx < 1 || grid.my < 1) {
    throw ProblemError("potential contact needs MX, MY >= 1, got MX=" + std::to_string(grid.mx) +
                       ", MY=" + std::to_string(grid.my));
  }
  if (static_cast<long long>(grid.mx) * grid.my > max_grid_elements) {
    throw ProblemError("potential contact has MX*MY = " +
                       std::to_string(static_cast<long long>(grid.mx) * grid.my) +
                       " elements, more than the maximum " + std::to_string(max_grid_elements));
  }
  // The negated comparison also rejects NaN.
  if (!(grid.dx >= min_element_size) || !(grid.dy >= min_element_size) || !std::isfinite(grid.dx) ||
      !std::isfinite(grid.dy)) {
    throw ProblemError("element size DX=" + std::to_string(grid.dx) + ", DY=" +
                       std::to_string(grid.dy) + " mm: both must be finite and >= 1e-8 mm");
  }
  // Larger elements: the coefficients (∝ size/G) and the pressures they imply leave the range the
  // products and the single-precision preconditioner represent (DX = 1e30 gave NaN forces).
  if (grid.dx > max_element_size || grid.dy > max_element_size) {
    throw ProblemError(
        fmt::format("element size DX = {} mm, DY = {} mm lies outside [{}, {}] mm: the influence "
                    "coefficients would over- or underflow",
                    grid.dx, grid.dy, min_element_size, max_element_size));
  }
  if (!std::isfinite(grid.xl) || !std::isfinite(grid.yl)) {
    throw ProblemError("potential contact corner XL, YL must be finite");
  }
}

Grid rectangular_grid(const PotentialContact& pot) {
  require_counts(pot);
  const auto& v = pot.values;
  Grid g;
  g.mx = pot.mx;
  g.my = pot.my;
  switch (pot.ipotcn) {
    case 1:  // XL YL DX DY
      g.xl = v[0];
      g.yl = v[1];
      g.dx = v[2];
      g.dy = v[3];
      break;
    case 2:  // XL YL XH YH
      g.xl = v[0];
      g.yl = v[1];
      g.dx = (v[2] - v[0]) / pot.mx;
      g.dy = (v[3] - v[1]) / pot.my;
      break;
    case 3:  // XC1 YC1 DX DY: centre of element (1,1)
      g.dx = v[2];
      g.dy = v[3];
      g.xl = v[0] - 0.5 * g.dx;
      g.yl = v[1] - 0.5 * g.dy;
      break;
    case 4:  // XC1 YC1 XCM YCM: centres of the first and last elements
      if (pot.mx < 2 || pot.my < 2) {
        throw ProblemError("IPOTCN=4 needs MX, MY >= 2 (element size from first/last centres)");
      }
      g.dx = (v[2] - v[0]) / (pot.mx - 1);
      g.dy = (v[3] - v[1]) / (pot.my - 1);
      g.xl = v[0] - 0.5 * g.dx;
      g.yl = v[1] - 0.5 * g.dy;
      break;
    default:
      if (pot.ipotcn < 0) {
        throw ProblemError("IPOTCN=" + std::to_string(pot.ipotcn) +
                           " is Hertzian: its grid follows from the Hertz solution "
                           "(use build_discretisation or hertzian_grid)");
      }
      throw ProblemError("IPOTCN must be 1..4 or -1..-6, got " + std::to_string(pot.ipotcn));
  }
  validate_grid(g);
  return g;
}

Grid hertzian_grid(const PotentialContact& pot, const HertzReport& hertz) {
  require_counts(pot);
  if (!hertz.present) throw ProblemError("hertzian_grid: no Hertz solution given");
  const double s = hertz.scale;
  if (!(s > 0.0) || !std::isfinite(s)) {
    throw ProblemError("Hertzian potential contact needs SCALE > 0, got " + std::to_string(s));
  }
  Grid g;
  g.mx = pot.mx;
  g.my = pot.my;
  g.xl = -s * hertz.aa;
  g.dx = 2.0 * s * hertz.aa / pot.mx;
  if (hertz.two_dimensional) {
    // Rows: n_int of the MY rows cover the strip [−b, b] exactly; MY − n_int is kept even so
    // that the grid stays symmetric about y = 0.
    int n_int = pot.my;
    if (s > 1.0) n_int = static_cast<int>(std::lround(pot.my / s));
    if ((pot.my - n_int) % 2 != 0) ++n_int;
    if (n_int < 1) n_int = pot.my % 2 == 1 ? 1 : 2;  // SCALE so large that no row remains
    g.dy = 2.0 * hertz.bb / n_int;
    g.yl = -0.5 * pot.my * g.dy;
  } else {
    g.yl = -s * hertz.bb;
    g.dy = 2.0 * s * hertz.bb / pot.my;
  }
  validate_grid(g);
  return g;
}

}  // namespace rollcontact::geometry
