#pragma once
// Writers write to a temporary file and rename: a crash never leaves half a report.

#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

namespace rollcontact::format {

/// A file written piece by piece and put in place by commit(): until then the pieces go to a
/// temporary file in the target's folder (same file system, so the rename is atomic; a random
/// suffix keeps parallel writers apart), removed when the writer is destroyed uncommitted — a
/// run that fails half-way never leaves half a report, and a long run need not hold its
/// outputs in memory. A device, pipe or symbolic link (-o /dev/null, /dev/stdout, a link into
/// another folder) is written through instead: renaming over it would destroy it.
class AtomicFileWriter {
 public:
  /// Opens the temporary file (or the device); throws rollcontact::Error when it cannot.
  explicit AtomicFileWriter(std::filesystem::path path);
  ~AtomicFileWriter();
  AtomicFileWriter(const AtomicFileWriter&) = delete;
  AtomicFileWriter& operator=(const AtomicFileWriter&) = delete;

  void append(std::string_view text);
  /// Flushes and renames the temporary file onto the path; throws rollcontact::Error (and
  /// removes the temporary file) on a write error.
  void commit();
  const std::filesystem::path& path() const noexcept { return path_; }

 private:
  [[noreturn]] void fail(const std::string& why);

  std::filesystem::path path_, tmp_;
  std::ofstream out_;
  bool through_ = false;  ///< writing to the path itself (device, pipe, symbolic link)
  bool done_ = false;     ///< committed, or failed and cleaned up
};

/// Writes `content` to `path` atomically (temporary file in the same folder, then rename).
/// Throws rollcontact::Error when the file cannot be written.
void write_file_atomically(const std::filesystem::path& path, const std::string& content);

/// Writes an output the user named: atomically for a regular (or new) file; directly for a
/// device, pipe or symbolic link (-o /dev/null, /dev/stdout), whose node a rename would replace.
void write_output_file(const std::filesystem::path& path, const std::string& content);

}  // namespace rollcontact::format
