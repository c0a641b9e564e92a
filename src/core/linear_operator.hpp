#pragma once
// The one notion of a linear operator y = A·x that every iterative solver in rollcontact takes.
//
// Operators on a grid field (influence products by FFT, preconditioners) implement
// LinearOperator: plain arrays of a fixed size, no allocation per product, and a fused
// product-and-dot that the bound-constrained CG of the normal problem uses. Operators assembled
// on the fly — the Newton systems restricted to the current adhesion and slip sets — are
// callables of the same meaning, LinearMap; any LinearOperator is one through as_map().

#include <cstddef>
#include <functional>
#include <vector>

namespace rollcontact::core {

/// y = A·x for vectors of one fixed size (ix fastest on a grid); y is overwritten.
class LinearOperator {
 public:
  virtual ~LinearOperator() = default;
  /// x and y have size() entries; no allocation.
  virtual void apply(const double* x, double* y) = 0;
  /// apply() that also returns Σ x_I·y_I, summed in index order: the sum is taken in the last
  /// pass over y, which saves the caller (CG: d·A·d) another pass over both vectors.
  virtual double apply_dot(const double* x, double* y) = 0;
};

/// y = A·x as a callable on vectors (y is resized by the map if needed).
using LinearMap = std::function<void(const std::vector<double>& x, std::vector<double>& y)>;

/// The callable view of `op` for vectors of n entries; `op` must outlive the map.
inline LinearMap as_map(LinearOperator& op, std::size_t n) {
  return [&op, n](const std::vector<double>& x, std::vector<double>& y) {
    y.resize(n);
    op.apply(x.data(), y.data());
  };
}

}  // namespace rollcontact::core
