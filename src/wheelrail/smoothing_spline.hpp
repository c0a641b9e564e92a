#pragma once
// The natural cubic smoothing spline of one coordinate over a parameter (Reinsch): it minimises
//   Σ w_i (f_i − g(s_i))² + λ ∫ g''(s)² ds
// and returns the node values g(s_i) and the second derivatives g''(s_i) (zero at both ends).
// λ = 0 gives the interpolating natural spline. Used for y(s) and z(s) of every profile section
// (spec/physics.md §13.1, spec-additions §A1).

#include <vector>

namespace rollcontact::wheelrail {

struct SplineNodes {
  std::vector<double> value;   ///< g(s_i)
  std::vector<double> second;  ///< g''(s_i)
};

/// `s` strictly increasing (n >= 2), `weights` positive (empty: all 1), lambda >= 0.
SplineNodes fit_smoothing_spline(const std::vector<double>& s, const std::vector<double>& f,
                                 const std::vector<double>& weights, double lambda);

}  // namespace rollcontact::wheelrail
