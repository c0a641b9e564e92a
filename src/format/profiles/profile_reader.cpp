#include "format/profiles/profile_reader.hpp"

#include <algorithm>
#include <cctype>

#include "format/profiles/profile_simpack.hpp"
#include "format/profiles/profile_table.hpp"
#include "format/profiles/profile_text.hpp"
#include "rollcontact/errors.hpp"

namespace rollcontact::format {

ProfileFormat profile_format_of(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".prr" || ext == ".prw") return ProfileFormat::Simpack;
  if (ext == ".ban" || ext == ".whl") return ProfileFormat::Miniprof;
  if (ext == ".slcs" || ext == ".slcw") return ProfileFormat::Slices;
  return ProfileFormat::Plain;
}

Profile read_profile_file(const std::filesystem::path& path, const ProfileOptions& options,
                          std::vector<std::string>& warnings) {
  const ProfileFormat format = profile_format_of(path);
  const std::string name = path.string();
  if (format == ProfileFormat::Slices) {
    throw InputError(name, 0, "a slices file cannot be used as a single profile here");
  }
  const std::string text = read_text_file(path);
  RawProfile raw =
      format == ProfileFormat::Simpack
          ? parse_simpack_profile(text, name, options.is_wheel, warnings)
          : parse_table_profile(text, name, format == ProfileFormat::Miniprof, warnings);
  return finish_profile(std::move(raw), options, warnings);
}

}  // namespace rollcontact::format
