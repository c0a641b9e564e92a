#pragma once
// Corner functions of the half-space potentials of a uniform load on a rectangle
// (spec/physics.md §16), the building blocks of the subsurface displacements and stresses.
//
// With ρ = √((x−ξ)² + (y−η)² + z²) and Ω = z·ln(ρ + z) − ρ (Johnson, Contact Mechanics §3.2,
// after Love 1929), a uniform load on a rectangle [ξ₁, ξ₂] × [η₁, η₂] gives the potentials
//   V = ∫∫ 1/ρ,   L = ∫∫ ln(ρ + z) (∂L/∂z = V),   M = ∫∫ Ω (∂M/∂z = L),
// all harmonic in z > 0. Every derivative D of them needed for displacements and stresses is a
// corner sum D = F(a₁, b₁) − F(a₁, b₂) − F(a₂, b₁) + F(a₂, b₂) with a_k = x − ξ_k, b_k = y − η_k
// of a closed-form corner function F(a, b, z): the antiderivative ∫∫ da db (or ∫ db after one
// x-derivative) of the integrand. Corner functions are determined up to terms that depend on
// only (a, z) or (b, z); those cancel in the corner sum and are dropped.

#include <array>
#include <cstddef>

namespace rollcontact::post {

/// Index of one corner function (derivatives of V, L, M named by their subscripts). Derivatives
/// not listed follow from harmonicity and ∂_z L = V, ∂_z M = L (see half_space_response.cpp).
enum Corner : std::size_t {
  kV,     ///< a ln(b+ρ) + b ln(a+ρ) − z atan(ab/(zρ))
  kVx,    ///< ln(b+ρ)
  kVy,    ///< ln(a+ρ)
  kVz,    ///< −atan(ab/(zρ))  (solid angle)
  kVxx,   ///< a / (ρ (b+ρ))
  kVyy,   ///< b / (ρ (a+ρ))
  kVxy,   ///< 1/ρ
  kVxz,   ///< z / (ρ (b+ρ))
  kVyz,   ///< z / (ρ (a+ρ))
  kLx,    ///< b ln(ρ+z) + z ln(b+ρ) + a θ(a,b)
  kLy,    ///< a ln(ρ+z) + z ln(a+ρ) + b θ(b,a)
  kLxx,   ///< θ(a,b) = atan(b/a) − atan(bz/(aρ))
  kLyy,   ///< θ(b,a)
  kLxy,   ///< ln(ρ+z)
  kLxxy,  ///< a / (ρ (ρ+z))
  kLxyy,  ///< b / (ρ (ρ+z))
  kMxx,   ///< z θ(a,b) − a ln(b+ρ)
  kMyy,   ///< z θ(b,a) − b ln(a+ρ)
  kMxy,   ///< z ln(ρ+z) − ρ  (= Ω)
  kMxxy,  ///< −a / (ρ+z)
  kMxyy,  ///< −b / (ρ+z)
  kCornerCount
};

using CornerValues = std::array<double, kCornerCount>;

/// All corner functions at (a, b, z) [mm], z > 0 (callers keep z away from 0, see
/// kMinimumDepth in half_space_response.hpp). Units: mm^(2−order of the derivative) for V,
/// one more mm for L and two more for M.
CornerValues corner_values(double a, double b, double z);

}  // namespace rollcontact::post
