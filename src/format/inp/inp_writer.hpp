#pragma once
// Writer of CONTACT .inp text (spec/inp-format.md, modules 3 and 1) from case records: the way
// back from TOML case files to the control-digit language, readable by CONTACT and by
// read_input_string().

#include <filesystem>
#include <string>
#include <vector>

#include "format/inp/case_record.hpp"
#include "format/inp/inp_reader.hpp"
#include "format/inp/inp_writer_module1.hpp"

namespace rollcontact::format {

/// The .inp text of `problems`, every case written explicitly: each case is preceded by a module
/// line "3 MODULE REID CPID" and uses D=2, Z=2, C = influence type, L = friction law, G = solver
/// method, E = extra-slip mode, M2 = 0/2, H = 0/3, S = 0/3 and R = 1/3 (no "keep" digits), so
/// reading it back gives the same Problems for every solve-relevant field. Doubles are written
/// with round-trip precision. `base_dir` is the folder the file will live in (influence-file
/// names are written relative to it). Throws rollcontact::Error for values the .inp language
/// cannot express (e.g. a file name containing a quote).
std::string write_inp_string(const std::vector<CaseRecord>& problems,
                             const std::filesystem::path& base_dir = {});

/// Writes write_inp_string(problems, path's folder) to `path` atomically.
void write_inp_file(const std::filesystem::path& path, const std::vector<CaseRecord>& problems);

/// An .inp text and the files it names that the writer makes (profiles given as points).
struct InpText {
  std::string text;
  std::vector<CompanionFile> companions;
};

/// The .inp text of module-3 and module-1 (wheel/rail) cases, every case explicit: module-3
/// cases as write_inp_string, wheel/rail cases after a module line "1 REID MODULE" with Z=3,
/// E=3 (5 with a flexible wheel), C, L, G, D and V resolved (write_wheelrail_case). Profile files
/// are named relative to `base_dir`; profiles given as points become companion tables named
/// `<companion_stem>_rail1.txt`, ….
InpText write_inp_text(const std::vector<InputCase>& cases,
                       const std::filesystem::path& base_dir = {},
                       const std::string& companion_stem = "case");

/// Writes write_inp_text(cases, path's folder, path's stem) to `path` and its companion tables
/// beside it, each atomically; a companion that would replace a profile file one of the cases
/// reads is refused (rollcontact::Error) before anything is written. Returns the companions'
/// paths.
std::vector<std::filesystem::path> write_inp_input_file(const std::filesystem::path& path,
                                                        const std::vector<InputCase>& cases);

}  // namespace rollcontact::format
