#include "batch/run_input.hpp"

#include <fmt/format.h>

#include <atomic>
#include <map>
#include <sstream>
#include <variant>

#include "batch/parallel.hpp"
#include "format/inp/inp_reader.hpp"
#include "format/inp/to_model.hpp"
#include "format/inp/to_wheelrail.hpp"
#include "format/report/json_writer.hpp"
#include "format/report/mat_writer.hpp"
#include "format/report/report_writer.hpp"
#include "format/report/subs_writer.hpp"
#include "format/text/atomic_file.hpp"
#include "format/toml/toml_case_reader.hpp"
#include "rollcontact/errors.hpp"
#include "rollcontact/model/validation.hpp"

namespace rollcontact::batch {

namespace {

/// Message prefix that lets a user find the case: "file:line: case N: " (parts when known).
std::string case_context(const format::CaseRecord& r) {
  std::string s;
  if (!r.source.file.empty()) {
    s += r.source.file;
    if (r.source.first_line > 0) s += ":" + std::to_string(r.source.first_line);
    s += ": ";
  }
  s += "case " + std::to_string(r.case_number) + ": ";
  return s;
}

}  // namespace

Solution solve_case(const format::CaseRecord& record, PatchSolver& solver) {
  const model::PatchProblem problem = format::to_patch_problem(record);
  try {
    return solver.solve(problem);
  } catch (const GeometryError& e) {
    // The geometry says what is wrong; the record knows where the case came from.
    throw GeometryError(case_context(record) + e.what());
  }
}

namespace {

/// The per-file state of a run: one solver per result element (REID) and module.
struct RunState {
  const RunOptions& options;
  std::map<int, PatchSolver> patch_solvers;
  std::map<int, WheelsetSolver> wheelset_solvers;
};

CaseOutcome solve_module3(const format::CaseRecord& problem, RunState& state) {
  CaseOutcome outcome;
  outcome.problem = problem;
  // find() first: with threads the solvers exist already and find is safe to call concurrently.
  auto it = state.patch_solvers.find(problem.result_element);
  if (it == state.patch_solvers.end())
    it = state.patch_solvers.try_emplace(problem.result_element, state.options.solve).first;
  try {
    if (!problem.source.case_error.empty()) throw ProblemError(problem.source.case_error);
    outcome.solution = solve_case(problem, it->second);
    outcome.solved = true;
    // The reader's consistency overrides are part of what the user must see for this case.
    auto& warnings = outcome.solution.warnings;
    warnings.insert(warnings.begin(), problem.source.warnings.begin(),
                    problem.source.warnings.end());
  } catch (const NotSupportedError& e) {
    outcome.error = e.what();
  } catch (const ProblemError& e) {
    outcome.error = e.what();
  }
  return outcome;
}

CaseOutcome solve_module1(const format::WheelRailRecord& record, RunState& state) {
  CaseOutcome outcome;
  outcome.problem = format::identity_record(record);
  outcome.wheel_rail = true;
  auto it = state.wheelset_solvers.find(record.result_element);
  if (it == state.wheelset_solvers.end())
    it = state.wheelset_solvers.try_emplace(record.result_element, state.options.solve).first;
  try {
    if (!record.source.case_error.empty()) throw ProblemError(record.source.case_error);
    const model::WheelRailProblem problem = format::to_wheelrail_problem(record);
    outcome.wheelrail = it->second.solve(problem);
    outcome.solved = true;
    auto& warnings = outcome.wheelrail.warnings;
    warnings.insert(warnings.begin(), record.source.warnings.begin(), record.source.warnings.end());
  } catch (const NotSupportedError& e) {
    outcome.error = e.what();
  } catch (const GeometryError& e) {
    outcome.error = case_context(outcome.problem) + e.what();
  } catch (const ProblemError& e) {
    outcome.error = e.what();
  }
  return outcome;
}

}  // namespace

namespace {

/// Solves case k (or marks it skipped), with the error naming file and line.
CaseOutcome solve_one(const format::InputCase& problem, RunState& state) {
  const auto* m3 = std::get_if<format::CaseRecord>(&problem);
  const auto* m1 = std::get_if<format::WheelRailRecord>(&problem);
  const format::CaseRecord identity = m3 ? *m3 : format::identity_record(*m1);
  CaseOutcome outcome;
  if (identity.digits.r == 2 || identity.digits.r == 3) {
    outcome.problem = identity;
    outcome.wheel_rail = m1 != nullptr;
    outcome.skipped = true;
    return outcome;
  }
  outcome = m3 ? solve_module3(*m3, state) : solve_module1(*m1, state);
  if (!outcome.error.empty()) {
    const format::SourceInfo& src = identity.source;
    if (!src.file.empty())
      outcome.error = src.file + ":" + std::to_string(src.first_line) + ": " + outcome.error;
  }
  return outcome;
}

/// The cases solved on `threads` workers: each sequence (module and result element) in its
/// order on one worker, the sequences in parallel. The solvers are made before the workers
/// start, so that each worker only touches its own.
std::vector<CaseOutcome> solve_in_parallel(const std::vector<format::InputCase>& problems,
                                           RunState& state, const RunOptions& options) {
  std::map<std::pair<int, int>, std::vector<std::size_t>> sequences;
  for (std::size_t k = 0; k < problems.size(); ++k) {
    const auto* m3 = std::get_if<format::CaseRecord>(&problems[k]);
    const int module = m3 ? 3 : 1;
    const int element =
        m3 ? m3->result_element : std::get<format::WheelRailRecord>(problems[k]).result_element;
    sequences[{module, element}].push_back(k);
    if (m3)
      state.patch_solvers.try_emplace(element, options.solve);
    else
      state.wheelset_solvers.try_emplace(element, options.solve);
  }
  std::vector<std::vector<std::size_t>> groups;
  for (auto& [key, indices] : sequences) groups.push_back(std::move(indices));
  std::vector<CaseOutcome> outcomes(problems.size());
  std::atomic<std::size_t> done{0};
  ParallelOptions parallel;
  parallel.threads = options.threads;
  parallel.schedule = Schedule::Dynamic;
  std::function<void(std::size_t)> progress;
  if (options.on_progress)
    progress = [&](std::size_t) { options.on_progress(done.load(), problems.size()); };
  parallel_for(
      groups.size(), parallel,
      [&](std::size_t, std::size_t g) {
        for (const std::size_t k : groups[g]) {
          outcomes[k] = solve_one(problems[k], state);
          ++done;
        }
      },
      progress);
  return outcomes;
}

}  // namespace

RunResult run_problems(const std::vector<format::InputCase>& problems,
                       const std::string& input_name, const std::filesystem::path& output_stem,
                       const RunOptions& options) {
  RunResult result;
  std::ostringstream report;
  format::write_report_banner(report);
  nlohmann::json cases = nlohmann::json::array();
  RunState state{options, {}, {}};
  std::vector<CaseOutcome> solved;
  if (options.threads > 1) solved = solve_in_parallel(problems, state, options);

  for (std::size_t k = 0; k < problems.size(); ++k) {
    const auto* m3 = std::get_if<format::CaseRecord>(&problems[k]);
    const auto* m1 = std::get_if<format::WheelRailRecord>(&problems[k]);
    const format::CaseRecord identity = m3 ? *m3 : format::identity_record(*m1);
    CaseOutcome outcome = solved.empty() ? solve_one(problems[k], state) : std::move(solved[k]);
    if (outcome.solved &&
        !(outcome.wheel_rail ? outcome.wheelrail.converged : outcome.solution.solver.converged))
      ++result.failed;
    if (!outcome.error.empty()) ++result.failed;
    if (outcome.solved && outcome.wheel_rail) {
      format::write_wheelrail_case_report(report, *m1, identity, outcome.wheelrail);
      if (m1->digits.a >= 1)
        format::write_wheelrail_mat_files(output_stem, *m1, identity, outcome.wheelrail);
      cases.push_back(format::wheelrail_case_to_json(identity, outcome.wheelrail));
    } else if (outcome.solved) {
      format::write_case_report(report, *m3, outcome.solution);
      format::write_subs_file(output_stem, *m3, outcome.solution);
      if (m3->digits.a >= 1) format::write_mat_file(output_stem, *m3, outcome.solution);
      cases.push_back(format::case_to_json(*m3, outcome.solution));
    } else if (!outcome.skipped) {
      format::write_case_error(report, identity, outcome.error);
      cases.push_back(format::case_error_to_json(identity, outcome.error));
    }
    if (options.on_case) options.on_case(outcome, k, problems.size());
    result.cases.push_back(std::move(outcome));
  }
  format::write_report_end(report);

  result.report_path = output_stem;
  result.report_path += ".out";
  result.json_path = output_stem;
  result.json_path += ".json";
  format::write_file_atomically(result.report_path, report.str());
  format::write_file_atomically(
      result.json_path, format::results_document(input_name, std::move(cases)).dump(2) + "\n");
  return result;
}

namespace {

std::vector<format::InputCase> read_problems(const std::filesystem::path& input) {
  // TOML case files (docs/case-files.md) by extension; everything else is CONTACT .inp.
  if (input.extension() == ".toml") return format::read_toml_input_file(input);
  return format::read_input_cases(input);
}

/// Every case's values pass the model's check before anything is solved or written, so that a
/// bad value anywhere is an input error naming file, line and case (exit 2, nothing written),
/// the same for .inp and TOML. Cases that cannot be converted (not supported, a per-case error)
/// are left to the run, which reports them case by case.
void validate_cases(const std::vector<format::InputCase>& problems) {
  for (const format::InputCase& c : problems) {
    const auto* m3 = std::get_if<format::CaseRecord>(&c);
    if (m3 == nullptr) continue;  // module 1: the reader checks its values
    const format::CaseRecord& r = *m3;
    if (!r.source.case_error.empty() || r.digits.r == 2 || r.digits.r == 3) continue;
    model::PatchProblem p;
    try {
      p = format::to_patch_problem(r);
    } catch (const Error&) {
      continue;
    }
    try {
      model::validate(p);
    } catch (const InvalidValueError& e) {
      throw InputError(r.source.file, r.source.first_line,
                       fmt::format("case {}: {}", r.case_number, e.what()));
    }
  }
}

}  // namespace

namespace {

/// The output folder exists (created when missing), is a folder, and takes a file — checked
/// before anything is solved, so that a wrong -o costs nothing and says why (exit 2).
void prepare_output_dir(const std::filesystem::path& dir) {
  namespace fs = std::filesystem;
  const fs::path shown = dir.empty() ? fs::path(".") : dir;
  std::error_code ec;
  if (fs::exists(shown, ec) && !fs::is_directory(shown, ec))
    throw InputError(shown.string(), 0, "the output folder is an existing file, not a folder");
  if (!dir.empty()) {
    fs::create_directories(dir, ec);
    if (ec) throw InputError(shown.string(), 0, "cannot create the output folder: " + ec.message());
  }
  try {
    format::write_file_atomically(shown / ".rollcontact-write-test", "");
  } catch (const Error&) {
    throw InputError(shown.string(), 0, "cannot write to the output folder");
  }
  fs::remove(shown / ".rollcontact-write-test", ec);
}

/// An output never replaces the input (an input named x.out or x.json would be overwritten by
/// the report of its own run).
void refuse_overwriting_input(const std::filesystem::path& input,
                              const std::filesystem::path& stem) {
  namespace fs = std::filesystem;
  for (const char* ext : {".out", ".json"}) {
    fs::path out = stem;
    out += ext;
    std::error_code ec;
    if (fs::exists(out, ec) && fs::equivalent(out, input, ec)) {
      throw InputError(input.string(), 0,
                       fmt::format("the output {} would replace this input; rename the input "
                                   "(e.g. to .inp) or write elsewhere with -o DIR",
                                   out.string()));
    }
  }
}

}  // namespace

RunResult run_input_file(const std::filesystem::path& input, const RunOptions& options) {
  const std::filesystem::path dir =
      options.output_dir.empty() ? input.parent_path() : options.output_dir;
  const std::filesystem::path stem = dir / input.stem();
  refuse_overwriting_input(input, stem);
  std::vector<format::InputCase> problems = read_problems(input);
  validate_cases(problems);
  prepare_output_dir(dir);
  RunResult result = run_problems(problems, input.filename().string(), stem, options);
  result.inputs = std::move(problems);
  return result;
}

}  // namespace rollcontact::batch
