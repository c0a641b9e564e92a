#pragma once
// The CONTACT-style text report (.out), spec/outputs.md §3.

#include <iosfwd>
#include <string>

#include "format/inp/case_record.hpp"
#include "format/inp/wheelrail_record.hpp"
#include "rollcontact/solution.hpp"
#include "rollcontact/wheelrail.hpp"

namespace rollcontact::format {

/// Banner at the top of a report.
void write_report_banner(std::ostream& os);
/// All blocks of one solved case at the level of problem.digits.o.
void write_case_report(std::ostream& os, const CaseRecord& problem, const Solution& solution);
/// A case that could not be solved (error / not supported): header and message.
void write_case_error(std::ostream& os, const CaseRecord& problem, const std::string& message);
/// All blocks of one solved wheel/rail (module 1) case, spec/outputs.md §3.8. `identity` is the
/// case's number, result element and digits as a module-3 record (for the shared blocks).
void write_wheelrail_case_report(std::ostream& os, const WheelRailRecord& record,
                                 const CaseRecord& identity, const WheelRailSolution& solution);
/// Closing lines.
void write_report_end(std::ostream& os);

/// The element-division picture (`.` exterior, `*` adhesion, `S` slip, `|` plastic), §3.5.
void write_element_division(std::ostream& os, const Solution& solution, int tangential_digit);
/// Same, with the rolling direction chi [rad] printed under the picture for T = 2, 3.
void write_element_division(std::ostream& os, const Solution& solution, int tangential_digit,
                            double chi);

/// The ` Case     n` line (preceded by a blank line), with the result element when REID >= 1.
void write_case_header(std::ostream& os, const CaseRecord& problem);

}  // namespace rollcontact::format
