#pragma once
// The blocks of the module-1 report that a conformal patch (D=4) prints instead of, or next to,
// the planar ones (spec/outputs.md §3.8, spec/wheelrail-advanced.md §1.8): its contact rows and
// angles, the friction per row (V=1), the bar and tilde forces, and the curved reference.

#include <ostream>

#include "rollcontact/wheelrail.hpp"

namespace rollcontact::format::report {

/// "Actual contact on columns …", the reference angle and its range, the planar moments.
void write_conformal_diagnostics(std::ostream& os, const WheelRailPatch& w);

/// FRICTION LAW PARAMETERS per grid row (V=1 on a conformal patch); the first and last two
/// rows when there are more than five.
void write_row_friction(std::ostream& os, const ConformalPatch& c);

/// The force block with BAR_FN … MN and TILDE_FN, FX/FN or FX/FSTAT/FN (mu_scale: the friction
/// coefficient the relative forces are divided by, 1 for V=1). eps: the solver tolerance, for
/// the printed noise filter.
void write_conformal_forces(std::ostream& os, const WheelRailPatch& w, double mu_scale, double eps,
                            bool with_temperature);

/// CURVED REFERENCE SURFACE, TRACK COORDINATES (O ≥ 3).
void write_curved_reference(std::ostream& os, const ConformalPatch& c);

}  // namespace rollcontact::format::report
