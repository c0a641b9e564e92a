#pragma once
// The module-1 report's echo of the case's inputs (spec/outputs.md §3.8): the profile reading
// lines, the problem description, material and friction constants, discretisation, profiles and
// track, and per patch the simplified theory's constants. Printed where and when CONTACT prints
// them (by the case's digits), so that scripts reading CONTACT's reports read ours.

#include <iosfwd>

#include "format/inp/wheelrail_record.hpp"
#include "rollcontact/solution.hpp"

namespace rollcontact::format::report {

/// ` reading rail  profile "…"` / ` reading wheel profile "…"` when the case reads them (Z=3,
/// E=3,5), as CONTACT's trace lines before the vertical-force iterates.
void write_profile_reading(std::ostream& os, const WheelRailRecord& r);

/// ` VERTICAL PROBLEM WITH PRESCRIBED …, {FULL|APPROXIMATE KPEC|APPROXIMATE ANALYN} SOLUTION`,
/// the rolling line (with `"FASTSIM APPROACH"` for M=2,3) and the friction-stress method.
void write_wheelrail_problem_lines(std::ostream& os, const WheelRailRecord& r);

/// MATERIAL CONSTANTS (C ≥ 2, with the model's parameters), FRICTION LAW PARAMETERS (L ≠ 1,
/// one row per ALPHA or SVF for V=1,2), DISCRETISATION PARAMETERS (D ≥ 2), RAIL PROFILE (Z=3),
/// TRACK DIMENSIONS AND RAIL POSITION (Z=1,3), WHEEL PROFILE (E=3,5), in CONTACT's order.
void write_wheelrail_input_blocks(std::ostream& os, const WheelRailRecord& r,
                                  const CombinedMaterial& material);

/// Per patch, M=2,3,5: the effective flexibilities and slope reduction factor the simplified
/// theory used (SIMPLIFIED THEORY MATERIAL CONSTANTS, K0_EFF).
void write_patch_simplified(std::ostream& os, const WheelRailRecord& r, const Solution& s);

}  // namespace rollcontact::format::report
