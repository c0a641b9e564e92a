#include "format/inp/profile_spec_checks.hpp"

#include <memory>

#include "format/profiles/profile_reader.hpp"
#include "format/profiles/profile_slices.hpp"

namespace rollcontact::format {

SlicesFileProblem slices_file_problem(const std::filesystem::path& path, bool is_wheel,
                                      double gauge_height_mm) {
  if (!has_slices_extension(path, is_wheel)) return SlicesFileProblem::wrong_extension;
  if (!is_wheel && gauge_height_mm > 0.0) return SlicesFileProblem::rail_with_gauge_point;
  return SlicesFileProblem::none;
}

void load_profile(ProfileSpec& ps, const std::filesystem::path& path, const ProfileOptions& options,
                  std::vector<std::string>& warnings) {
  if (profile_format_of(path) == ProfileFormat::Slices) {
    ps.sliced = true;
    ps.slices = std::make_shared<const SlicedProfile>(read_slices_file(path, options, warnings));
  } else {
    ps.sliced = false;
    ps.profile = std::make_shared<const Profile>(read_profile_file(path, options, warnings));
  }
}

InadmissibleLength first_inadmissible_length(const ProfileSpec& ps) {
  const auto check = [](const Profile& p) {
    const double chord = profile_chord_length(p);
    return is_admissible_profile_length(chord) ? InadmissibleLength{}
                                               : InadmissibleLength{&p, chord};
  };
  if (!ps.sliced) return check(*ps.profile);
  for (const Profile& slice : ps.slices->slices) {
    if (const InadmissibleLength bad = check(slice); bad.profile != nullptr) return bad;
  }
  return {};
}

}  // namespace rollcontact::format
