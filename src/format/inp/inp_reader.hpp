#pragma once
// Reader of CONTACT's .inp input language (spec/inp-format.md): module 3 (basic contact) and
// module 1 (wheel/rail) cases, in file order.

#include <filesystem>
#include <string>
#include <variant>
#include <vector>

#include "format/inp/case_record.hpp"
#include "format/inp/wheelrail_record.hpp"

namespace rollcontact::format {

/// Choices of the .inp reader.
struct InpReadOptions {
  /// A missing auxiliary file (C=9 coefficient file) is an InputError. When false (default), the
  /// case gets CaseRecord::source.case_error and reading continues, so the other cases of the file
  /// can still be computed (spec/validation.md §4, conformal.inp).
  bool missing_files_are_errors = false;
};

/// One case of an .inp file: a module-3 CaseRecord or a module-1 WheelRailRecord.
using InputCase = std::variant<CaseRecord, WheelRailRecord>;

/// Module number of a case: 3 (basic contact) or 1 (wheel/rail).
inline int input_case_module(const InputCase& c) {
  return std::holds_alternative<WheelRailRecord>(c) ? 1 : 3;
}

/// Reads every case of an .inp file, modules 1 and 3, in file order, fully resolved ("keep"
/// digits resolved per result element, consistency overrides applied; case numbers count per
/// result element, shared by both modules). Profile files named by module-1 cases are read and
/// validated. Cases with R=2,3 are included. Throws InputError naming file, line and offending
/// text for malformed input (including missing or malformed profile files).
std::vector<InputCase> read_input_cases(const std::filesystem::path& path,
                                        const InpReadOptions& options = {});

/// Same from a string; `name` is used in messages, `base_dir` resolves relative file names.
std::vector<InputCase> read_input_string(const std::string& text, const std::string& name,
                                         const std::filesystem::path& base_dir = {},
                                         const InpReadOptions& options = {});

/// Reads every case of a module-3-only .inp file into fully resolved Problems ("keep" digits are
/// resolved from the previous case of the same result element, consistency overrides applied).
/// Cases with R=2,3 are included (digits.r tells they are not to be solved). Throws InputError
/// naming file, line and offending text for malformed input, and an InputError "module 1
/// (wheel/rail) input is not supported yet by this reader" at the first module-1 module line of an
/// otherwise readable file (use read_input_cases for those).
std::vector<CaseRecord> read_inp_file(const std::filesystem::path& path);

/// Same from a string; `name` is used in messages and to resolve relative file names.
std::vector<CaseRecord> read_inp_string(const std::string& text, const std::string& name,
                                        const std::filesystem::path& base_dir = {});

/// As above, with explicit options.
std::vector<CaseRecord> read_inp_file(const std::filesystem::path& path,
                                      const InpReadOptions& options);
std::vector<CaseRecord> read_inp_string(const std::string& text, const std::string& name,
                                        const std::filesystem::path& base_dir,
                                        const InpReadOptions& options);

}  // namespace rollcontact::format
