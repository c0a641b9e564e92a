#pragma once
// Machine-readable results (spec/results-json.md).

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "format/inp/case_record.hpp"
#include "rollcontact/solution.hpp"
#include "rollcontact/wheelrail.hpp"

namespace rollcontact::format {

/// JSON of one solved module-3 case.
nlohmann::json case_to_json(const CaseRecord& problem, const Solution& solution);
/// A module-1 case: totals, vertical-force iterations and a `patches` array
/// (docs/results-json-wheelrail.md).
nlohmann::json wheelrail_case_to_json(const CaseRecord& identity,
                                      const WheelRailSolution& solution);
/// JSON of a case that failed ("error") with its message.
nlohmann::json case_error_to_json(const CaseRecord& problem, const std::string& message);
/// Top-level document.
nlohmann::json results_document(const std::string& input_name, nlohmann::json cases);

}  // namespace rollcontact::format
