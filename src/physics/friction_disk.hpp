#pragma once
// The admissible set of an isotropic friction law on one element: the disk |p_t| ≤ g of radius
// g, the traction bound [N/mm²]. Every tangential solver uses these three operations — and only
// these — so that a new friction law changes the bound g, not the solvers (spec/physics.md §5).
//
//   project    the traction nearest to z inside the disk (g ≤ 0: the origin);
//   slips      whether a traction is on the bound (the element slips);
//   linearise  the derivative of the projection at z, for semismooth Newton.

#include <cmath>

namespace rollcontact::physics {

/// Projects (x, y) onto the disk |p| ≤ g in place: unchanged inside, scaled to the rim outside,
/// zero when g ≤ 0 (no pressure: no tangential traction).
inline void project_onto_disk(double& x, double& y, double g) {
  if (g <= 0.0) {
    x = y = 0.0;
    return;
  }
  const double magnitude = std::hypot(x, y);
  if (magnitude > g) {
    x *= g / magnitude;
    y *= g / magnitude;
  }
}

/// Tolerance of the slip test: |p| ≥ g·(1 − 1e-9) counts as on the bound, so that a traction
/// projected onto the rim (rounded by a few ulp) is classified as slipping.
inline constexpr double kSlipTestTolerance = 1e-9;

/// True when a traction of magnitude `magnitude` lies on the bound g (or g ≤ 0): the element slips.
inline bool slips(double magnitude, double g) {
  return g <= 0.0 || magnitude >= g * (1.0 - kSlipTestTolerance);
}

/// Where z lies relative to the disk, with what the derivative of the projection P_g needs.
struct DiskLinearisation {
  enum class Region {
    ZeroBound,  ///< g ≤ 0: P_g(z) = 0, derivative 0
    Interior,   ///< |z| ≤ g: P_g(z) = z, derivative I
    Exterior    ///< |z| > g: P_g(z) = g z/|z|, derivative κ (I − n nᵀ)
  };
  Region region = Region::ZeroBound;
  double nx = 0.0, ny = 0.0;  ///< Exterior: unit vector n = z/|z|
  double kappa = 1.0;         ///< Exterior: κ = g/|z| < 1
};

/// The derivative of the projection onto the disk |p| ≤ g at z = (zx, zy).
DiskLinearisation linearise_disk_projection(double zx, double zy, double g);

}  // namespace rollcontact::physics
