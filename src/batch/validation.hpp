#pragma once
// `rollcontact validate DIR`: runs every `.inp` of a folder that has a CONTACT reference report
// (`.ref_out`) next to it, writing our reports into a separate output folder (DIR may be
// read-only), and compares the two reports case by case (validation_compare.hpp).

#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "batch/validation_compare.hpp"
#include "batch/validation_tolerances.hpp"
#include "rollcontact/solve.hpp"

namespace rollcontact::batch {

/// An input with its reference report.
struct ExampleFiles {
  std::string name;  ///< file stem, e.g. `cattaneo`
  std::filesystem::path input, reference;
};

/// The largest of one measure of difference over the compared quantities of one example, with
/// the case and quantity where it occurs.
struct WorstDifference {
  double value = -1;  ///< < 0: nothing compared
  int case_number = 0;
  std::string quantity;
};

struct ExampleResult {
  std::string name;
  std::vector<CaseComparison> cases;  ///< one per case of the reference, in its order
  /// Non-empty when our run failed as a whole (unreadable input, e.g. module 1 not supported
  /// yet): every case is then NotSupported with this reason.
  std::string run_error;
  double seconds = 0;

  int count(CaseStatus status) const;
  /// The largest relative difference |ours − ref| / |ref| (non-count quantities with a nonzero
  /// reference): how far from CONTACT in its own terms.
  WorstDifference worst() const;
  /// The largest share of its tolerance a difference uses, |ours − ref| / allowed (every
  /// quantity, counts too): how close the example is to failing; above 1 is a failure.
  WorstDifference closest_to_tolerance() const;
};

/// What running one example produced; validate_example() reads the outputs.
struct ExampleRun {
  std::filesystem::path report;  ///< our FILE.out (empty: nothing written)
  std::filesystem::path json;    ///< our FILE.json: per-case convergence (optional)
  /// The input was rejected as a whole (InputError, e.g. "module 1 … not supported yet"): every
  /// reference case counts as NotSupported with this reason.
  std::string input_error;
  /// The run itself failed (crash, internal error): every reference case counts as Failed.
  std::string failure;
};

/// Runs one example, writing into `output_dir`. Must not throw for a failing run.
using ExampleRunner =
    std::function<ExampleRun(const ExampleFiles& example, const std::filesystem::path& output_dir)>;

/// The runner used when ValidationOptions::runner is empty: format::run_input_file in this process.
ExampleRun run_example_in_process(const ExampleFiles& example,
                                  const std::filesystem::path& output_dir,
                                  const SolveOptions& solve, bool solve_unvalidated = false);

struct ValidationOptions {
  ToleranceTable tolerances = default_tolerances();
  int jobs = 1;  ///< examples run concurrently (they are independent)
  /// Where our reports go (one file per example, FILE.out / FILE.json); empty: a temporary folder
  /// that is removed afterwards.
  std::filesystem::path output_dir;
  SolveOptions solve;  ///< for the in-process runner
  /// The in-process runner solves the features a plain run refuses as not yet validated
  /// (RunOptions::solve_unvalidated); the CLI's child runner passes `--unvalidated`.
  bool solve_unvalidated = false;
  /// How an example is run; empty: run_example_in_process. The CLI runs `rollcontact run` in a
  /// child process so that a crashing example cannot take the whole validation down.
  ExampleRunner runner;
  /// Called after each example (progress); calls are serialised, `done` counts finished ones.
  std::function<void(const ExampleResult&, std::size_t done, std::size_t total)> on_example;
};

/// `.inp` files of `dir` with a `.ref_out` of the same stem, sorted by name.
std::vector<ExampleFiles> find_examples(const std::filesystem::path& dir);

/// Runs one example into `output_dir` and compares. Never throws for a failing run: errors
/// become NotSupported (our run reported them) or Failed (crash, internal error) cases; a case
/// our FILE.json marks not converged is Failed even when its numbers agree.
ExampleResult validate_example(const ExampleFiles& example, const std::filesystem::path& output_dir,
                               const ValidationOptions& options);

/// All examples of `dir`, in name order. Throws InputError if `dir` holds no example.
std::vector<ExampleResult> validate_folder(const std::filesystem::path& dir,
                                           const ValidationOptions& options);

/// Cases compared with a reference (passed or failed) over all examples.
int compared_cases(const std::vector<ExampleResult>& results);

/// True when a supported case failed, an example could not be compared at all, or nothing was
/// compared (the exit status of `rollcontact validate`).
bool any_failed(const std::vector<ExampleResult>& results);

}  // namespace rollcontact::batch
