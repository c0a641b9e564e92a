#pragma once
// Reading an input file whole, bounded: a device, pipe or folder (`run /dev/zero` would never
// end) and a file over the size limit are refused before a byte is read.

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace rollcontact::format {

/// The largest input file read [bytes]: 256 MiB, some hundred times the largest input CONTACT's
/// examples need (a 2000×1000 grid of per-element values is about 60 MB of text).
inline constexpr std::uintmax_t kMaxInputBytes = 256ull * 1024 * 1024;

/// The contents of `path`, `what` naming it in messages ("input file", "profile file").
/// Throws InputError (file, line 0) when it is not a regular file, cannot be opened, or is larger
/// than kMaxInputBytes; reads at most kMaxInputBytes even if the file grows meanwhile.
std::string read_input_file(const std::filesystem::path& path, std::string_view what);

}  // namespace rollcontact::format
