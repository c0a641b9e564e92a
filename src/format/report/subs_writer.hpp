#pragma once
// The `.subs` file of subsurface points (spec/outputs.md §6).

#include <filesystem>
#include <string>
#include <vector>

#include "format/inp/case_record.hpp"
#include "format/inp/wheelrail_record.hpp"
#include "rollcontact/solution.hpp"
#include "rollcontact/wheelrail.hpp"

namespace rollcontact::format {

/// Text of the .subs file: per block the NX NY NZ header and one row per point (x fastest, then
/// y, then z) with X Y Z UX UY UZ SIGHYD SIGVM (+ the six stresses for MATFIL_S = 2).
std::string format_subs(const CaseRecord& problem, const Solution& solution);

/// Writes `<output_stem>.<nnnn>.subs` (case number, at least 4 digits) atomically when S >= 1,
/// MATFIL_S >= 1 and the solution has subsurface results; returns its path, or an empty path
/// when nothing is written. Throws rollcontact::Error when the file cannot be written.
std::filesystem::path write_subs_file(const std::filesystem::path& output_stem,
                                      const CaseRecord& problem, const Solution& solution);

/// Module 1: `<output_stem>.<nnnn><a, b, …>.subs`, one per contact patch with subsurface
/// results, under the same conditions (the wheel/rail case's S digit and MATFIL_S; the case
/// number is `identity`'s, as for the `.mat` files). Returns the paths written.
std::vector<std::filesystem::path> write_wheelrail_subs_files(
    const std::filesystem::path& output_stem, const WheelRailRecord& record,
    const CaseRecord& identity, const WheelRailSolution& solution);

}  // namespace rollcontact::format
