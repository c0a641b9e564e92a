#pragma once
// The delayed (viscous) part of the influence coefficients of standard-linear-solid bodies in
// steady rolling (CONTACT M=1, spec-additions §B5).
//
// A body with glassy modulus G_a and creep ratio FG_a creeps after a load step as
// J(t) = [1 + FG_a(1 − e^{−t/τ})]/G_a. In steady rolling the load seen by a material point
// changes only because the point moves: the particle now at x was at x + ℓσ (upstream, χ = 0)
// σ relaxation times ago, ℓ = τ·V. Superposing the creep responses to the load history gives
//   u(x) = C(x)·p/G_a + (FG_a/G_a)·∫₀^∞ e^{−σ} C(x + ℓσ)·p dσ,
// i.e. the elastic coefficients plus a viscous part: the same corner-function sums at the
// upstream-shifted observation point, weighted by e^{−σ}. The integral has no closed form and is
// taken numerically along the corner lattice (history_corner_rule); the corner sums are the
// elastic make_kernel's.

#include <vector>

#include "elastic/influence.hpp"

namespace rollcontact::elastic {

/// The relaxation integral of a kernel on mx elements of length dx [mm] whose observation points
/// are already moved by shift_x [mm], relaxation length ell [mm] > 0, as a rule along x on the
/// kernel's corner lattice (make_integrated_kernels):
/// the history of corner X_i is the stretch to the next corner plus e^{−δx/ℓ} times the next
/// corner's history, ∫₀^∞ e^{−s/ℓ}F(X_i + s) ds/ℓ = ∫_{X_i}^{X_{i+1}} … + e^{−δx/ℓ}·G_{i+1}, so
/// that F is evaluated once per node and corner row — O(nodes·rows) — where a whole
/// kernel per node costs O(nodes·corners). The corner function has its one kink at x = 0, an
/// x·log|x| (or x·atan) kink: stretches are split there, refined towards it geometrically and
/// graded by t = a + h·u³ in the innermost panel (the Jacobian 3u² turns t·log t into
/// u⁵·log u); panels span at most ℓ, or min(ℓ/4, δx/2) at the kink, with 10 Gauss–Legendre
/// nodes (6 or 4 far from the kink); the last corner's history takes panels growing
/// geometrically to 40ℓ (e^{−40} < 5e−18). Agrees with a kernel per history node (16 nodes
/// per panel) to 7.5e-13 of the largest coefficient (test_viscous_kernel).
CornerXRule history_corner_rule(double ell_mm, double dx_mm, int mx, double shift_x_mm,
                                int nodes = 10);

/// Adds the viscous parts of `material` (CombinedMaterial::viscous) to `kernels`, which hold
/// components cs for the grid and observation shift (shift_x, shift_y) [mm] (divided by G), all
/// on one history lattice (history_corner_rule, make_integrated_kernels). A part with ℓ = 0
/// (τ = 0: the body relaxes at once) adds weight·C exactly, without quadrature.
void add_viscous_parts(const std::vector<Component>& cs, const Grid& grid,
                       const CombinedMaterial& material, double shift_x, double shift_y,
                       std::vector<Kernel>& kernels);

}  // namespace rollcontact::elastic
