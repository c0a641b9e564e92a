#include "format/text/file_names.hpp"

#include <algorithm>
#include <system_error>

namespace rollcontact::format {

namespace {

std::filesystem::path resolve(const std::filesystem::path& base_dir, const std::string& name) {
  const std::filesystem::path p(name);
  return ((p.is_absolute() || base_dir.empty()) ? p : base_dir / p).lexically_normal();
}

}  // namespace

std::filesystem::path resolve_input_name(const std::filesystem::path& base_dir,
                                         const std::string& name) {
  const std::filesystem::path as_written = resolve(base_dir, name);
  std::error_code ec;
  if (name.find('\\') == std::string::npos || std::filesystem::exists(as_written, ec))
    return as_written;
  std::string slashes = name;
  std::replace(slashes.begin(), slashes.end(), '\\', '/');
  return resolve(base_dir, slashes);
}

std::string written_input_name(const std::filesystem::path& file,
                               const std::filesystem::path& base_dir) {
  std::error_code ec;
  const std::filesystem::path rel =
      base_dir.empty() ? file : std::filesystem::relative(file, base_dir, ec);
  return (ec || rel.empty() ? file : rel).generic_string();
}

}  // namespace rollcontact::format
