#include "format/text/atomic_file.hpp"

#include <fmt/format.h>

#include <fstream>
#include <random>
#include <system_error>

#include "rollcontact/errors.hpp"

namespace rollcontact::format {

void write_file_atomically(const std::filesystem::path& path, const std::string& content) {
  namespace fs = std::filesystem;
  // A device, pipe or symbolic link (/dev/null, /dev/stdout, a link into another folder) is
  // written through, never replaced: renaming over it would destroy it.
  std::error_code status_error;
  const fs::file_status st = fs::symlink_status(path, status_error);
  if (!status_error && fs::exists(st) && !fs::is_regular_file(st)) {
    std::ofstream out(path, std::ios::binary);
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    out.flush();
    if (!out) throw Error(fmt::format("cannot write '{}'", path.string()));
    return;
  }
  // The temporary lives in the target folder so that the final rename never crosses file
  // systems (rename is atomic only within one). A random suffix keeps parallel writers apart.
  const fs::path folder = path.has_parent_path() ? path.parent_path() : fs::path(".");
  std::random_device rd;
  const fs::path tmp =
      folder / fmt::format(".{}.tmp{:08x}", path.filename().string(), static_cast<unsigned>(rd()));

  auto fail = [&](const std::string& why) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    throw Error(fmt::format("cannot write '{}': {}", path.string(), why));
  };

  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) fail("cannot create a temporary file in the folder");
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    out.flush();
    if (!out) fail("write error");
  }
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) fail(ec.message());
}

void write_output_file(const std::filesystem::path& path, const std::string& content) {
  std::error_code ec;
  const auto st = std::filesystem::symlink_status(path, ec);
  if (!ec && std::filesystem::exists(st) && !std::filesystem::is_regular_file(st)) {
    std::ofstream out(path, std::ios::binary);
    out << content;
    out.flush();
    if (!out) throw Error("cannot write " + path.string());
    return;
  }
  write_file_atomically(path, content);
}

}  // namespace rollcontact::format
