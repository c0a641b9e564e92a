#pragma once
// Writers write to a temporary file and rename: a crash never leaves half a report.

#include <filesystem>
#include <string>

namespace rollcontact::format {

/// Writes `content` to `path` atomically (temporary file in the same folder, then rename).
/// Throws rollcontact::Error when the file cannot be written.
void write_file_atomically(const std::filesystem::path& path, const std::string& content);

}  // namespace rollcontact::format
