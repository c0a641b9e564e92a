#pragma once
// Approximate normal pressures of non-Hertzian contacts with a prescribed approach
// (spec/physics.md §7.3): KPEC, Kik–Piotrowski's virtual penetration with Vollebregt's ellipse
// correction (B=5), and the modified ANALYN (B=6). Both read the total gap
// h_tot = h − PEN (≤ 0 where the bodies interpenetrate) and need no iteration: one Hertz solution
// of equivalent curvatures sets the shape, one influence sum the level.

#include <vector>

#include "elastic/influence.hpp"
#include "rollcontact/grid.hpp"
#include "rollcontact/solution.hpp"

namespace rollcontact::simplified {

struct ApproximateNormal {
  std::vector<double> pn;  ///< pressure per element [N/mm²]
  double pen_total = 0.0;  ///< −min h_tot [mm] (0: no interpenetration, pn all zero)
  HertzReport hertz;       ///< Hertz solution of the equivalent curvatures at pen_total
  /// KPEC: rows that interpenetrate where the ellipse correction asks for more than the full
  /// interpenetration (ε(y) > 1: the row's virtual length reaches beyond it): a second lobe of
  /// the gap outside the equivalent ellipse. CONTACT's pressures still differ there
  /// (docs/decisions.md, "KPEC"); 0 for ANALYN.
  int rows_beyond_interpenetration = 0;
};

/// KPEC: equivalent curvatures at the deepest point, a row-wise virtual-penetration threshold
/// that reproduces the Hertz ellipse, semi-elliptic pressures per row scaled so that the normal
/// displacement at the deepest point equals pen_total. `h_total` has grid.size() values [mm]
/// (values ≥ 1e29: excluded); `material` gives E* for the Hertz solution, `normal_kernel` (the
/// grid's C_nn, divided by G: elastic::make_kernel, or a kept kernel of the same elements at
/// least the grid's size, elastic::KernelLibrary::covering) the normal displacement.
ApproximateNormal kpec_pressure(const Grid& grid, const std::vector<double>& h_total,
                                const CombinedMaterial& material,
                                const elastic::Kernel& normal_kernel);
/// kpec_pressure with the grid's normal kernel tabulated here.
ApproximateNormal kpec_pressure(const Grid& grid, const std::vector<double>& h_total,
                                const CombinedMaterial& material);

/// Modified ANALYN: per row the local Hertz problem of the row's curvatures and gap, corrected
/// with the factors of the global Hertz solution (physics.md §7.3).
ApproximateNormal analyn_pressure(const Grid& grid, const std::vector<double>& h_total,
                                  const CombinedMaterial& material);

}  // namespace rollcontact::simplified
