#pragma once
// Displacements, displacement gradients and stresses inside an elastic half-space loaded by
// uniform tractions on rectangles of its surface (Boussinesq–Cerruti, spec/physics.md §16).

#include <array>

#include "post/corner_functions.hpp"

namespace rollcontact::post {

/// Uniform surface traction acting ON the half-space [N/mm²]: tangential (px, py) and the
/// compressive normal pressure pn (pushing into the body, along +z).
struct Traction {
  double px = 0.0, py = 0.0, pn = 0.0;
};

/// Corner sums of all corner functions, weighted by each traction component: x[k] = Σ ± px F_k.
struct CornerSums {
  CornerValues x{}, y{}, n{};
};

using Matrix3 = std::array<std::array<double, 3>, 3>;

/// Response at one point of the half-space z ≥ 0 (z into the body).
struct HalfSpaceResponse {
  std::array<double, 3> u{};  ///< displacement (x, y, z) [mm]
  Matrix3 grad{};             ///< ∂u_i/∂x_j [-]
  Matrix3 stress{};           ///< Cauchy stress, tension positive [N/mm²]
};

/// Smallest depth used, relative to the element size: surface points (z = 0) are evaluated at
/// this depth so that points on element edges stay finite (the exact surface field jumps there).
inline constexpr double kMinimumRelativeDepth = 1e-9;

/// Assembles the response from corner sums at depth z > 0 [mm] for shear modulus g [N/mm²] and
/// Poisson ratio nu (Johnson, Contact Mechanics eq. 3.7, displacements from the potentials).
HalfSpaceResponse response_from_sums(const CornerSums& sums, double z, double g, double nu);

/// Adds w·(corner functions at (a, b, z)) for each traction component to `sums`.
void add_corner(CornerSums& sums, double a, double b, double z, const Traction& w);

/// Response at (x, y, z) [mm], z ≥ 0, to the traction t on [x0, x1] × [y0, y1] [mm].
HalfSpaceResponse rectangle_response(double x, double y, double z, double x0, double x1, double y0,
                                     double y1, const Traction& t, double g, double nu);

}  // namespace rollcontact::post
