#include "format/text/input_file.hpp"

#include <fmt/format.h>

#include <fstream>
#include <system_error>

#include "rollcontact/errors.hpp"

namespace rollcontact::format {

std::string read_input_file(const std::filesystem::path& path, std::string_view what) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);  // follows symbolic links
  if (ec || !fs::exists(status))
    throw InputError(path.string(), 0, fmt::format("cannot open {}: no such file", what));
  if (!fs::is_regular_file(status)) {
    throw InputError(path.string(), 0,
                     fmt::format("the {} is not a regular file (a folder, device or pipe)", what));
  }
  const std::uintmax_t size = fs::file_size(path, ec);
  if (!ec && size > kMaxInputBytes) {
    throw InputError(path.string(), 0,
                     fmt::format("the {} has {} bytes, more than the limit of {} bytes (256 MiB)",
                                 what, size, kMaxInputBytes));
  }
  std::ifstream file(path, std::ios::binary);
  if (!file) throw InputError(path.string(), 0, fmt::format("cannot open {}", what));
  std::string text(static_cast<std::size_t>(ec ? 0 : size), '\0');
  file.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(file.gcount()));
  // A file that grew since its size was taken: read on, within the limit.
  char buffer[65536];
  while (file.read(buffer, sizeof buffer) || file.gcount() > 0) {
    if (text.size() + static_cast<std::size_t>(file.gcount()) > kMaxInputBytes) {
      throw InputError(path.string(), 0,
                       fmt::format("the {} grew beyond the limit of {} bytes while being read",
                                   what, kMaxInputBytes));
    }
    text.append(buffer, static_cast<std::size_t>(file.gcount()));
  }
  return text;
}

}  // namespace rollcontact::format
