#pragma once
// Module 1 (wheel/rail) case reader: the line layout of spec/inp-format.md §5, the profile
// files it names (§5.1, §8), the "keep" semantics of the control digits and the consistency
// rules of §3.2 that apply to module 1.

#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "format/inp/inp_reader.hpp"
#include "format/inp/wheelrail_record.hpp"
#include "format/text/inp_stream.hpp"

namespace rollcontact::format {

/// What a result element remembers between module-1 cases beyond the previous case itself.
struct Module1Stored {
  bool has_case = false;
  WheelRailRecord last;
  bool has_materials = false;       ///< a material block was read (C=2,3,4)
  bool has_discretisation = false;  ///< a discretisation line was read (D=2..9)
  bool has_rail = false;            ///< track dimensions and a rail profile were read
  bool has_wheel = false;           ///< wheelset dimensions and a wheel profile were read
  bool has_position = false;        ///< a wheelset position was read
  bool has_subsurface = false;      ///< an S=3 block list was read
  bool has_heat = false;            ///< H=3 parameters were read
};

/// Reads module-1 cases one at a time. Holds the stored state of every result element seen so
/// far, so one instance must read a whole file (and only one file).
class Module1Reader {
 public:
  Module1Reader(std::filesystem::path base_dir, InpReadOptions options)
      : base_dir_(std::move(base_dir)), options_(options) {}

  /// Reads the case starting at the control words. `module_line` is the line of the preceding
  /// module line (0 after an R=0/2 case); `case_number` is assigned by the caller (numbering is
  /// per result element and shared with module 3). Throws InputError for malformed input,
  /// including missing or malformed profile files.
  WheelRailRecord read_case(InpStream& in, int reid, int module_line, int case_number);

 private:
  /// Profile line(s) of §5.1 and the profile or slices file they name; `gaught` is the track's
  /// gauge height in effect (a rail slices file requires GAUGHT <= 0).
  ProfileSpec read_profile_line(InpStream& in, bool is_wheel, double gaught,
                                std::vector<std::string>& warnings) const;

  std::filesystem::path base_dir_;
  InpReadOptions options_;
  std::map<int, Module1Stored> stored_;
};

}  // namespace rollcontact::format
