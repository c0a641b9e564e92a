#pragma once
// Attenuated influence between the parts of one grid: u_I = Σ_J f(part(I), part(J)) K(I−J) p_J
// with f(a, a) = 1. CONTACT's IPLAN=4 planform (NPATCH rectangles with factors f_ij, physics.md
// §4) and the wheel/rail combination of two contact regions whose distance lies between D_COMB
// and D_SEP (§13.3 step 5) both lead to it: one contact problem whose parts feel each other only
// in part.
//
// For 0 ≤ f ≤ 1 the modified operator stays symmetric positive definite where K is:
// A_f = f·A + (1 − f)·blockdiag(A_aa), a convex combination of two such matrices.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace rollcontact::elastic {

struct Interaction {
  int n_parts = 1;
  std::vector<std::uint8_t> part;  ///< per element (ix fastest), < n_parts
  std::vector<double> factor;      ///< n_parts × n_parts, symmetric, diagonal 1

  double f(std::size_t i, std::size_t j) const noexcept {
    return factor[static_cast<std::size_t>(part[i]) * static_cast<std::size_t>(n_parts) + part[j]];
  }
  double f_parts(int a, int b) const noexcept {
    return factor[static_cast<std::size_t>(a) * static_cast<std::size_t>(n_parts) +
                  static_cast<std::size_t>(b)];
  }

  friend bool operator==(const Interaction& a, const Interaction& b) noexcept {
    return a.n_parts == b.n_parts && a.part == b.part && a.factor == b.factor;
  }
};

/// Shared between the operators of one grid; nullptr means full interaction (no parts).
using InteractionPtr = std::shared_ptr<const Interaction>;

/// True when both describe the same operator (both absent, or equal contents).
inline bool same_interaction(const InteractionPtr& a, const InteractionPtr& b) noexcept {
  if (!a || !b) return !a && !b;
  return a == b || *a == *b;
}

/// Applies a plain (full-interaction) product part by part: for each part a the inputs are
/// weighted by f(a, part(J)), the product is taken, and u keeps its values on part a. Costs
/// n_parts products. The buffers are kept between calls.
class PartwiseProduct {
 public:
  /// `product(in, out)` takes n_in inputs and fills n_out outputs of n values each.
  template <class Product>
  void apply(const Interaction& inter, std::size_t n, int n_in, int n_out, const double* const* p,
             double* const* u, Product&& product) {
    in_.resize(static_cast<std::size_t>(n_in) * n);
    out_.resize(static_cast<std::size_t>(n_out) * n);
    in_ptr_.resize(static_cast<std::size_t>(n_in));
    out_ptr_.resize(static_cast<std::size_t>(n_out));
    for (int j = 0; j < n_in; ++j)
      in_ptr_[static_cast<std::size_t>(j)] = in_.data() + static_cast<std::size_t>(j) * n;
    for (int i = 0; i < n_out; ++i)
      out_ptr_[static_cast<std::size_t>(i)] = out_.data() + static_cast<std::size_t>(i) * n;
    for (int a = 0; a < inter.n_parts; ++a) {
      for (int j = 0; j < n_in; ++j) {
        double* q = in_ptr_[static_cast<std::size_t>(j)];
        for (std::size_t e = 0; e < n; ++e) q[e] = inter.f_parts(a, inter.part[e]) * p[j][e];
      }
      product(in_ptr_.data(), out_ptr_.data());
      for (int i = 0; i < n_out; ++i) {
        const double* t = out_ptr_[static_cast<std::size_t>(i)];
        for (std::size_t e = 0; e < n; ++e)
          if (inter.part[e] == static_cast<std::uint8_t>(a)) u[i][e] = t[e];
      }
    }
  }

 private:
  std::vector<double> in_, out_;
  std::vector<double*> in_ptr_;
  std::vector<double*> out_ptr_;
};

}  // namespace rollcontact::elastic
