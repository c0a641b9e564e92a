#pragma once
// The one admissibility check of a PatchProblem, shared by every front end (.inp, TOML, the C++
// API): every number finite, and within the physical range CONTACT accepts (0 ≤ ν ≤ 0.5,
// G ≥ 1e-5 N/mm², μ ≥ 0, FN > 0 when prescribed, element sizes ≥ 1e-8 mm, ...). PatchSolver::solve
// runs it first; the readers run it on every case before anything is solved or written.

#include "rollcontact/errors.hpp"
#include "rollcontact/model/patch_problem.hpp"

namespace rollcontact::model {

/// Element sizes the solvers represent [mm]: below, the readers' limit; above, the influence
/// coefficients and pressures overflow (docs/decisions.md, "Finite in, finite out").
inline constexpr double kMinElementSize_mm = 1e-8;
inline constexpr double kMaxElementSize_mm = 1e8;

/// Throws InvalidValueError for the first inadmissible value (in the order of the struct).
void validate(const PatchProblem& problem);

}  // namespace rollcontact::model
