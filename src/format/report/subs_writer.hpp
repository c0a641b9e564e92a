#pragma once
// The `.subs` file of subsurface points (spec/outputs.md §6).

#include <filesystem>
#include <string>

#include "format/inp/case_record.hpp"
#include "rollcontact/solution.hpp"

namespace rollcontact::format {

/// Text of the .subs file: per block the NX NY NZ header and one row per point (x fastest, then
/// y, then z) with X Y Z UX UY UZ SIGHYD SIGVM (+ the six stresses for MATFIL_S = 2).
std::string format_subs(const CaseRecord& problem, const Solution& solution);

/// Writes `<output_stem>.<nnnn>.subs` (case number, at least 4 digits) atomically when S >= 1,
/// MATFIL_S >= 1 and the solution has subsurface results; returns its path, or an empty path
/// when nothing is written. Throws rollcontact::Error when the file cannot be written.
std::filesystem::path write_subs_file(const std::filesystem::path& output_stem,
                                      const CaseRecord& problem, const Solution& solution);

}  // namespace rollcontact::format
