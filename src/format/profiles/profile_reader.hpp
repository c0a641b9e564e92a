#pragma once
// Reading a rail or wheel profile file named on a profile line of an .inp file
// (spec/inp-format.md §5.1, §8): the format follows from the extension; slices files (.slcs,
// .slcw) give a SlicedProfile whose slices are read with the same options.

#include <filesystem>
#include <string>
#include <vector>

#include "format/profiles/profile_points.hpp"
#include "rollcontact/model/profile.hpp"

namespace rollcontact::format {

/// Format from the file extension (case-insensitive): .prr/.prw SIMPACK, .ban/.whl Miniprof,
/// .slcs/.slcw slices, anything else a plain table.
ProfileFormat profile_format_of(const std::filesystem::path& path);

/// Reads one cross-section profile (not a slices file) and applies the clean-up of §8.3.
/// Throws InputError naming the profile file and line for unreadable or malformed files.
Profile read_profile_file(const std::filesystem::path& path, const ProfileOptions& options,
                          std::vector<std::string>& warnings);

}  // namespace rollcontact::format
