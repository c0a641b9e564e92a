#include "batch/validation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <limits>
#include <mutex>
#include <nlohmann/json.hpp>

#include "batch/parallel.hpp"
#include "batch/run_input.hpp"
#include "batch/temporary_folder.hpp"
#include "format/report/report_parser.hpp"
#include "rollcontact/errors.hpp"

namespace rollcontact::batch {

int ExampleResult::count(CaseStatus status) const {
  return static_cast<int>(
      std::count_if(cases.begin(), cases.end(), [&](const auto& c) { return c.status == status; }));
}

WorstDifference ExampleResult::worst() const {
  WorstDifference w;
  for (const auto& c : cases)
    for (const auto& q : c.quantities) {
      // Counts have an absolute tolerance; a zero reference has no relative difference.
      if (q.count || q.reference == 0) continue;
      const double r = q.relative_difference();
      if (r > w.value) w = {r, c.number, q.name};
    }
  return w;
}

WorstDifference ExampleResult::closest_to_tolerance() const {
  WorstDifference w;
  for (const auto& c : cases)
    for (const auto& q : c.quantities) {
      const double d = q.difference();
      // A missing value (NaN) uses all of any tolerance; allowed 0 admits equality only.
      const double share = std::isnan(d)   ? std::numeric_limits<double>::infinity()
                           : q.allowed > 0 ? d / q.allowed
                           : d == 0        ? 0.0
                                           : std::numeric_limits<double>::infinity();
      if (share > w.value) w = {share, c.number, q.name};
    }
  return w;
}

namespace {

/// A new, empty folder under the system's temporary directory.
/// Every case of the reference with the same status and reason (our run produced no report).
void mark_all(ExampleResult& result, const format::Report& reference, CaseStatus status,
              const std::string& reason) {
  result.cases.clear();
  for (const auto& ref : reference.cases)
    result.cases.push_back(CaseComparison{ref.number, status, reason, {}});
}

/// Convergence is not part of CONTACT's report layout; our JSON has it per case
/// (spec/results-json.md: "status": "not_converged"). A missing or unreadable JSON changes nothing.
void mark_not_converged(ExampleResult& result, const std::filesystem::path& json_path) {
  if (json_path.empty()) return;
  std::ifstream in(json_path);
  if (!in) return;
  const auto doc = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
  if (!doc.is_object() || !doc.contains("cases") || !doc["cases"].is_array()) return;
  for (const auto& c : doc["cases"]) {
    if (!c.is_object() || c.value("status", std::string()) != "not_converged") continue;
    const int number = c.value("case", 0);
    for (auto& cmp : result.cases)
      if (cmp.number == number && cmp.status == CaseStatus::Passed) {
        cmp.status = CaseStatus::Failed;
        // Only Passed cases get here: the numbers agree, but a non-converged solution must not
        // be trusted (the run's exit status says so too).
        cmp.reason =
            "not converged (values within tolerance): " + c.value("message", std::string());
      }
  }
}

}  // namespace

std::vector<ExampleFiles> find_examples(const std::filesystem::path& dir) {
  std::vector<ExampleFiles> out;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    const auto& p = entry.path();
    if (p.extension() != ".inp" || !entry.is_regular_file()) continue;
    auto ref = p;
    ref.replace_extension(".ref_out");
    if (std::filesystem::is_regular_file(ref)) out.push_back({p.stem().string(), p, ref});
  }
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
  return out;
}

ExampleRun run_example_in_process(const ExampleFiles& example,
                                  const std::filesystem::path& output_dir,
                                  const SolveOptions& solve, bool solve_unvalidated) {
  ExampleRun run;
  RunOptions options;
  options.output_dir = output_dir;
  options.solve = solve;
  options.solve_unvalidated = solve_unvalidated;
  try {
    const RunResult result = run_input_file(example.input, options);
    run.report = result.report_path;
    run.json = result.json_path;
  } catch (const InputError& e) {
    run.input_error = e.what();
  } catch (const std::exception& e) {
    run.failure = std::string("internal error: ") + e.what();
  }
  return run;
}

