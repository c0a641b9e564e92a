#pragma once
// The entry point of the numerics: solve one Problem, remembering what a sequence needs in State.

#include <memory>

#include "rollcontact/fft_options.hpp"
#include "rollcontact/problem.hpp"
#include "rollcontact/solution.hpp"

namespace rollcontact {

/// Options that affect how, not what, is computed.
struct SolveOptions {
  FftBackendKind fft = FftBackendKind::Default;
  FftPlanning fft_planning = FftPlanning::Estimate;
};

/// What a sequence of cases remembers: cached influence coefficients and FFT plans, the previous
/// solution (for P=0 continuation and warm starts). One State per thread; not shared.
class State {
 public:
  State();
  explicit State(SolveOptions options);
  ~State();
  State(State&&) noexcept;
  State& operator=(State&&) noexcept;
  State(const State&) = delete;
  State& operator=(const State&) = delete;

  const SolveOptions& options() const noexcept;
  struct Impl;
  Impl& impl() noexcept { return *impl_; }

 private:
  std::unique_ptr<Impl> impl_;
};

/// Solves one case. Throws ProblemError for inadmissible data and NotSupportedError for features
/// that are not implemented; a solver that does not converge returns solution.solver.converged ==
/// false (never a silent wrong answer).
Solution solve(const Problem& problem, State& state);

/// Throws NotSupportedError naming the digit and value when the problem uses a feature that
/// solve() does not implement yet; returns normally otherwise.
void check_supported(const Problem& problem);

}  // namespace rollcontact
