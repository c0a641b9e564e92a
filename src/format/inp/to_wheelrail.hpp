#pragma once
// The adapter from a module-1 case (WheelRailRecord) to the wheel/rail model: the patch settings
// go through the module-3 adapter, the rest is copied into named fields.

#include "format/inp/wheelrail_record.hpp"
#include "rollcontact/model/wheelrail.hpp"

namespace rollcontact::format {

/// Throws NotSupportedError naming the digit and value for module-1 features not implemented
/// yet (roller rigs, conformal contact, transient rolling, massless rail, ...).
void check_supported(const WheelRailRecord& record);

/// The case's identity (number, result element, digits, source) as a module-3 record, for
/// the parts of a run that speak of cases in general (progress, errors, shared report blocks).
CaseRecord identity_record(const WheelRailRecord& record);

/// A profile line's points and smoothing options as the wheel/rail model takes them.
model::WheelRailProfile to_wheelrail_profile(const ProfileSpec& spec);

/// The settings every patch of `record` shares (digits, solver, friction, material, damping,
/// heat, subsurface) with its identity, as a module-3 record: the report, the TOML writer and
/// the patch template start from it.
CaseRecord settings_record(const WheelRailRecord& record);

/// The physics of `record`. Calls check_supported() first. `solve_unvalidated`: the problem
/// solves features whose results are known to differ from CONTACT's, with a warning each
/// (model::WheelRailProblem::validated_only false; `rollcontact run --unvalidated`); by default
/// the solver refuses them.
model::WheelRailProblem to_wheelrail_problem(const WheelRailRecord& record,
                                             bool solve_unvalidated = false);

}  // namespace rollcontact::format
