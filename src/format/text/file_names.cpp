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

}  // namespace rollcontact::format
