#pragma once
// Reader of slices files (`.slcs` rail along the track, `.slcw` wheel around its axle),
// spec/inp-format.md §8.4: a header, one profile file per slice, optional kink/acceleration
// lists and feature positions.

#include <filesystem>
#include <string>
#include <vector>

#include "format/profiles/profile_points.hpp"
#include "rollcontact/model/profile.hpp"

namespace rollcontact::format {

/// True when `path` has the slices extension of its body: `.slcw` for a wheel, `.slcs` for a
/// rail (any letter case).
bool has_slices_extension(const std::filesystem::path& path, bool is_wheel);

/// Reads a slices file and every slice profile it names (relative to the slices file's folder),
/// each processed with `options`. Throws InputError naming the slices file and line (header
/// values out of range, slice positions not increasing, a missing slice file) or the slice file
/// and line (malformed slice).
SlicedProfile read_slices_file(const std::filesystem::path& path, const ProfileOptions& options,
                               std::vector<std::string>& warnings);

}  // namespace rollcontact::format
