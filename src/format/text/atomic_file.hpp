#pragma once
// Writers write to a temporary file and rename: a crash never leaves half a report.

#include <filesystem>
#include <string>

namespace rollcontact::format {

/// Writes `content` to `path` atomically (temporary file in the same folder, then rename).
/// Throws rollcontact::Error when the file cannot be written.
void write_file_atomically(const std::filesystem::path& path, const std::string& content);

/// Writes an output the user named: atomically for a regular (or new) file; directly for a
/// device, pipe or symbolic link (-o /dev/null, /dev/stdout), whose node a rename would replace.
void write_output_file(const std::filesystem::path& path, const std::string& content);

}  // namespace rollcontact::format
