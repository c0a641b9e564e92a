#pragma once
// Reader of CONTACT's .inp input language (spec/inp-format.md), module 3.

#include <filesystem>
#include <string>
#include <vector>

#include "rollcontact/problem.hpp"

namespace rollcontact::io {

/// Choices of the .inp reader.
struct InpReadOptions {
  /// A missing auxiliary file (C=9 coefficient file) is an InputError. When false (default), the
  /// case gets Problem::source.case_error and reading continues, so the other cases of the file
  /// can still be computed (spec/validation.md §4, conformal.inp).
  bool missing_files_are_errors = false;
};

/// Reads every case of an .inp file into fully resolved Problems ("keep" digits are resolved from
/// the previous case of the same result element, consistency overrides applied). Cases with R=2,3
/// are included (digits.r tells they are not to be solved). Throws InputError naming file, line
/// and offending text for malformed input.
std::vector<Problem> read_inp_file(const std::filesystem::path& path);

/// Same from a string; `name` is used in messages and to resolve relative file names.
std::vector<Problem> read_inp_string(const std::string& text, const std::string& name,
                                     const std::filesystem::path& base_dir = {});

/// As above, with explicit options.
std::vector<Problem> read_inp_file(const std::filesystem::path& path,
                                   const InpReadOptions& options);
std::vector<Problem> read_inp_string(const std::string& text, const std::string& name,
                                     const std::filesystem::path& base_dir,
                                     const InpReadOptions& options);

}  // namespace rollcontact::io
