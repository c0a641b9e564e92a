#pragma once
// The profile checks both wheel/rail readers (.inp module 1 and TOML) make on a named profile:
// the file's kind against its body and placement, and the chord length of release 25.1. The
// readers phrase the problems in their own terms (file:line and CONTACT's names, or TOML keys).

#include <filesystem>
#include <string>
#include <vector>

#include "format/inp/wheelrail_record.hpp"
#include "format/profiles/profile_points.hpp"

namespace rollcontact::format {

/// What may be wrong with a slices file named as a profile (spec/inp-format.md §8.4).
enum class SlicesFileProblem {
  none,
  wrong_extension,        ///< a wheel needs `.slcw`, a rail `.slcs`
  rail_with_gauge_point,  ///< rail slices are placed absolutely: GAUGHT ≤ 0 (rail origin)
};

/// The problem of naming the slices file `path` as the profile of a wheel or a rail whose gauge
/// height is `gauge_height_mm` (> 0: gauge-point placement).
SlicesFileProblem slices_file_problem(const std::filesystem::path& path, bool is_wheel,
                                      double gauge_height_mm);

/// Reads the profile file at `path` (resolved; a plain profile or a slices file) into `ps`
/// (`profile`, or `slices` with `sliced` set). Throws InputError naming the profile file.
void load_profile(ProfileSpec& ps, const std::filesystem::path& path, const ProfileOptions& options,
                  std::vector<std::string>& warnings);

/// A profile of `ps` (the plain profile, or each slice) whose chord length lies outside
/// 5..500 mm, with that length [mm].
struct InadmissibleLength {
  const Profile* profile = nullptr;  ///< null: every profile is admissible
  double chord_mm = 0.0;
};
InadmissibleLength first_inadmissible_length(const ProfileSpec& ps);

}  // namespace rollcontact::format
