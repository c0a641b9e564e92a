#pragma once
// The adapter from CONTACT's case description to the solver's model: control digits become
// named choices, "keep" digits have already been resolved by the readers.

#include "format/inp/case_record.hpp"
#include "rollcontact/model/patch_problem.hpp"

namespace rollcontact::format {

/// Throws NotSupportedError naming the digit and value when the case uses a feature that the
/// solvers do not implement yet; returns normally otherwise.
void check_supported(const CaseRecord& record);

/// The friction law L with one parameter set and the memory line as the model's Friction.
model::Friction to_model_friction(int law, const FrictionValues& values, double memdst,
                                  double mem_s0);

/// The physics of `record` as a PatchProblem. Calls check_supported() first.
model::PatchProblem to_patch_problem(const CaseRecord& record);

}  // namespace rollcontact::format
