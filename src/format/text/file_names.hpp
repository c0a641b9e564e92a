#pragma once
// File names written inside input files: relative to the input file's folder, and with either
// separator — CONTACT accepts 'profiles\rail.prr' on every platform, so a name that does not
// exist as written is tried again with its backslashes read as separators.

#include <filesystem>
#include <string>

namespace rollcontact::format {

/// `name` as written in an input file, resolved against `base_dir` (empty: as is) and
/// normalised. When that file does not exist and the name contains backslashes, the name with
/// '/' for '\' is returned instead (whether or not that exists: the caller reports it).
std::filesystem::path resolve_input_name(const std::filesystem::path& base_dir,
                                         const std::string& name);

/// The inverse for writers: `file` as an input file in `base_dir` names it — relative to
/// `base_dir` (std::filesystem::relative; `file` itself when base_dir is empty or no relative
/// form exists), with '/' separators.
std::string written_input_name(const std::filesystem::path& file,
                               const std::filesystem::path& base_dir);

}  // namespace rollcontact::format
