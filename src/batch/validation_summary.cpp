#include "batch/validation_summary.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <utility>

namespace rollcontact::batch {

namespace {

std::string format_worst(const WorstDifference& w, const char* number_format) {
  if (w.value < 0) return "-";
  if (w.value == 0) return "0";
  if (std::isinf(w.value)) return fmt::format("inf (c{} {})", w.case_number, w.quantity);
  return fmt::format(fmt::runtime(number_format), w.value) +
         fmt::format(" (c{} {})", w.case_number, w.quantity);
}

std::string format_relative(const WorstDifference& w) {
  return format_worst(w, "{:.1e}");
}
std::string format_share(const WorstDifference& w) {
  return format_worst(w, "{:.2f}");
}

struct Row {
  std::string example;
  int cases = 0, passed = 0, failed = 0, not_supported = 0;
  std::string worst;     ///< the largest relative difference
  std::string tightest;  ///< the largest share of a tolerance
};

/// `value (cN quantity) (example)` for the total row; the example only where something differs.
std::string with_example(const std::string& formatted, const WorstDifference& w,
                         const std::string& example) {
  return w.value > 0 ? fmt::format("{} ({})", formatted, example) : formatted;
}

std::vector<Row> table_rows(const std::vector<ExampleResult>& results) {
  std::vector<Row> rows;
  Row total{"total", 0, 0, 0, 0, "-", "-"};
  WorstDifference worst_total, tightest_total;
  for (const auto& r : results) {
    const WorstDifference worst = r.worst();
    const WorstDifference tightest = r.closest_to_tolerance();
    Row row{r.name,
            static_cast<int>(r.cases.size()),
            r.count(CaseStatus::Passed),
            r.count(CaseStatus::Failed),
            r.count(CaseStatus::NotSupported),
            format_relative(worst),
            format_share(tightest)};
    if (r.cases.empty() && !r.run_error.empty()) row.worst = "error: " + r.run_error;
    total.cases += row.cases;
    total.passed += row.passed;
    total.failed += row.failed;
    total.not_supported += row.not_supported;
    if (worst.value > worst_total.value) {
      worst_total = worst;
      total.worst = with_example(format_relative(worst), worst, r.name);
    }
    if (tightest.value > tightest_total.value) {
      tightest_total = tightest;
      total.tightest = with_example(format_share(tightest), tightest, r.name);
    }
    rows.push_back(std::move(row));
  }
  rows.push_back(std::move(total));
  return rows;
}

}  // namespace

std::string strip_location(const std::string& message) {
  // `path/file.inp:35: text` → `text`: the first `:<digits>: ` ends a location; the run may
  // prefix one location to another (`a.inp:2046: a.inp:2053: text`), so strip all leading ones.
  std::string text = message;
  for (bool stripped = true; stripped;) {
    stripped = false;
    for (std::size_t i = text.find(':'); i != std::string::npos; i = text.find(':', i + 1)) {
      std::size_t j = i + 1;
      while (j < text.size() && std::isdigit(static_cast<unsigned char>(text[j]))) ++j;
      if (j > i + 1 && text.compare(j, 2, ": ") == 0) {
        text = text.substr(j + 2);
        stripped = true;
        break;
      }
    }
  }
  return text;
}

std::string format_case_ranges(std::vector<int> numbers) {
  std::sort(numbers.begin(), numbers.end());
  std::string out;
  for (std::size_t i = 0; i < numbers.size();) {
    std::size_t j = i;
    while (j + 1 < numbers.size() && numbers[j + 1] == numbers[j] + 1) ++j;
    if (!out.empty()) out += ", ";
    out += j == i ? fmt::format("c{}", numbers[i]) : fmt::format("c{}-c{}", numbers[i], numbers[j]);
    i = j + 1;
  }
  return out;
}

std::string format_validation_table(const std::vector<ExampleResult>& results, TableStyle style) {
  const auto rows = table_rows(results);
  std::string out;
  if (style == TableStyle::Markdown) {
    out +=
        "| Example | Cases | Passed | Failed | Not supported | Worst relative difference | "
        "Most of a tolerance used |\n";
    out += "|---|---:|---:|---:|---:|---|---|\n";
    for (const auto& r : rows) {
      const bool total = &r == &rows.back();
      const std::string name = total ? "**total**" : "`" + r.example + "`";
      out += fmt::format("| {} | {} | {} | {} | {} | {} | {} |\n", name, r.cases, r.passed,
                         r.failed, r.not_supported, r.worst, r.tightest);
    }
    return out;
  }
  std::size_t width = 7, worst_width = 25;
  for (const auto& r : rows) {
    width = std::max(width, r.example.size());
    worst_width = std::max(worst_width, r.worst.size());
  }
  const auto line = [&](const std::string& a, const std::string& b, const std::string& c,
                        const std::string& d, const std::string& e, const std::string& f,
                        const std::string& g) {
    out += fmt::format("{:<{}}  {:>5}  {:>6}  {:>6}  {:>13}  {:<{}}  {}\n", a, width, b, c, d, e, f,
                       worst_width, g);
  };
  line("example", "cases", "passed", "failed", "not supported", "worst relative difference",
       "most of a tolerance used");
  for (const auto& r : rows) {
    if (&r == &rows.back()) out += std::string(width + worst_width + 66, '-') + "\n";
    line(r.example, std::to_string(r.cases), std::to_string(r.passed), std::to_string(r.failed),
         std::to_string(r.not_supported), r.worst, r.tightest);
  }
  return out;
}

std::string format_case_reasons(const std::vector<ExampleResult>& results, TableStyle style) {
  std::string out;
  for (const CaseStatus status : {CaseStatus::Failed, CaseStatus::NotSupported}) {
    std::string section;
    for (const auto& r : results) {
      // Reasons in the order of their first case.
      std::vector<std::pair<std::string, std::vector<int>>> by_reason;
      for (const auto& c : r.cases) {
        if (c.status != status) continue;
        const std::string reason = strip_location(c.reason);
        auto it = std::find_if(by_reason.begin(), by_reason.end(),
                               [&](const auto& g) { return g.first == reason; });
        if (it == by_reason.end()) it = by_reason.insert(by_reason.end(), {reason, {}});
        it->second.push_back(c.number);
      }
      for (auto& [reason, numbers] : by_reason) {
        const std::string cases = format_case_ranges(numbers);
        section += style == TableStyle::Markdown
                       ? fmt::format("- `{}` {}: {}\n", r.name, cases, reason)
                       : fmt::format("  {} {}: {}\n", r.name, cases, reason);
      }
    }
    if (section.empty()) continue;
    const char* title = status == CaseStatus::Failed ? "Failed" : "Not supported";
    out += style == TableStyle::Markdown ? fmt::format("\n### {}\n\n", title)
                                         : fmt::format("\n{}:\n", title);
    out += section;
  }
  return out;
}

std::string format_case_details(const ExampleResult& result) {
  std::string out = fmt::format("{} ({:.1f} s)\n", result.name, result.seconds);
  for (const auto& c : result.cases) {
    out += fmt::format("  c{:<4} {}", c.number, to_string(c.status));
    if (!c.reason.empty()) out += ": " + strip_location(c.reason);
    out += '\n';
    for (const auto& q : c.quantities) {
      out += fmt::format(
          "    {:<16} ours {:>12.6g}  ref {:>12.6g}  diff {:>9.2e}  allowed {:>9.2e}  {}\n", q.name,
          q.ours, q.reference, q.difference(), q.allowed, q.passed ? "ok" : "FAIL");
    }
  }
  return out;
}

std::string format_validation_markdown(const std::vector<ExampleResult>& results,
                                       const std::string& folder) {
  std::string out = "# Validation against CONTACT\n\n";
  out += fmt::format(
      "Produced by `rollcontact validate {}`: every `.inp` with a `.ref_out` is solved and each "
      "case's report is compared with CONTACT's reference (tolerances: "
      "`src/batch/validation_tolerances.cpp`). The worst relative difference is over all compared "
      "quantities except element counts; the most of a tolerance used is the largest "
      "|ours − reference| / allowed over all of them (above 1 fails).\n\n",
      folder);
  out += format_validation_table(results, TableStyle::Markdown);
  out += format_case_reasons(results, TableStyle::Markdown);
  return out;
}

}  // namespace rollcontact::batch
