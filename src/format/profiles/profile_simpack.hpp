#pragma once
// Reader of SIMPACK profile files (`.prr` rail, `.prw` wheel), spec/inp-format.md §8.1.

#include <string>
#include <string_view>
#include <vector>

#include "format/profiles/profile_points.hpp"

namespace rollcontact::format {

/// Parses the text of a SIMPACK profile file named `file`. `is_wheel` selects the expected
/// header type (0 rail, 1 wheel). Throws InputError(file, line, ...) for misplaced sections,
/// unreadable values, a non-zero `rotate`, a wrong `type` or fewer than 2 points; unknown keys
/// give a warning.
RawProfile parse_simpack_profile(std::string_view text, const std::string& file, bool is_wheel,
                                 std::vector<std::string>& warnings);

}  // namespace rollcontact::format
