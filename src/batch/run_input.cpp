#include "batch/run_input.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <atomic>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <set>
#include <sstream>
#include <variant>

#include "batch/in_order.hpp"
#include "batch/parallel.hpp"
#include "batch/run_files.hpp"
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

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// Adds a solved case's wall time to the split: its set-up as the solver measured it, the rest
/// as solve time.
void add_case_time(const CaseOutcome& c, double seconds, RunTiming& timing) {
  // Wheel/rail: the profiles' placement, contact search and patch set-up of every iterate, and
  // the patch problems' own set-up (kernels, operators, plans).
  const double setup = !c.solved ? 0.0
                       : c.wheel_rail
                           ? c.wheelrail.geometry_seconds + c.wheelrail.patch_setup_seconds
                           : c.solution.solver.setup_seconds;
  timing.setup += setup;
  timing.solve += seconds - setup;
}

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
    const model::WheelRailProblem problem =
        format::to_wheelrail_problem(record, state.options.solve_unvalidated);
    outcome.wheelrail = it->second.solve(problem);
    outcome.solved = true;
    auto& warnings = outcome.wheelrail.warnings;
    warnings.insert(warnings.begin(), record.source.warnings.begin(), record.source.warnings.end());
  } catch (const NotValidatedError& e) {
    outcome.error = e.what();
    outcome.refused_unvalidated = true;
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
    // Every message names the case's file and line once (geometry errors carry them already).
    const format::SourceInfo& src = identity.source;
    const std::string where = src.file + ":" + std::to_string(src.first_line) + ": ";
    if (!src.file.empty() && outcome.error.rfind(where, 0) != 0)
      outcome.error = where + outcome.error;
  }
  return outcome;
}

/// The sequences of a run: the case indices of each module and result element, in order.
/// Sequences are independent of each other; the cases of one depend on their predecessors.
std::vector<std::vector<std::size_t>> sequence_groups(
    const std::vector<format::InputCase>& problems) {
  std::map<std::pair<int, int>, std::vector<std::size_t>> sequences;
  for (std::size_t k = 0; k < problems.size(); ++k) {
    const auto* m3 = std::get_if<format::CaseRecord>(&problems[k]);
    const int module = m3 ? 3 : 1;
    const int element =
        m3 ? m3->result_element : std::get<format::WheelRailRecord>(problems[k]).result_element;
    sequences[{module, element}].push_back(k);
  }
  std::vector<std::vector<std::size_t>> groups;
  for (auto& [key, indices] : sequences) groups.push_back(std::move(indices));
  return groups;
}

}  // namespace

