#pragma once
// Flexibilities of the simplified theory (spec/physics.md §11.2): the equivalent ellipse of a
// contact patch, Kalker's three flexibilities L1, L2, L3, their blending towards one value at
// large creepage, and Spiryagin's slope reduction factor k.

#include <span>

#include "rollcontact/grid.hpp"
#include "simplified/kalker_coefficients.hpp"

namespace rollcontact::simplified {

/// Semi-axes of an ellipse [mm]: a along x (rolling direction), b along y.
struct Ellipse {
  double a = 0.0, b = 0.0;
};

/// Flexibilities [mm³/N] for the x, y and spin parts of the traction: u = L·p.
struct Flexibilities {
  double l1 = 0.0, l2 = 0.0, l3 = 0.0;
};

/// Creepages (ξ, η [-], φ [rad/mm]).
struct Creepages {
  double ksi = 0.0, eta = 0.0, phi = 0.0;
};

/// Ellipse with the area A = n·δxδy of the elements with pn > 0 and the aspect ratio ℓ/w of their
/// bounding index box: a = √(A/π)·√(ℓ/w), b = √(A/π)·√(w/ℓ). Zero semi-axes when no element is in
/// contact.
Ellipse equivalent_ellipse(const Grid& grid, std::span<const double> pn);

/// Kalker's flexibilities for the ellipse and combined shear modulus G [N/mm²]:
/// L1 = 8a/(3 C11 G), L2 = 8a/(3 C22 G), L3 = πa√(a/b)/(4 C23 G).
Flexibilities kalker_flexibilities(const Ellipse& e, const KalkerCoefficients& c, double g);

/// Blending of L1, L2, L3 towards the single "weighted" flexibility L_c as the creepages grow
/// relative to the characteristic creepages μFN/(abG·C): weight w = clamp(f/3, 0, 1) with f the
/// ratio of the creepage to its characteristic value. FN [N], G [N/mm²].
Flexibilities blend_flexibilities(const Flexibilities& l, const Ellipse& e,
                                  const KalkerCoefficients& c, double g, double mu, double fn,
                                  const Creepages& cr);

/// Parameters of the slope reduction (K0_MF, ALFAMF, BETAMF); k0 = alpha = 1: original Fastsim.
struct SlopeReduction {
  double k0 = 1.0, alpha = 1.0, beta = 1.0;
};

/// Slope reduction factor k (a, b, C11 of the equivalent ellipse) = k0(α∞ + (1 − α∞)/(1 + βε)) with
/// the non-dimensional creepage ε = G·πab·k0·C11·ν_tot/(4μFN), ν_tot = √(ξ² + ν_φ²), ν_φ = η + φa
/// (or η if smaller). The effective flexibilities are L/k.
double slope_reduction_factor(const SlopeReduction& s, const Ellipse& e, double c11, double g,
                              double mu, double fn, const Creepages& cr);

}  // namespace rollcontact::simplified
