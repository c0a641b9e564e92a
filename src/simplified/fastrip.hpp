#pragma once
// Modified FaStrip (spec/physics.md §11.4): the Fastsim solution corrected row by row with the
// 2-D strip theory (Kalker's strip solution with spin), which places the adhesion zone at the
// leading edge with the traction shape of Carter's solution.

#include <span>

#include "rollcontact/grid.hpp"
#include "simplified/fastsim.hpp"
#include "simplified/flexibility.hpp"
#include "simplified/kalker_coefficients.hpp"

namespace rollcontact::simplified {

struct FastripInput {
  Grid grid;
  std::span<const double> pn;  ///< normal pressure [N/mm²]; contact where pn > 0
  double mu = 0.3;             ///< static friction coefficient [-]
  Ellipse ellipse;             ///< equivalent ellipse [mm]
  KalkerCoefficients coefficients;
  double g = 0.0, nu = 0.0;  ///< combined shear modulus [N/mm²] and Poisson ratio [-]
  double fn = 0.0;           ///< total normal force [N]
  Creepages creepages;
  double chi = 0.0;    ///< rolling direction [rad]: 0 (leading edge at +x) or π
  Flexibilities flex;  ///< effective flexibilities L/k [mm³/N], for u = L·p
};

/// Replaces, row by row, the Fastsim tractions in `fields` by the strip-theory solution where it
/// respects the traction bound (max |f| ≤ 1 over the adhesion zone): adhesion zone at the
/// leading edge with the strip tractions, slip elsewhere with the Fastsim direction scaled onto
/// μp_n. Rows whose strip solution violates the bound keep the Fastsim result. In corrected rows
/// u = L·p; the slip S keeps the Fastsim value in slip elements and is 0 in adhesion.
void fastrip_correction(const FastripInput& in, SimplifiedFields& fields);

}  // namespace rollcontact::simplified