namespace {

/// What one case contributes to the run's report and JSON (its side files are written here).
CaseOutput render_case(const format::InputCase& input, const CaseOutcome& outcome,
                       const std::filesystem::path& output_stem) {
  const auto* m3 = std::get_if<format::CaseRecord>(&input);
  const auto* m1 = std::get_if<format::WheelRailRecord>(&input);
  CaseOutput out;
  std::ostringstream report;
  if (outcome.solved &&
      !(outcome.wheel_rail ? outcome.wheelrail.converged : outcome.solution.solver.converged))
    out.failed = 1;
  if (!outcome.error.empty()) out.failed = 1;
  if (outcome.solved && outcome.wheel_rail) {
    format::write_wheelrail_case_report(report, *m1, outcome.problem, outcome.wheelrail);
    if (m1->digits.a >= 1)
      format::write_wheelrail_mat_files(output_stem, *m1, outcome.problem, outcome.wheelrail);
    format::write_wheelrail_subs_files(output_stem, *m1, outcome.problem, outcome.wheelrail);
    out.json = format::wheelrail_case_to_json(outcome.problem, outcome.wheelrail).dump(2);
  } else if (outcome.solved) {
    format::write_case_report(report, *m3, outcome.solution);
    format::write_subs_file(output_stem, *m3, outcome.solution);
    if (m3->digits.a >= 1) format::write_mat_file(output_stem, *m3, outcome.solution);
    out.json = format::case_to_json(*m3, outcome.solution).dump(2);
  } else if (!outcome.skipped) {
    format::write_case_error(report, outcome.problem, outcome.error);
    out.json = format::case_error_to_json(outcome.problem, outcome.error).dump(2);
  }
  out.report = report.str();
  return out;
}

/// Frees a vector's memory (clear() keeps the capacity).
template <class T>
void release(std::vector<T>& v) {
  std::vector<T>().swap(v);
}

/// The per-element fields of a solution, released; totals, statistics and reports stay.
void release_fields(Solution& s) {
  for (std::vector<double>* v :
       {&s.h, &s.pn, &s.px, &s.py, &s.un, &s.ux, &s.uy, &s.sx, &s.sy, &s.wx, &s.wy, &s.mu,
        &s.yield_limit, &s.plastic_x, &s.plastic_y, &s.plastic_accumulated, &s.temp1, &s.temp2})
    release(*v);
  release(s.state);
  release(s.subsurface);
}

/// RunOptions::keep_fields = false: what a case's outcome keeps once its outputs are made.
void release_fields(CaseOutcome& outcome) {
  release_fields(outcome.solution);
  for (WheelRailPatch& patch : outcome.wheelrail.patches) release_fields(patch.solution);
}

/// The next case's outputs into the run's files.
void add_output(RunFilesWriter& files, const CaseOutput& o, RunResult& result) {
  files.add(o);
  result.failed += o.failed;
}

/// Counts a finished case and keeps its outcome where the options ask for it.
void keep_outcome(CaseOutcome outcome, const RunOptions& options, RunResult& result) {
  ++result.case_count;
  if (!outcome.solved && outcome.refused_unvalidated) ++result.refused_unvalidated;
  if (options.keep_outcomes) result.cases.push_back(std::move(outcome));
}

/// A case solved on a worker, with its outputs, waiting for the cases before it.
struct SolvedCase {
  CaseOutcome outcome;
  CaseOutput output;
  double output_seconds = 0.0;  ///< making `output` (and the case's side files)
};

/// The cases solved on `threads` workers: each sequence (module and result element) in its
/// order on one worker, the sequences in parallel. The solvers are made before the workers
/// start, so that each worker only touches its own. Each worker makes its cases' outputs and,
/// without keep_fields, releases their fields; a finished case then goes to the run's files,
/// on_case and `result` in case order as soon as every case before it has (InOrder), so that
/// the run holds only the cases waiting for an earlier one, not all of them until the end.
void run_in_parallel(const std::vector<format::InputCase>& problems, RunState& state,
                     const RunOptions& options, const std::filesystem::path& output_stem,
                     RunFilesWriter& files, RunResult& result) {
  for (const format::InputCase& c : problems) {
    if (const auto* m3 = std::get_if<format::CaseRecord>(&c))
      state.patch_solvers.try_emplace(m3->result_element, options.solve);
    else
      state.wheelset_solvers.try_emplace(std::get<format::WheelRailRecord>(c).result_element,
                                         options.solve);
  }
  InOrder<SolvedCase> in_order([&](std::size_t k, SolvedCase& c) {
    const auto start = std::chrono::steady_clock::now();
    add_case_time(c.outcome, 0.0, result.timing);  // the set-up out of the workers' wall time
    add_output(files, c.output, result);
    c.output = CaseOutput{};
    if (options.on_case) options.on_case(c.outcome, k, problems.size());
    keep_outcome(std::move(c.outcome), options, result);
    result.timing.output += c.output_seconds + seconds_since(start);
  });
  const std::vector<std::vector<std::size_t>> groups = sequence_groups(problems);
  std::atomic<std::size_t> done{0};
  ParallelOptions parallel;
  parallel.threads = options.threads;
  parallel.schedule = Schedule::Dynamic;
  std::function<void(std::size_t)> progress;
  if (options.on_progress)
    progress = [&](std::size_t) { options.on_progress(done.load(), problems.size()); };
  const auto start = std::chrono::steady_clock::now();
  parallel_for(
      groups.size(), parallel,
      [&](std::size_t, std::size_t g) {
        for (const std::size_t k : groups[g]) {
          SolvedCase c;
          c.outcome = solve_one(problems[k], state);
          const auto rendered = std::chrono::steady_clock::now();
          c.output = render_case(problems[k], c.outcome, output_stem);
          if (!options.keep_fields) release_fields(c.outcome);
          c.output_seconds = seconds_since(rendered);
          in_order.add(k, std::move(c));
          ++done;
        }
      },
      progress);
  if (in_order.handed_on() != problems.size())
    throw Error("internal: a threaded run left cases unwritten");
  // The workers' wall time (what they spent on outputs is in `output` as well).
  result.timing.solve += seconds_since(start);
}

/// The run's files complete and in place.
void finish_files(RunFilesWriter& files, RunResult& result) {
  files.finish();
  result.report_path = files.report_path();
  result.json_path = files.json_path();
}

/// Length-prefixed fields of the case outputs one process sends the root.
void append_field(std::string& out, const std::string& field) {
  const std::uint64_t n = field.size();
  out.append(reinterpret_cast<const char*>(&n), sizeof n);
  out.append(field);
}

std::string take_field(const std::string& in, std::size_t& pos) {
  std::uint64_t n = 0;
  if (pos + sizeof n > in.size()) throw Error("truncated case output from another process");
  std::memcpy(&n, in.data() + pos, sizeof n);
  pos += sizeof n;
  if (pos + n > in.size()) throw Error("truncated case output from another process");
  std::string field = in.substr(pos, n);
  pos += n;
  return field;
}

/// The run spread over the processes of options.distribution: a sequence at a time to
/// whichever process is free; the root assembles the outputs in case order.
RunResult run_distributed(const std::vector<format::InputCase>& problems,
                          const std::string& input_name, const std::filesystem::path& output_stem,
                          const RunOptions& options) {
  Distribution& d = *options.distribution;
  const std::vector<std::vector<std::size_t>> groups = sequence_groups(problems);
  RunState state{options, {}, {}};
  const std::vector<std::string> blobs = d.map_gather(groups.size(), 1, [&](std::size_t g) {
    std::string out;
    for (const std::size_t k : groups[g]) {
      const CaseOutput o = render_case(problems[k], solve_one(problems[k], state), output_stem);
      append_field(out, std::to_string(k));
      append_field(out, std::to_string(o.failed));
      append_field(out, o.report);
      append_field(out, o.json);
    }
    return out;
  });
  RunResult result;
  if (!d.is_root()) return result;
  // The processes answer per sequence, not in case order: the root orders the outputs.
  std::vector<CaseOutput> outputs(problems.size());
  for (const std::string& blob : blobs) {
    for (std::size_t pos = 0; pos < blob.size();) {
      const std::size_t k = std::stoul(take_field(blob, pos));
      CaseOutput& o = outputs.at(k);
      o.failed = std::stoi(take_field(blob, pos));
      o.report = take_field(blob, pos);
      o.json = take_field(blob, pos);
    }
  }
  RunFilesWriter files(output_stem, input_name);
  for (const CaseOutput& o : outputs) add_output(files, o, result);
  result.case_count = problems.size();
  finish_files(files, result);
  return result;
}

}  // namespace

