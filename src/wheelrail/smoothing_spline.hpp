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

/// CONTACT's ISMOOTH = 2 (spec-additions §A1): values g at the nodes minimising
///   Σ w_i (f_i − g_i)² + λ Σ_j h̄_j (D³g)_j²,
/// the discrete form of λ ∫ g'''(s)² ds (D³: third divided differences over s_j..s_{j+3}
/// times 3!, h̄_j = (s_{j+3} − s_j)/3). Quadratics pass unchanged; a sine of wavelength L keeps
/// the fraction 1/(1 + λ(2π/L)⁶/w) of its amplitude where the nodes are dense and w is the
/// weight per unit length (λ = (L_filt/2π)⁶ with chord-length weights: half at L_filt). The
/// caller interpolates g. Fewer than 4 nodes or λ = 0: f itself.
std::vector<double> smooth_third_order(const std::vector<double>& s, const std::vector<double>& f,
                                       const std::vector<double>& weights, double lambda);

}  // namespace rollcontact::wheelrail
