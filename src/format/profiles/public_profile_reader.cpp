// The public reader of include/rollcontact/profiles.hpp: the .inp reader's profile path without
// an .inp file around it.

#include <fmt/format.h>

#include "format/profiles/profile_reader.hpp"
#include "rollcontact/errors.hpp"
#include "rollcontact/profiles.hpp"

namespace rollcontact {

Profile read_profile(const std::filesystem::path& path, const ProfileFileOptions& options,
                     std::vector<std::string>* warnings) {
  if (format::profile_format_of(path) == ProfileFormat::Slices)
    throw NotSupportedError(fmt::format("'{}': slices files (variable profiles)", path.string()));
  format::ProfileOptions o;
  o.is_wheel = options.is_wheel;
  o.mirror_y = options.mirror_y;
  o.mirror_z = options.mirror_z;
  o.scale_yz = options.scale_yz;
  std::vector<std::string> local;
  Profile p = format::read_profile_file(path, o, warnings != nullptr ? *warnings : local);
  const double length = format::profile_chord_length(p);
  if (!format::is_admissible_profile_length(length))
    throw GeometryError(fmt::format(
        "{} profile '{}' has a length of {:.6g} mm, outside 5..500 mm: SCALEYZ ({}) or the "
        "file's units are probably wrong",
        options.is_wheel ? "wheel" : "rail", path.string(), length, options.scale_yz));
  return p;
}

}  // namespace rollcontact
