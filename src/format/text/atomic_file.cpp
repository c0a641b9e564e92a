#include "format/text/atomic_file.hpp"

#include <fmt/format.h>

#include <random>
#include <system_error>
#include <utility>

#include "rollcontact/errors.hpp"

namespace rollcontact::format {

namespace {

/// A device, pipe or symbolic link that exists at `path`: written through, never replaced.
bool write_through(const std::filesystem::path& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status st = fs::symlink_status(path, ec);
  return !ec && fs::exists(st) && !fs::is_regular_file(st);
}

}  // namespace

AtomicFileWriter::AtomicFileWriter(std::filesystem::path path) : path_(std::move(path)) {
  namespace fs = std::filesystem;
  through_ = write_through(path_);
  if (through_) {
    out_.open(path_, std::ios::binary);
    if (!out_) throw Error(fmt::format("cannot write '{}'", path_.string()));
    return;
  }
  const fs::path folder = path_.has_parent_path() ? path_.parent_path() : fs::path(".");
  std::random_device rd;
  tmp_ =
      folder / fmt::format(".{}.tmp{:08x}", path_.filename().string(), static_cast<unsigned>(rd()));
  out_.open(tmp_, std::ios::binary | std::ios::trunc);
  if (!out_) fail("cannot create a temporary file in the folder");
}

AtomicFileWriter::~AtomicFileWriter() {
  if (done_ || through_) return;
  out_.close();
  std::error_code ignored;
  std::filesystem::remove(tmp_, ignored);
}

void AtomicFileWriter::append(std::string_view text) {
  out_.write(text.data(), static_cast<std::streamsize>(text.size()));
}

void AtomicFileWriter::fail(const std::string& why) {
  done_ = true;
  out_.close();
  if (!through_) {
    std::error_code ignored;
    std::filesystem::remove(tmp_, ignored);
  }
  throw Error(fmt::format("cannot write '{}': {}", path_.string(), why));
}

void AtomicFileWriter::commit() {
  out_.flush();
  if (!out_) fail("write error");
  out_.close();
  if (through_) {
    done_ = true;
    return;
  }
  std::error_code ec;
  std::filesystem::rename(tmp_, path_, ec);
  if (ec) fail(ec.message());
  done_ = true;
}

void write_file_atomically(const std::filesystem::path& path, const std::string& content) {
  AtomicFileWriter out(path);
  out.append(content);
  out.commit();
}

void write_output_file(const std::filesystem::path& path, const std::string& content) {
  write_file_atomically(path, content);
}

}  // namespace rollcontact::format
