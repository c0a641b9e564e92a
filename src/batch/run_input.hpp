#pragma once
// Runs every case of an input file and writes the report and JSON (the `rollcontact run` job).

#include <filesystem>
#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

#include "batch/distribution.hpp"
#include "format/inp/case_record.hpp"
#include "format/inp/inp_reader.hpp"
#include "rollcontact/solution.hpp"
#include "rollcontact/solve.hpp"
#include "rollcontact/wheelrail.hpp"

namespace rollcontact::batch {

/// Where a run of `input` writes its outputs: `<output_dir>/<input's stem>` (the input's own
/// folder when `output_dir` is empty), to which .out, .json, .<nnnn>.mat … are appended.
std::filesystem::path output_stem(const std::filesystem::path& input,
                                  const std::filesystem::path& output_dir);

/// The files the cases read besides their input file: profiles (each slice of a slices file
/// too) and influence-coefficient files (C=9), as resolved.
std::vector<std::filesystem::path> files_read_by(const std::vector<format::InputCase>& cases);

/// The cases of an input file: a TOML case file (docs/case-files.md) by its extension `.toml`,
/// anything else CONTACT's `.inp` format. Throws InputError naming file and line.
std::vector<format::InputCase> read_input_file(const std::filesystem::path& input);

/// Result of one case of a run.
struct CaseOutcome {
  /// The module-3 case, or the identity (number, digits, source) of a module-1 case.
  format::CaseRecord problem;
  bool solved = false;          ///< a Solution (module 3) or a WheelRailSolution (module 1) exists
  bool wheel_rail = false;      ///< module 1: `wheelrail` holds the result
  Solution solution;            ///< valid when solved (module 3)
  WheelRailSolution wheelrail;  ///< valid when solved (module 1)
  std::string error;            ///< non-empty for "error" (not supported, inadmissible data)
  /// The error is a refusal of a feature not validated against CONTACT (NotValidatedError):
  /// `rollcontact run --unvalidated` would solve the case with a warning.
  bool refused_unvalidated = false;
  bool skipped = false;  ///< R = 2, 3: read but not solved
};

struct RunOptions {
  std::filesystem::path output_dir;  ///< empty: next to the input
  SolveOptions solve;
  /// Called after each case (progress); may be empty. With threads > 1 it is called in case
  /// order as soon as a case and every case before it are solved, one call at a time, on the
  /// worker thread whose case completed the order.
  std::function<void(const CaseOutcome&, std::size_t index, std::size_t count)> on_case;
  /// Worker threads: the sequences (one per result element and module) run in parallel, each
  /// in its order; reports and results are those of a one-thread run, value for value.
  int threads = 1;
  /// Called about every 0.2 s with the cases solved so far while threads > 1 work; may be empty.
  std::function<void(std::size_t done, std::size_t count)> on_progress;
  /// Several processes (MPI): the sequences are spread over them dynamically, every process
  /// writes the side files (.mat, .subs) of the cases it solves, and the root writes the report
  /// and JSON — the bytes of a one-process run. RunResult::cases stay empty and on_case is not
  /// called then; the other processes' RunResult is empty. Null or one process: this one.
  Distribution* distribution = nullptr;
  /// Solve the wheel/rail features whose results are known to differ from CONTACT's (wheel
  /// slices, KPEC beyond its ellipse, ...) with a warning each instead of refusing them
  /// (model::WheelRailProblem::validated_only).
  bool solve_unvalidated = false;
  /// Keep each case's per-element fields (pressures, tractions, displacements, slips, …) in
  /// RunResult::cases. False (the command-line program, which has written them to the report
  /// and JSON): each outcome keeps its flags, totals, statistics and solver report, but its
  /// fields are released once its outputs are made, so that a run's memory does not grow with
  /// its number of cases (with threads > 1 by the worker, before on_case sees the outcome).
  bool keep_fields = true;
  /// Keep each case's outcome in RunResult::cases. False (the command-line program, which needs
  /// only the counts RunResult keeps anyway, and sees each outcome in on_case): `cases` stays
  /// empty and a run's memory holds no per-case results at all.
  bool keep_outcomes = true;
};

/// Where the wall time of a run went [s] (one thread: with threads > 1 set-up and solve are
/// summed over the workers). Process start-up and exit are not included.
struct RunTiming {
  double read = 0.0;    ///< reading and checking the input file
  double setup = 0.0;   ///< per case: discretisation and operators built (SolverReport)
  double solve = 0.0;   ///< per case: the rest of the solve
  double output = 0.0;  ///< reports, JSON and side files
};

struct RunResult {
  std::vector<CaseOutcome> cases;  ///< empty with RunOptions::keep_outcomes = false
  std::size_t case_count = 0;      ///< cases run (read and reported)
  /// Cases refused as not validated against CONTACT (CaseOutcome::refused_unvalidated).
  std::size_t refused_unvalidated = 0;
  /// The cases as read, in the order of `cases` (run_input_file only; run_problems leaves it
  /// empty): what callers need beyond the outcomes (e.g. a wheel/rail case's profiles).
  std::vector<format::InputCase> inputs;
  std::filesystem::path report_path, json_path;
  int failed = 0;  ///< errors + not converged
  RunTiming timing;
};

/// Solves one case of an input file with `solver` (the sequence of its result element): the
/// record becomes a model::PatchProblem (NotSupportedError for what is not implemented), and
/// geometry errors get the file, line and case number in front.
Solution solve_case(const format::CaseRecord& record, PatchSolver& solver);

/// Reads `input`, solves each case in order (one PatchSolver per result element), writes
/// <name>.out and <name>.json atomically. Throws InputError (nothing written) for bad input.
RunResult run_input_file(const std::filesystem::path& input, const RunOptions& options);

/// A rough cost of solving the cases of `input`, to start several files longest first (it only
/// orders, it never changes a result): per case the elements to solve for — module 3 the grid
/// MX·MY, three times with a tangential problem; module 1 a Hertzian patch of 25 mm² at 10 kN
/// growing like FZ^(2/3) over DX·DS, twice with the vertical force prescribed. Throws
/// InputError like run_input_file for an unreadable file.
double estimated_run_cost(const std::filesystem::path& input);

/// Same for problems already read; `input_name` names the outputs.
RunResult run_problems(const std::vector<format::InputCase>& problems,
                       const std::string& input_name, const std::filesystem::path& output_stem,
                       const RunOptions& options);

}  // namespace rollcontact::batch
