#pragma once
// Subsurface stress summaries of the .out report (spec/outputs.md §3.7).

#include <iosfwd>

#include "format/inp/case_record.hpp"
#include "rollcontact/solution.hpp"

namespace rollcontact::format::report {

/// Per block the eight maxima with their locations (OUTPUT_S >= 1), and for OUTPUT_S = 4 every
/// point's displacements and stress tensor. Writes nothing when S = 0 or OUTPUT_S = 0.
void write_subsurface_summaries(std::ostream& os, const CaseRecord& problem,
                                const Solution& solution);

}  // namespace rollcontact::format::report
