#pragma once
// Gauss–Legendre quadrature rules of any order on [0, 1].

#include <vector>

namespace rollcontact::core {

/// Nodes u and weights w of an n-point Gauss–Legendre rule on [0, 1]: ∫₀¹ f ≈ Σ w_k f(u_k),
/// exact for polynomials of degree 2n − 1. Nodes ascending.
struct GaussRule {
  std::vector<double> u, w;
};

/// The n-point rule (n ≥ 1), by Newton's iteration on the Legendre polynomial P_n from
/// Chebyshev-like guesses; nodes and weights to double precision (Σ w = 1 to ~1e-15).
GaussRule gauss_legendre(int n);

}  // namespace rollcontact::core