ExampleResult validate_example(const ExampleFiles& example, const std::filesystem::path& output_dir,
                               const ValidationOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  ExampleResult result;
  result.name = example.name;
  format::Report reference;
  try {
    reference = format::parse_report_file(example.reference);
  } catch (const std::exception& e) {
    result.run_error = e.what();  // no cases: counted as a failure by any_failed()
    return result;
  }
  if (reference.cases.empty()) {
    // A reference without one parsable case would otherwise compare nothing and pass.
    result.run_error = example.reference.string() + ": no case could be read from this report";
    return result;
  }

  ExampleRun run;
  try {
    run = options.runner ? options.runner(example, output_dir)
                         : run_example_in_process(example, output_dir, options.solve,
                                                  options.solve_unvalidated);
    if (run.input_error.empty() && run.failure.empty() && run.report.empty())
      run.failure = "the run wrote no report";
  } catch (const std::exception& e) {
    run.failure = std::string("internal error: ") + e.what();
  }

  if (!run.input_error.empty()) {
    // An example the reader refuses (file:line in the message) compares nothing: a failure,
    // not a feature still missing.
    result.run_error = "input error: " + run.input_error;
    mark_all(result, reference, CaseStatus::Failed, result.run_error);
  } else if (!run.failure.empty()) {
    result.run_error = run.failure;
    mark_all(result, reference, CaseStatus::Failed, result.run_error);
  } else {
    try {
      result.cases = compare_reports(
          format::parse_report_file(run.report), reference,
          tolerances_for_example(options.tolerances, example.input.stem().string()));
      mark_not_converged(result, run.json);
    } catch (const std::exception& e) {
      result.run_error = e.what();
      mark_all(result, reference, CaseStatus::Failed, result.run_error);
    }
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

std::vector<ExampleResult> validate_folder(const std::filesystem::path& dir,
                                           const ValidationOptions& options) {
  const auto examples = find_examples(dir);
  if (examples.empty())
    throw InputError(dir.string(), 0, "no .inp file with a matching .ref_out reference report");

  const bool temporary = options.output_dir.empty();
  const auto output_dir =
      temporary ? new_temporary_folder("rollcontact-validate") : options.output_dir;

  std::vector<ExampleResult> results(examples.size());
  std::mutex report_mutex;  // serialises on_example and the bookkeeping of finished examples
  std::size_t done = 0;
  parallel_for(examples.size(), {options.jobs, Schedule::Dynamic},
               [&](std::size_t /*worker*/, std::size_t k) {
                 ExampleResult r = validate_example(examples[k], output_dir, options);
                 const std::lock_guard<std::mutex> lock(report_mutex);
                 results[k] = std::move(r);
                 ++done;
                 try {
                   if (options.on_example) options.on_example(results[k], done, examples.size());
                 } catch (const std::exception&) {
                   // Progress output is optional (e.g. a closed stderr); the validation goes on.
                 }
               });

  if (temporary) {
    std::error_code ignored;  // a leftover temporary folder is not worth failing the validation
    std::filesystem::remove_all(output_dir, ignored);
  }
  return results;
}

int compared_cases(const std::vector<ExampleResult>& results) {
  int n = 0;
  for (const ExampleResult& r : results)
    n += r.count(CaseStatus::Passed) + r.count(CaseStatus::Failed);
  return n;
}

bool any_failed(const std::vector<ExampleResult>& results) {
  if (compared_cases(results) == 0) return true;  // a validation that compared nothing
  return std::any_of(results.begin(), results.end(), [](const ExampleResult& r) {
    return r.count(CaseStatus::Failed) > 0 || (r.cases.empty() && !r.run_error.empty());
  });
}

}  // namespace rollcontact::batch