RunResult run_problems(const std::vector<format::InputCase>& problems,
                       const std::string& input_name, const std::filesystem::path& output_stem,
                       const RunOptions& options) {
  if (options.distribution != nullptr && options.distribution->size() > 1)
    return run_distributed(problems, input_name, output_stem, options);
  RunResult result;
  RunState state{options, {}, {}};
  // Each case's report and results go to the files as it finishes (RunFilesWriter).
  RunFilesWriter files(output_stem, input_name);
  if (options.threads > 1) {
    run_in_parallel(problems, state, options, output_stem, files, result);
  } else {
    for (std::size_t k = 0; k < problems.size(); ++k) {
      auto start = std::chrono::steady_clock::now();
      CaseOutcome outcome = solve_one(problems[k], state);
      add_case_time(outcome, seconds_since(start), result.timing);
      start = std::chrono::steady_clock::now();
      add_output(files, render_case(problems[k], outcome, output_stem), result);
      result.timing.output += seconds_since(start);
      if (options.on_case) options.on_case(outcome, k, problems.size());
      if (!options.keep_fields) release_fields(outcome);
      keep_outcome(std::move(outcome), options, result);
    }
  }
  const auto start = std::chrono::steady_clock::now();
  finish_files(files, result);
  result.timing.output += seconds_since(start);
  return result;
}

