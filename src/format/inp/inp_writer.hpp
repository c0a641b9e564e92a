#pragma once
// Writer of CONTACT .inp text (spec/inp-format.md, module 3) from Problems: the way back from
// TOML case files to the control-digit language, readable by CONTACT and by read_inp_string().

#include <filesystem>
#include <string>
#include <vector>

#include "format/inp/case_record.hpp"

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

}  // namespace rollcontact::format
