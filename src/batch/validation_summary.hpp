#pragma once
// Text and Markdown presentation of `rollcontact validate` results: the per-example table
// (example, cases, passed, failed, not supported, worst relative difference), the reasons of
// not-supported and failed cases, and the per-case details of --verbose.

#include <string>
#include <vector>

#include "batch/validation.hpp"

namespace rollcontact::batch {

enum class TableStyle { Text, Markdown };

/// The table with one row per example and a total row.
std::string format_validation_table(const std::vector<ExampleResult>& results, TableStyle style);

/// Not-supported and failed cases grouped by example and reason, case numbers as ranges
/// (`cattaneo c2: not supported yet: tangential problem T=1`). Empty when there are none.
std::string format_case_reasons(const std::vector<ExampleResult>& results, TableStyle style);

/// Every case of one example with each compared quantity: ours, reference, difference, allowed.
std::string format_case_details(const ExampleResult& result);

/// A Markdown document: a title, the table and the reasons (`rollcontact validate --output`).
std::string format_validation_markdown(const std::vector<ExampleResult>& results,
                                       const std::string& folder);

/// "c2", "c2–c6, c9": sorted case numbers compressed to ranges.
std::string format_case_ranges(std::vector<int> numbers);

/// A message without its leading `file:line: ` location, so equal reasons group together.
std::string strip_location(const std::string& message);

}  // namespace rollcontact::batch