std::vector<format::InputCase> read_input_file(const std::filesystem::path& input) {
  // TOML case files (docs/case-files.md) by extension; everything else is CONTACT .inp.
  if (input.extension() == ".toml") return format::read_toml_input_file(input);
  return format::read_input_cases(input);
}

namespace {

/// Every case's values pass the model's check before anything is solved or written, so that a
/// bad value anywhere is an input error naming file, line and case (exit 2, nothing written),
/// the same for .inp and TOML. Cases that cannot be converted (not supported, a per-case error)
/// are left to the run, which reports them case by case.
void validate_cases(const std::vector<format::InputCase>& problems) {
  for (const format::InputCase& c : problems) {
    const auto* m3 = std::get_if<format::CaseRecord>(&c);
    if (m3 == nullptr) continue;  // module 1: the reader checks its values
    const format::CaseRecord& r = *m3;
    // R=2, 3 (check only, CONTACT's "do not compute") are checked too: checking is what they ask.
    if (!r.source.case_error.empty()) continue;
    model::PatchProblem p;
    try {
      p = format::to_patch_problem(r);
    } catch (const InputError&) {
      throw;  // a file the case reads (C=9 coefficients) is malformed: as bad as the input
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
  // access() answers for this process's permissions and a read-only file system alike, without
  // creating a file (which cost a journal commit, ≈ 0.2 ms of a small case's run).
  if (::access(shown.c_str(), W_OK | X_OK) != 0)
    throw InputError(shown.string(), 0, "cannot write to the output folder");
}

/// True when `file` is a name a run with output stem `stem` writes: <stem>.out, <stem>.json,
/// <stem>.<nnnn>.mat/.subs and module 1's <stem>.<nnnn><letter>.mat/.subs.
bool is_output_name(const std::filesystem::path& file, const std::filesystem::path& stem) {
  namespace fs = std::filesystem;
  // The name first (no file-system calls for the many files it rules out), then the folder.
  const std::string name = file.filename().string(), prefix = stem.filename().string() + ".";
  if (name.rfind(prefix, 0) != 0) return false;
  const std::string rest = name.substr(prefix.size());
  bool output = rest == "out" || rest == "json";
  if (!output) {
    std::size_t digits = 0;
    while (digits < rest.size() && std::isdigit(static_cast<unsigned char>(rest[digits]))) ++digits;
    std::string tail = digits >= 4 ? rest.substr(digits) : std::string();
    if (!tail.empty() && std::islower(static_cast<unsigned char>(tail[0])) && tail[0] != '.')
      tail = tail.substr(1);
    output = tail == ".mat" || tail == ".subs";
  }
  if (!output) return false;
  std::error_code ec;
  const fs::path dir =
      fs::weakly_canonical(file.parent_path().empty() ? "." : file.parent_path(), ec);
  const fs::path out_dir =
      fs::weakly_canonical(stem.parent_path().empty() ? "." : stem.parent_path(), ec);
  return !ec && dir == out_dir;
}

/// An output never replaces an input: of `files`, the input file itself (x.out or x.json would
/// be overwritten by the report of its own run) or the files its cases read (a profile named
/// like an output, or a link to one).
void refuse_overwriting_inputs(const std::filesystem::path& input,
                               const std::filesystem::path& stem,
                               const std::vector<std::filesystem::path>& files) {
  namespace fs = std::filesystem;
  // Each file once (a sweep's cases share their profiles).
  std::vector<fs::path> inputs;
  std::set<std::string> seen;
  for (const fs::path& file : files)
    if (seen.insert(file.string()).second) inputs.push_back(file);
  // The report and JSON that exist already: a file read may be one of them under another name.
  std::vector<fs::path> existing;
  for (const char* ext : {".out", ".json"}) {
    fs::path out = stem;
    out += ext;
    std::error_code ec;
    if (fs::exists(out, ec)) existing.push_back(std::move(out));
  }
  for (const fs::path& file : inputs) {
    bool same = false;
    for (const fs::path& out : existing) {
      std::error_code ec;
      same = same || fs::equivalent(file, out, ec);
    }
    if (!same && !is_output_name(file, stem)) continue;
    if (file == input)
      throw InputError(input.string(), 0,
                       fmt::format("the output {} would replace this input; rename the input "
                                   "(e.g. to .inp) or write elsewhere with -o DIR",
                                   file.string()));
    throw InputError(input.string(), 0,
                     fmt::format("the outputs of this run ({}.out, .json, .mat, .subs) would "
                                 "replace the input {} that it reads; rename that file or write "
                                 "elsewhere with -o DIR",
                                 stem.string(), file.string()));
  }
}

}  // namespace

std::vector<std::filesystem::path> files_read_by(const std::vector<format::InputCase>& cases) {
  std::vector<std::filesystem::path> files;
  for (const format::InputCase& c : cases) {
    if (const auto* m3 = std::get_if<format::CaseRecord>(&c)) {
      if (!m3->materials.influence_file.empty()) files.emplace_back(m3->materials.influence_file);
      continue;
    }
    const auto& w = std::get<format::WheelRailRecord>(c);
    for (const format::ProfileSpec* ps : {&w.rail, &w.wheel}) {
      if (!ps->path.empty()) files.emplace_back(ps->path);
      if (ps->sliced)
        for (const Profile& slice : ps->slices->slices)
          if (!slice.file.empty()) files.emplace_back(slice.file);
    }
  }
  return files;
}

double estimated_run_cost(const std::filesystem::path& input) {
  double cost = 0.0;
  for (const format::InputCase& c : read_input_file(input)) {
    if (const auto* w = std::get_if<format::WheelRailRecord>(&c)) {
      const bool force = w->digits.n == 1;
      const double load = force && w->motion.fz > 0.0 ? w->motion.fz / 1e4 : 1.0;
      const double area_mm2 = 25.0 * std::cbrt(load * load);
      cost += (force ? 2.0 : 1.0) * area_mm2 /
              std::max(w->discretisation.dx * w->discretisation.ds, 1e-6);
    } else {
      const auto& r = std::get<format::CaseRecord>(c);
      cost += (r.digits.t != 0 ? 3.0 : 1.0) * r.potential.mx * r.potential.my;
    }
  }
  return cost;
}

std::filesystem::path output_stem(const std::filesystem::path& input,
                                  const std::filesystem::path& output_dir) {
  return (output_dir.empty() ? input.parent_path() : output_dir) / input.stem();
}

RunResult run_input_file(const std::filesystem::path& input, const RunOptions& options) {
  const std::filesystem::path stem = output_stem(input, options.output_dir);
  const std::filesystem::path dir = stem.parent_path();
  refuse_overwriting_inputs(input, stem, {input});  // before reading it
  const auto start = std::chrono::steady_clock::now();
  std::vector<format::InputCase> problems = read_input_file(input);
  refuse_overwriting_inputs(input, stem, files_read_by(problems));
  validate_cases(problems);
  const double read_seconds = seconds_since(start);
  // One process checks (and creates) the folder; the others wait for it before they write.
  const bool root = options.distribution == nullptr || options.distribution->is_root();
  int prepared = 0;
  try {
    if (root) prepare_output_dir(dir);
  } catch (const InputError&) {
    prepared = 1;
    if (options.distribution != nullptr) options.distribution->max_over_processes(prepared);
    throw;
  }
  if (options.distribution != nullptr && options.distribution->max_over_processes(prepared) != 0)
    throw InputError(dir.string(), 0, "the output folder could not be prepared (see the root)");
  RunResult result = run_problems(problems, input.filename().string(), stem, options);
  result.timing.read = read_seconds;
  result.inputs = std::move(problems);
  return result;
}

}  // namespace rollcontact::batch
