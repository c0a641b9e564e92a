#pragma once
// Reader of Miniprof profiles (`.ban`, `.whl`: `Key=Value` header, then columns) and plain
// two-column tables (any other extension), spec/inp-format.md §8.2.

#include <string>
#include <string_view>
#include <vector>

#include "format/profiles/profile_points.hpp"

namespace rollcontact::format {

/// Parses the text of a Miniprof (`miniprof` true) or plain profile file named `file`. Throws
/// InputError(file, line, ...) for a non-numeric data word, a bad ColumnDef or fewer than 2
/// points; lines with too few columns are skipped with a warning.
RawProfile parse_table_profile(std::string_view text, const std::string& file, bool miniprof,
                               std::vector<std::string>& warnings);

}  // namespace rollcontact::format
