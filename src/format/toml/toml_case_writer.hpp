#pragma once
// Writer of TOML case files (docs/case-files.md): Problems → human-readable TOML with names and
// units instead of control digits. read_toml_string() reads the text back into the same
// Problems (every solve-relevant field; doubles are written with round-trip precision).

#include <filesystem>
#include <string>
#include <vector>

#include "format/inp/case_record.hpp"
#include "format/inp/inp_reader.hpp"

namespace rollcontact::format {

/// The TOML text of `problems`, one [[case]] each, in order. Only the values that matter for
/// each case's choices are written (e.g. no rolling step for a shift). `base_dir` is the folder
/// the file will live in: influence-coefficient file names are written relative to it. Throws
/// rollcontact::Error for a CaseRecord holding a value the schema has no name for (e.g. L=5).
std::string write_toml_string(const std::vector<CaseRecord>& problems,
                              const std::filesystem::path& base_dir = {});

/// Writes write_toml_string(problems, path's folder) to `path` atomically.
void write_toml_file(const std::filesystem::path& path, const std::vector<CaseRecord>& problems);

/// The same for cases of both modules; wheel/rail cases become [case.wheel_rail] tables with
/// their profile files relative to `base_dir`. Throws rollcontact::Error for what the schema
/// cannot express yet (variable friction, massless rail, flexible wheelsets, slices files).
std::string write_toml_input_string(const std::vector<InputCase>& cases,
                                    const std::filesystem::path& base_dir = {});
void write_toml_input_file(const std::filesystem::path& path, const std::vector<InputCase>& cases);

}  // namespace rollcontact::format
