#pragma once
// The solver API: a PatchSolver solves one contact patch (model::PatchProblem) after another,
// keeping what a sequence needs — cached influence operators and FFT plans, and the previous
// solution (transient rolling, warm starts).

#include <memory>

#include "rollcontact/fft_options.hpp"
#include "rollcontact/model/patch_problem.hpp"
#include "rollcontact/solution.hpp"

namespace rollcontact {

/// Options that affect how, not what, is computed.
struct SolveOptions {
  FftBackendKind fft = FftBackendKind::Default;
  FftPlanning fft_planning = FftPlanning::Estimate;
};

/// Solves patch problems one after another. One PatchSolver per sequence (for CONTACT inputs:
/// per result element) and per thread: it is not thread-safe, but independent solvers may run
/// in different threads.
class PatchSolver {
 public:
  explicit PatchSolver(SolveOptions options = {});
  ~PatchSolver();
  PatchSolver(PatchSolver&&) noexcept;
  PatchSolver& operator=(PatchSolver&&) noexcept;
  PatchSolver(const PatchSolver&) = delete;
  PatchSolver& operator=(const PatchSolver&) = delete;

  /// Solves one patch. problem.sequence says whether it continues from the previous solution and
  /// whether it becomes the previous one. Throws GeometryError or ProblemError for inadmissible
  /// data; a solver that does not converge returns solution.solver.converged == false (never a
  /// silent wrong answer).
  Solution solve(const model::PatchProblem& problem);

  /// Forgets the previous solution (the cached operators stay).
  void reset_sequence() noexcept;

  /// Makes `solution` the previous one of the sequence, its grid's origin at (origin_x_mm,
  /// origin_y_mm) of the sequence's frame (model::SequenceLink): for a caller that solved trial
  /// problems with becomes_previous = false (a force iteration) and keeps one as the result.
  void set_previous(Solution solution, double origin_x_mm, double origin_y_mm);

  /// Adds u_n = A·p_n and the elastic energy ½Σ(p_n·u_n + p_t·u_t)·δxδy to `solution`, which
  /// this solver returned for `problem` with model::SolverOptions::defer_elastic_energy set
  /// (KPEC/ANALYN pressures; nothing to do otherwise). u_t is Fastsim's own where it solved the
  /// tangential part.
  void complete_elastic_energy(const model::PatchProblem& problem, Solution& solution);

  const SolveOptions& options() const noexcept;

  struct Impl;  ///< cached operators and the previous solution (src/contact/patch_solver_impl.hpp)

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace rollcontact
