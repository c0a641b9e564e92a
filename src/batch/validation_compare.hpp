#pragma once
// Comparison of one case of our report with CONTACT's reference report (`rollcontact validate`):
// every quantity the reference prints and the tolerance table knows is compared; quantities only
// we print are ignored.

#include <string>
#include <vector>

#include "batch/validation_tolerances.hpp"
#include "format/report/report_parser.hpp"

namespace rollcontact::batch {

enum class CaseStatus {
  Passed,        ///< every compared quantity within tolerance (or nothing to compare)
  Failed,        ///< solved but different, missing from our report, or not converged
  NotSupported,  ///< our run reported an error for it ("not supported yet: …", unreadable input)
};

/// One compared quantity.
struct QuantityComparison {
  std::string name;      ///< report key (`PMAX`, `patch 1/FN`)
  double ours = 0;       ///< NaN when missing from our report or overflowed
  double reference = 0;  ///< CONTACT's value
  double allowed = 0;    ///< allowed |ours − reference|
  bool passed = false;
  bool count = false;  ///< element count (not in the relative statistics)

  double difference() const;
  /// |ours − reference| / |reference|; 0 when both are 0, +inf when only the reference is 0.
  double relative_difference() const;
};

struct CaseComparison {
  int number = 0;
  CaseStatus status = CaseStatus::Passed;
  std::string reason;  ///< NotSupported: our error message; Failed: a short summary
  std::vector<QuantityComparison> quantities;
};

/// Compares `ours` (nullptr: the case is missing from our report) with `reference`.
CaseComparison compare_case(const format::ReportCase* ours, const format::ReportCase& reference,
                            const ToleranceTable& tolerances);

/// Compares every case of the reference with the case of the same number in `ours`.
std::vector<CaseComparison> compare_reports(const format::Report& ours,
                                            const format::Report& reference,
                                            const ToleranceTable& tolerances);

/// "passed", "failed" or "not supported".
const char* to_string(CaseStatus status);

}  // namespace rollcontact::batch
