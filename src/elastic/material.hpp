#pragma once
// Combined elastic constants of two bodies (spec/physics.md §3.1).

#include "rollcontact/model/bodies.hpp"
#include "rollcontact/solution.hpp"

namespace rollcontact::elastic {

/// 1/G = ½(1/G₁+1/G₂), ν/G = ½(ν₁/G₁+ν₂/G₂), K = (G/4)[(1−2ν₁)/G₁ − (1−2ν₂)/G₂].
/// Moduli in N/mm². Throws ProblemError for G ≤ 0 or ν outside [0, 0.5].
CombinedMaterial combine_materials(double nu1, double nu2, double g1, double g2);

/// The combined material of the bodies as the influence coefficients use it: combine_materials
/// of the (glassy) moduli, an interfacial layer's compliance (M=4) and, for viscoelastic bodies
/// (M=1), their viscous parts (spec-additions §B5) with relaxation lengths τ_a·V,
/// V = velocity_mm_s. The viscous part of body a has weight ½·G·FG_a/G_a, its own ν_a and the
/// coupling ±½(1−2ν_a) (its share of K); the two parts are merged into one when the bodies
/// have the same ν and ℓ (identical bodies: no viscous coupling, half the quadrature work).
CombinedMaterial combine_bodies(const model::Bodies& bodies, double velocity_mm_s);

/// The effective constants of viscoelastic bodies (spec-additions §B5; CONTACT's NUV, GV, AKV):
/// P§3.1 with the compliance c_a = 1/G_a of a body that responds glassy (τ_a > 0) or
/// (1 + FG_a)/G_a of one that relaxes at once (τ_a = 0).
CombinedMaterial effective_viscoelastic_constants(const model::Bodies& bodies);

using model::material_difference_k;

/// Hertz contact modulus E* = G/(1−ν) [N/mm²] of the combined material.
inline double contact_modulus(const CombinedMaterial& m) {
  return m.g / (1.0 - m.nu);
}

}  // namespace rollcontact::elastic
