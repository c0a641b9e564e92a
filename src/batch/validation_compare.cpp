#include "batch/validation_compare.hpp"

#include <cmath>
#include <limits>

namespace rollcontact::batch {

double QuantityComparison::difference() const {
  return std::abs(ours - reference);
}

double QuantityComparison::relative_difference() const {
  const double d = difference();
  if (std::isnan(d)) return std::numeric_limits<double>::infinity();
  if (reference != 0) return d / std::abs(reference);
  return d == 0 ? 0.0 : std::numeric_limits<double>::infinity();
}

namespace {

/// The force that scales the absolute part of the tolerances: FN of the case (module 3), the
/// vertical total FZ(TR) (module 1); 0 when the reference prints neither (O=0).
double normal_force(const format::ReportCase& reference) {
  if (auto fn = reference.value("FN"); fn && !std::isnan(*fn)) return *fn;
  if (auto fz = reference.value("FZ(TR)"); fz && !std::isnan(*fz)) return *fz;
  return 0;
}

}  // namespace

CaseComparison compare_case(const format::ReportCase* ours, const format::ReportCase& reference,
                            const ToleranceTable& tolerances) {
  CaseComparison result;
  result.number = reference.number;
  if (ours != nullptr && !ours->error.empty()) {
    result.status = CaseStatus::NotSupported;
    result.reason = ours->error;
    return result;
  }

  const double fn = normal_force(reference);
  int failed = 0;
  for (const auto& [key, ref] : reference.values) {
    const Tolerance* tol = tolerances.find(key);
    // Overflowed reference fields (asterisks) carry no number to compare with.
    if (tol == nullptr || std::isnan(ref)) continue;
    QuantityComparison q;
    q.name = key;
    q.reference = ref;
    q.count = tol->count;
    q.allowed = allowed_difference(*tol, ref, fn);
    const auto mine = ours != nullptr ? ours->value(key) : std::nullopt;
    q.ours = mine ? *mine : std::numeric_limits<double>::quiet_NaN();
    q.passed = !std::isnan(q.ours) && q.difference() <= q.allowed;
    if (!q.passed) ++failed;
    result.quantities.push_back(std::move(q));
  }

  if (ours == nullptr && !result.quantities.empty()) {
    result.status = CaseStatus::Failed;
    result.reason = "missing from our report";
  } else if (result.quantities.empty()) {
    // O=0 (or R=2,3, which we do not print at all): the reference has no numbers either.
    result.reason = "nothing to compare";
  } else if (failed > 0) {
    result.status = CaseStatus::Failed;
    std::string names;
    for (const auto& q : result.quantities)
      if (!q.passed) names += (names.empty() ? "" : ", ") + q.name;
    result.reason = "outside tolerance: " + names;
  }
  return result;
}

std::vector<CaseComparison> compare_reports(const format::Report& ours,
                                            const format::Report& reference,
                                            const ToleranceTable& tolerances) {
  std::vector<CaseComparison> out;
  out.reserve(reference.cases.size());
  for (const auto& ref : reference.cases)
    out.push_back(compare_case(ours.find(ref.number), ref, tolerances));
  // A reference that stops early (truncated, or garbage after the first cases) must not pass
  // by comparing fewer cases: every case we solved that it lacks is a failure.
  for (const auto& case_ours : ours.cases)
    if (reference.find(case_ours.number) == nullptr) {
      CaseComparison missing;
      missing.number = case_ours.number;
      missing.status = CaseStatus::Failed;
      missing.reason = "case missing from the reference report (truncated or unreadable there)";
      out.push_back(std::move(missing));
    }
  return out;
}

const char* to_string(CaseStatus status) {
  switch (status) {
    case CaseStatus::Passed:
      return "passed";
    case CaseStatus::Failed:
      return "failed";
    case CaseStatus::NotSupported:
      return "not supported";
  }
  return "?";
}

}  // namespace rollcontact::batch
