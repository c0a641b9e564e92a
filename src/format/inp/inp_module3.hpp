#pragma once
// Module 3 ("basic contact") case reader: the line layout of spec/inp-format.md §4, the "keep"
// semantics of the control digits and the consistency rules of §3.2.

#include <filesystem>
#include <map>
#include <utility>

#include "format/inp/case_record.hpp"
#include "format/inp/inp_reader.hpp"
#include "format/text/inp_stream.hpp"

namespace rollcontact::format {

/// What a module-3 contact problem remembers between cases beyond the previous CaseRecord.
struct Module3Stored {
  bool has_case = false;
  CaseRecord last;                ///< the previous case, fully resolved
  bool has_geometry = false;      ///< an IBASE block was read for a non-Hertzian grid
  bool has_subsurface = false;    ///< an S=3 block list was read
  bool has_heat = false;          ///< H=3 parameters were read
  bool has_coefficients = false;  ///< coefficients were computed for a grid (C != 0)
  int coef_mx = 0, coef_my = 0;   ///< grid of the stored coefficients
  double coef_dx = 0.0, coef_dy = 0.0;
  bool coef_dx_known = false;  ///< false for Hertzian grids (element size derived later)
};

/// Reads module-3 cases one at a time. Holds the stored state of every contact problem
/// (REID, CPID) seen so far, so one instance must read a whole file (and only one file).
class Module3Reader {
 public:
  Module3Reader(std::filesystem::path base_dir, InpReadOptions options)
      : base_dir_(std::move(base_dir)), options_(options) {}

  /// Reads the case starting at the control words. `module_line` is the line of the preceding
  /// module line (0 if the case follows an R=0/2 case); `case_number` is assigned by the caller
  /// (numbering is per result element and shared with module 1).
  CaseRecord read_case(InpStream& in, int reid, int cpid, int module_line, int case_number);

 private:
  /// C=9: the influence-coefficient file, resolved against the input's folder.
  void read_coefficient_file(InpStream& in, CaseRecord& p) const;
  std::filesystem::path base_dir_;
  InpReadOptions options_;
  std::map<std::pair<int, int>, Module3Stored> stored_;
};

}  // namespace rollcontact::format
