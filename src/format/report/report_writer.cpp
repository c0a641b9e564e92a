// Frame of the CONTACT-style report (spec/outputs.md §3.1) and the order of the result blocks
// of a module-3 case (§3.2). The blocks themselves live in report_*.cpp.

#include "format/report/report_writer.hpp"

#include <fmt/format.h>

#include <ostream>
#include <sstream>
#include <string>

#include "format/report/number_format.hpp"
#include "format/report/report_internal.hpp"
#include "format/report/report_subsurface.hpp"
#include "format/report/report_values.hpp"
#include "rollcontact/version.hpp"

namespace rollcontact::format {

namespace report {

void line(std::ostream& os, std::string_view text) {
  os << text << '\n';
}

std::string a12(std::string_view label) {
  std::string s(label.substr(0, 12));
  s.resize(12, ' ');
  return s;
}

std::string sig(double v) {
  return fmt_sig(12, 4, 4, v);
}

std::string g12(double v) {
  return fortran_g(v, 12, 4);
}

}  // namespace report

namespace {

// Writes each line of `text` with `first` before the first line and blanks of the same width
// before the others, so multi-line messages stay readable and never start in column 1.
void write_message(std::ostream& os, const std::string& first, const std::string& text) {
  std::istringstream in(text);
  std::string l;
  bool start = true;
  while (std::getline(in, l)) {
    report::line(os, (start ? first : std::string(first.size(), ' ')) + l);
    start = false;
  }
  if (start) report::line(os, first);
}

}  // namespace

void write_report_banner(std::ostream& os) {
  constexpr std::size_t inner = 70;
  auto boxed = [&](const std::string& text) {
    std::string s = text.substr(0, inner);
    s.resize(inner, ' ');
    report::line(os, "   |" + s + "|");
  };
  const std::string rule = "   " + std::string(inner + 2, '-');
  report::line(os, rule);
  boxed("  rollcontact - rolling and sliding contact between elastic bodies");
  boxed("            CONTACT-compatible (Vollebregt & Kalker)");
  boxed("");
  boxed(std::string("  Version: ") + version_string);
  boxed("  Licensed under the Apache License, Version 2.0");
  boxed("");
  report::line(os, rule);
}

void write_case_header(std::ostream& os, const CaseRecord& problem) {
  std::string s = fmt::format(" Case{:6d}", problem.case_number);
  if (problem.result_element >= 1)
    s += fmt::format(", result element{:4d}", problem.result_element);
  report::line(os, "");
  report::line(os, s);
}

void write_case_report(std::ostream& os, const CaseRecord& problem, const Solution& solution) {
  const auto& d = problem.digits;
  write_case_header(os, problem);
  // Warnings and convergence problems go where CONTACT writes its trace lines.
  for (const auto& w : solution.warnings) write_message(os, " WARNING: ", w);
  if (!solution.solver.converged) {
    write_message(
        os, " WARNING: the solver did not converge: ",
        solution.solver.message.empty() ? std::string("(no details)") : solution.solver.message);
  }
  if (d.r >= 2 || d.o <= 0) return;

  if (d.o >= 2) report::write_parameter_blocks(os, problem, solution);
  report::write_force_block(os, problem, solution);
  if (d.o >= 2) {
    report::write_sensitivities(os, problem, solution);
    report::write_statistics(os, problem, solution);
  }
  if (d.o >= 3) {
    report::line(os, "");
    report::line(os, " FORM OF THE CONTACT, ADHESION AND SLIP-AREA`S:");
    write_element_division(os, solution, d.t, effective_kinematics(solution).chi);
  }
  if (d.o >= 5) report::write_element_table(os, problem, solution);
  report::write_subsurface_summaries(os, problem, solution);
}

void write_case_error(std::ostream& os, const CaseRecord& problem, const std::string& message) {
  write_case_header(os, problem);
  write_message(os, " ERROR: ", message);
}

void write_report_end(std::ostream& os) {
  // A framed line as in CONTACT's closing timing table: readers stop a case at `^|`.
  report::line(os, "");
  report::line(os, "|" + std::string(74, '-') + "|");
  report::line(os, " The rollcontact program ended successfully.");
}

}  // namespace rollcontact::format
