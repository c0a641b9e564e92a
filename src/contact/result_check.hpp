#pragma once
// The last gate before a result is reported: a solution with a non-finite number in a total or
// a field on the contact is a failed case with the reason, never "converged" (issue 11).

#include <string>

#include "rollcontact/solution.hpp"

namespace rollcontact {

/// The first non-finite value of the totals, the fields (pressure, tractions, displacements,
/// slip) and the subsurface results, described as "FN = nan" or "pn[12] = inf"; empty when
/// everything is finite. Excluded elements keep their marker h = 1e30, which is finite.
std::string first_non_finite(const Solution& solution);

}  // namespace rollcontact
