#pragma once
// The .inp lines both modules share (solver, friction, materials, damping, heat, subsurface),
// written as values followed by a `%` comment naming them: the building blocks of the module-3
// and module-1 case writers (inp_writer.cpp, inp_writer_module1.cpp).

#include <array>
#include <initializer_list>
#include <span>
#include <string>
#include <string_view>

#include "format/inp/case_record.hpp"

namespace rollcontact::format {

/// Shortest text that reads back to exactly `v` (the .inp reader converts with from_chars);
/// throws rollcontact::Error for a non-finite value.
std::string inp_real(double v);

/// Appends .inp lines to a string.
class InpLineWriter {
 public:
  InpLineWriter(std::string& out, int case_number) : out_(out), case_number_(case_number) {}

  /// One group: values then a `%` comment naming them (labels never reach optional fields).
  void group(const std::string& values, std::string_view names);
  /// An array, six values per line (the reader takes up to 50 words per line).
  void array(std::span<const double> v, std::string_view names);
  void int_array(std::span<const int> v);
  static std::string reals(std::initializer_list<double> v);

  /// Control word 3 `XHGIAOWR` (the same layout in both modules; H as 0/3, G = the solver
  /// method, R as 1/3: every case explicit) and, with X = 1, the debug word 4 `PSFLCIN READLN`.
  void control_word3_and_debug(const ControlDigits& d, int solver_method);
  /// The iteration line (line 5) and the G-specific line(s); `npot_max` > 0 appends NPOT_MAX
  /// (module 1).
  void solver_lines(const SolverSettings& s, int npot_max = 0);
  /// One line of law values (spec §4.1); `prefix` (V=1,2: ALPHA or SVF) goes first when given.
  void friction_values(int law, const FrictionValues& v, std::string_view prefix_name = {},
                       double prefix = 0.0);
  /// MEMDST MEM_S0 for the laws with memory (L=2,3,4,6).
  void friction_memory(const Friction& f);
  /// POISS GG, FLXZ (B=1) and the M-specific line.
  void material_lines(const Materials& m, int b, int material_model);
  void damping_line(const Damping& d);
  /// The two heat lines (H ≥ 1) and BETAPL with M=4.
  void heat_lines(const HeatParameters& h, int material_model);
  /// MATFIL_S OUTPUT_S and every block, ended by ISUBS = 0 (S ≥ 1).
  void subsurface(const Subsurface& s);

 protected:
  std::string& out_;
  int case_number_;
};

}  // namespace rollcontact::format
