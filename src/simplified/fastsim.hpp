#pragma once
// Modified Fastsim (spec/physics.md §11.3): Kalker's simplified theory, in which the surface
// displacement of each element depends on its own traction only, u = L·p/k, integrated along
// the rolling direction with a traction bound μ·p_n per element.

#include <span>
#include <vector>

#include "rollcontact/grid.hpp"
#include "rollcontact/solution.hpp"
#include "simplified/flexibility.hpp"

namespace rollcontact::simplified {

/// Tractions, displacements and slip of a simplified-theory solution; grid.size() entries each.
struct SimplifiedFields {
  std::vector<double> px, py;  ///< tangential tractions on body 1 [N/mm²]
  std::vector<double> ux, uy;  ///< displacement differences u = L·p [mm]
  std::vector<double> sx, sy;  ///< slip per step S = u − u′ + W [mm]
  std::vector<ElementState> state;
};

struct FastsimInput {
  Grid grid;
  std::span<const double> pn;      ///< normal pressure [N/mm²]; contact where pn > 0
  double mu = 0.3;                 ///< friction coefficient [-]
  std::span<const double> wx, wy;  ///< rigid shift per step W [mm], spin parts already scaled
  Flexibilities flex;              ///< effective flexibilities L/k [mm³/N] (l3 unused here)
  bool steady = true;              ///< T=3: u′ from the upstream element; T=2: from ux_prev
  double chi = 0.0;  ///< rolling direction [rad]; steady: cos χ > 0 sweeps from ix = MX−1 down
  /// Transient rolling: displacement of the same particles at the previous time [mm] (empty: 0).
  std::span<const double> ux_prev, uy_prev;
};

/// One Fastsim pass. Per contact element: adhesion trial u = u′ − W, p = u/L; if |p| > μp_n the
/// element slips with p scaled onto the bound and u = L·p. Exterior elements get zeros.
SimplifiedFields fastsim(const FastsimInput& in);

/// Displacement of the same particles one step earlier for transient rolling: `u` (previous
/// case, same grid) evaluated at (x + δq cos χ, y + δq sin χ) by bilinear interpolation of the
/// element-centre values, 0 where the point lies outside the grid. δq [mm].
std::vector<double> upstream_field(const Grid& grid, std::span<const double> u, double chi,
                                   double dq);

}  // namespace rollcontact::simplified
