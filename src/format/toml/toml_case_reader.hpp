#pragma once
// Reader of TOML case files (docs/case-files.md): the Problems of an .inp file described with
// names and units instead of control digits. Every case is fully resolved (no "keep" values).

#include <filesystem>
#include <string>
#include <vector>

#include "format/inp/case_record.hpp"
#include "format/inp/inp_reader.hpp"

namespace rollcontact::format {

/// Choices of the TOML reader.
struct TomlReadOptions {
  /// A missing influence-coefficient file (influence = "from_file") is an InputError. When false
  /// (default) the case gets CaseRecord::source.case_error, as the .inp reader does.
  bool missing_files_are_errors = false;
};

/// Reads every [[case]] of a TOML case file, in order. The control digits of each CaseRecord are
/// set to their explicit values (D=2, Z=2, C = influence type, L = law, ...). Throws InputError
/// naming file, line and the key path (e.g. "case[2].normal.force_N") for malformed input,
/// unknown keys, wrong types and out-of-range values.
std::vector<CaseRecord> read_toml_file(const std::filesystem::path& path,
                                       const TomlReadOptions& options = {});

/// Same from a string; `name` is used in messages, `base_dir` resolves relative file names.
std::vector<CaseRecord> read_toml_string(const std::string& text, const std::string& name,
                                         const std::filesystem::path& base_dir = {},
                                         const TomlReadOptions& options = {});

/// Every [[case]] of a TOML case file, module 3 and wheel/rail (module 1: a [case.wheel_rail]
/// table), in order, with case numbers counted per result element as in .inp files.
std::vector<InputCase> read_toml_input_string(const std::string& text, const std::string& name,
                                              const std::filesystem::path& base_dir = {},
                                              const TomlReadOptions& options = {});
std::vector<InputCase> read_toml_input_file(const std::filesystem::path& path,
                                            const TomlReadOptions& options = {});

}  // namespace rollcontact::format
