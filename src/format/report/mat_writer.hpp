#pragma once
// ASCII per-element `.mat` file of a solved module-3 case (A digit 1 or 2), spec/outputs.md §5:
// six pairs of a `%` comment line and a value line (metadata, grid, material, friction; format
// version 2410), a column header and one row per element, in CONTACT's fixed 14-character
// columns (Fortran g14.6), readable by CONTACT's Matlab scripts.

#include <filesystem>
#include <string>

#include "format/inp/case_record.hpp"
#include "rollcontact/solution.hpp"

namespace rollcontact::format {

/// Version of the .mat layout written in the last column of line 2.
inline constexpr int kMatFormatVersion = 2410;

/// The text of the .mat file: with digits.a == 1 the elements in contact (adhesion, slip,
/// plastic), with digits.a >= 2 every element of the potential contact area.
std::string mat_file_text(const CaseRecord& problem, const Solution& solution);

/// `<stem>.<nnnn>.mat` (case number zero-padded to at least 4 digits).
std::filesystem::path mat_file_path(const std::filesystem::path& output_stem, int case_number);

/// Writes mat_file_text() atomically to mat_file_path() and returns the path.
/// Throws rollcontact::Error when the file cannot be written.
std::filesystem::path write_mat_file(const std::filesystem::path& output_stem,
                                     const CaseRecord& problem, const Solution& solution);

}  // namespace rollcontact::format
