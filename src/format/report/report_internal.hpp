#pragma once
// Pieces of the .out report shared between report_*.cpp files (not part of the public API).

#include <array>
#include <iosfwd>
#include <span>
#include <string>
#include <string_view>

#include "format/inp/case_record.hpp"
#include "rollcontact/solution.hpp"

namespace rollcontact::format::report {

/// Writes `text` and a newline.
void line(std::ostream& os, std::string_view text);

/// Fortran a12 of a label: left-aligned, padded with blanks to 12 characters.
std::string a12(std::string_view label);

/// The reports' usual real field: 12 wide, 4 significant digits (fmt_sig(12, 4, 4, v)).
std::string sig(double v);

/// Fortran g12.4 (`  0.2800    `, `0.1980E-04`): the reports' input echo fields.
std::string g12(double v);

/// ` JOHNSON"S METHOD …` (MAXOUT ≤ 1) or ` PANAGIOTOPOULOS" METHOD … MAXOUT=  n`.
std::string frictional_stress_method(int maxout);

/// ` USING CONFORMAL IF-CORRECTION: BLANCO(vN), CONSTANT CURVATURE` (C=4;
/// wheelrail-advanced.md §1.7).
std::string inclination_correction_method(const Materials::Conformal& c);

/// The friction law's column header after `prefix`, and one set of its values (g12.4 fields).
std::string friction_header(int law, const std::string& prefix);
std::string friction_values(int law, double fstat, double fkin, const std::array<double, 4>& p);

/// FRICTION LAW PARAMETERS: the law's single set, or V=3's rows (all for O ≥ 4).
void write_friction_block(std::ostream& os, const Friction& fr, int output_digit);

/// Module-3 parameter blocks printed for O >= 2 (digit echo up to kinematic constants).
void write_parameter_blocks(std::ostream& os, const CaseRecord& problem, const Solution& solution);

/// Force block (O >= 1), sensitivities and statistics (O >= 2), §3.3–3.4.
void write_force_block(std::ostream& os, const CaseRecord& problem, const Solution& solution);
void write_sensitivities(std::ostream& os, const CaseRecord& problem, const Solution& solution);
/// Module 3 writes the counts as 1x,7i7; module 1's patches as 7i7 (`leading_blank` false).
void write_statistics(std::ostream& os, const CaseRecord& problem, const Solution& solution,
                      bool leading_blank = true);

/// The O = 5 table of quantities per contact element, §3.6.
void write_element_table(std::ostream& os, const CaseRecord& problem, const Solution& solution);
/// What the O = 5 element table needs beside the solution: control digits T, H, O, the approach
/// [mm], the friction coefficient and law, and the rigid slip per element (W/δq, T=1: shift).
struct ElementTableInputs {
  int t = 0, h = 0, o = 0;
  double pen = 0.0;
  double mu = 0.0;
  int friction_law = 0;
  std::span<const double> wx, wy;
};
void write_element_table(std::ostream& os, const ElementTableInputs& in, const Solution& solution);

}  // namespace rollcontact::format::report
