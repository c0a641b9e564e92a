#pragma once
// Combined elastic constants of two bodies (spec/physics.md §3.1).

#include "rollcontact/model/bodies.hpp"
#include "rollcontact/solution.hpp"

namespace rollcontact::elastic {

/// 1/G = ½(1/G₁+1/G₂), ν/G = ½(ν₁/G₁+ν₂/G₂), K = (G/4)[(1−2ν₁)/G₁ − (1−2ν₂)/G₂].
/// Moduli in N/mm². Throws ProblemError for G ≤ 0 or ν outside [0, 0.5].
CombinedMaterial combine_materials(double nu1, double nu2, double g1, double g2);

using model::material_difference_k;

/// Hertz contact modulus E* = G/(1−ν) [N/mm²] of the combined material.
inline double contact_modulus(const CombinedMaterial& m) {
  return m.g / (1.0 - m.nu);
}

}  // namespace rollcontact::elastic
