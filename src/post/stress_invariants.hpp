#pragma once
// Scalar measures of a 3×3 stress tensor used in subsurface reports (spec/physics.md §16).

#include <array>

#include "post/half_space_response.hpp"

namespace rollcontact::post {

/// Derived stresses [N/mm²], tension positive.
struct StressInvariants {
  double hydrostatic = 0.0;           ///< σ_hyd = tr σ / 3
  double von_mises = 0.0;             ///< σ_vm = √(3 J₂)
  double tresca = 0.0;                ///< σ₁ − σ₃
  std::array<double, 3> principal{};  ///< σ₁ ≥ σ₂ ≥ σ₃
};

/// Invariants of the symmetric tensor `s` (only the upper triangle is read).
StressInvariants stress_invariants(const Matrix3& s);

}  // namespace rollcontact::post
