#pragma once
// Preconditioned Krylov solvers for the linear systems of the semismooth Newton iteration:
// conjugate gradients for symmetric positive definite operators (shift, transient rolling) and
// restarted GMRES with right preconditioning for the non-symmetric steady-rolling operator.
// Vectors are plain std::vector<double>; operators are LinearMaps (core/linear_operator.hpp).

#include <functional>
#include <vector>

#include "core/linear_operator.hpp"

namespace rollcontact::core {

struct KrylovResult {
  int iterations = 0;              ///< operator applications
  double relative_residual = 0.0;  ///< ‖b − A x‖ / ‖b‖ (preconditioned norm for CG)
  bool converged = false;
};

/// Called by PCG after each update x += α·d, before the preconditioner is applied: lets a caller
/// accumulate side results of the last application of A (e.g. full-grid products) with weight α.
using StepObserver = std::function<void(double alpha)>;

/// Solves A x = b from x = 0 until ‖r‖ ≤ rtol·‖b‖ (in the M-norm: √(rᵀ M r)), at most max_it.
KrylovResult solve_pcg(const LinearMap& a, const LinearMap& m, const std::vector<double>& b,
                       std::vector<double>& x, double rtol, int max_it,
                       const StepObserver& on_step = nullptr);

/// Lets a caller of GMRES keep side results of its operator applications, as StepObserver does
/// for PCG: `applied(j)` runs right after A is applied to the j-th direction z_j = M·v_j of the
/// current cycle, `combined(y, count)` when the cycle ends with x += Σ_{j<count} y_j·z_j. So a
/// caller that saved a by-product of A·z_j (e.g. the full-grid product) has that of A·x as the
/// same combination, without applying A to x. The restart's residual product is not reported.
struct GmresObserver {
  std::function<void(std::size_t j)> applied;
  std::function<void(const std::vector<double>& y, std::size_t count)> combined;
};

/// Right-preconditioned GMRES(restart) from x = 0 until ‖b − A x‖ ≤ rtol·‖b‖, at most max_it.
KrylovResult solve_gmres(const LinearMap& a, const LinearMap& m, const std::vector<double>& b,
                         std::vector<double>& x, double rtol, int max_it, int restart = 40,
                         const GmresObserver* observer = nullptr);

}  // namespace rollcontact::core
