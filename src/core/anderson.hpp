#pragma once
// Anderson acceleration of a fixed-point iteration x ← G(x) (Walker & Ni, SIAM J. Numer. Anal.
// 49, 2011). Used on top of Gauss–Seidel sweeps: for a linear map it behaves like GMRES with the
// sweep as preconditioner, which removes the slow convergence caused by the long-range coupling
// of the steady-rolling operator.

#include <cstddef>
#include <vector>

namespace rollcontact::core {

class AndersonAccelerator {
 public:
  AndersonAccelerator(std::size_t n, int depth);

  /// Given the iterate x and g = G(x), overwrites x with the accelerated next iterate.
  void step(std::vector<double>& x, const std::vector<double>& g);
  /// Forgets the history (after a safeguard rejected a step).
  void reset();

 private:
  std::size_t n_;
  int depth_;
  std::vector<std::vector<double>> df_, dg_;  // differences of residuals f = g − x and of g
  std::vector<double> f_prev_, g_prev_;
  bool has_prev_ = false;
};

}  // namespace rollcontact::core
