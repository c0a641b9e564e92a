#pragma once
// Blanco-Lorenzo's correction of the half-space influence coefficients for a contact surface
// whose inclination changes across the grid rows (CONTACT C=4, spec-additions.md §B8,
// wheelrail-advanced.md §1.7).
//
// The half-space coefficients A relate a load and a displacement in one tangent plane. On a
// curved surface the load at element J acts in J's local frame and the displacement at element
// I is wanted in I's; the frames differ by the turn θ = α_J − α_I about x (α the inclination,
// the frame's turn about +x). With M(φ) the turn by φ of the (s, n) components,
//
//   variant 1:  B = A·M(θ)            the load decomposed in the receiver's frame (Blanco);
//   variant 2:  as 1 with B_xn = A_xn;
//   variant 3:  B = M(θ)·A            the displacement turned into the receiver's frame;
//   variant 4:  B = M(θ/2)·A·M(θ/2)   both turned halfway: B stays symmetric where A is.
//
// With the constant-curvature method α = c₀ + c₁·y, so θ = −c₁·Δy depends on the offset
// Δy = y_I − y_J only and B is a convolution kernel like A (one matrix for all rows).

#include <vector>

#include "elastic/influence.hpp"
#include "rollcontact/model/bodies.hpp"

namespace rollcontact::elastic {

/// The slope c₁ [rad/mm] of the least-squares line α = c₀ + c₁·y through the inclination table
/// (the constant-curvature method); 0 for a table of one position. Throws ProblemError for an
/// empty table, one of unequal lengths or non-finite values.
double inclination_curvature(const model::InclinationCorrection& correction);

/// B of `variant` (1–4) for the turn θ [rad] from A: a[i][j] = displacement component i due to
/// traction component j, components (x, s, n).
void turn_coefficients(int variant, double theta_rad, const double (&a)[3][3], double (&b)[3][3]);

/// The material without its correction: whose kernels are turned.
CombinedMaterial uncorrected(const CombinedMaterial& material);

/// The plain components the correction reads, in the order turned_kernels() takes them: xx, xy,
/// yy, nn and, for a coupled plain material, xn, yn, nx, ny (C_yx = C_xy for the half-space).
std::vector<Component> plain_components(const CombinedMaterial& plain);

/// The kernels of components `cs` with the material's correction (CombinedMaterial::
/// inclination_corrected()) applied to `plain` (plain_components(uncorrected(material)) on
/// `grid` at the shift), offset by offset (the observation point moved by shift_y [mm],
/// physics.md §3.2).
std::vector<Kernel> turned_kernels(const std::vector<Component>& cs,
                                   const std::vector<Kernel>& plain, const Grid& grid,
                                   const CombinedMaterial& material, double shift_y);

/// turned_kernels() of the plain kernels made here.
std::vector<Kernel> inclination_corrected_kernels(const std::vector<Component>& cs,
                                                  const Grid& grid,
                                                  const CombinedMaterial& material, double shift_x,
                                                  double shift_y);

}  // namespace rollcontact::elastic
