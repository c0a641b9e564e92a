#pragma once
// Combined elastic constants of two bodies (spec/physics.md §3.1).

#include "rollcontact/solution.hpp"

namespace rollcontact::elastic {

/// 1/G = ½(1/G₁+1/G₂), ν/G = ½(ν₁/G₁+ν₂/G₂), K = (G/4)[(1−2ν₁)/G₁ − (1−2ν₂)/G₂].
/// Moduli in N/mm². Throws ProblemError for G ≤ 0 or ν outside [0, 0.5].
CombinedMaterial combine_materials(double nu1, double nu2, double g1, double g2);

/// Kalker's material difference parameter K = (G/4)[(1−2ν₁)/G₁ − (1−2ν₂)/G₂] (dimensionless;
/// 0 for quasi-identical bodies), without validating the inputs. The one definition used by the
/// solver and by the readers' MAXOUT override.
inline double material_difference_k(double nu1, double nu2, double g1, double g2) {
  const double g = 2.0 / (1.0 / g1 + 1.0 / g2);
  return 0.25 * g * ((1.0 - 2.0 * nu1) / g1 - (1.0 - 2.0 * nu2) / g2);
}

/// Hertz contact modulus E* = G/(1−ν) [N/mm²] of the combined material.
inline double contact_modulus(const CombinedMaterial& m) {
  return m.g / (1.0 - m.nu);
}

}  // namespace rollcontact::elastic
