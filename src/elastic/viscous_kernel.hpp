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
// taken numerically (history_corner_rule; history_quadrature is the per-node reference of the
// tests); the corner sums are the elastic make_kernel's.

#include <vector>

#include "elastic/influence.hpp"

namespace rollcontact::elastic {

/// One node of a rule ∫₀^∞ e^{−s/ℓ} f(s) ds/ℓ ≈ Σ weight·f(s_mm).
struct HistoryNode {
  double s_mm;    ///< upstream distance of the observation point [mm]
  double weight;  ///< includes e^{−s/ℓ}/ℓ and the panel's Jacobian [1/mm · mm = -]
};

/// Nodes for the relaxation integral of a kernel on mx elements of length dx [mm] whose
/// observation points are already moved by shift_x [mm], relaxation length ell [mm] > 0.
///
/// Quadrature: the integrand is the kernel at observation offset dix·dx + shift_x + s, whose
/// corner functions have x·log|x| kinks where a corner abscissa passes zero, i.e. at
/// s = (j + ½)dx − shift_x (the same lattice for every offset), and is analytic in between; beyond
/// the last kink it is analytic and slowly varying (log or 1/r decay on the scale of the distance
/// travelled). The range [0, 40ℓ] (e^{−40} < 5e−18) is split at the kinks, each stretch between
/// two kinks into panels of at most half an element and ℓ/4, then into panels growing
/// geometrically with the distance from the last kink, at most ℓ long. Each panel gets `nodes`
/// Gauss–Legendre points, after the substitution s = a + (b−a)·u³ (or its mirror) at a kink end:
/// the Jacobian 3u² turns t·log t into u⁵·log u. The kernels at the nodes are the continuous
/// corner sums (make_continuous_kernel). Measured (test_viscous_kernel) on the visc_cylindr strip
/// and a 3-D grid: 10 nodes agree with 16 to 3e-12 of the largest coefficient, and with a brute
/// force rule (uniform 4 µm panels) to its own error, 2e-12.
std::vector<HistoryNode> history_quadrature(double ell_mm, double dx_mm, int mx, double shift_x_mm,
                                            int nodes = 10);

/// The same integral as a rule along x on the kernel's corner lattice (make_integrated_kernels):
/// the history of corner X_i is the stretch to the next corner plus e^{−δx/ℓ} times the next
/// corner's history, ∫₀^∞ e^{−s/ℓ}F(X_i + s) ds/ℓ = ∫_{X_i}^{X_{i+1}} … + e^{−δx/ℓ}·G_{i+1}, so
/// that F is evaluated once per node and corner row — O(nodes·rows) — where history_quadrature's
/// kernel per node costs O(nodes·corners). The corner function has its one kink at x = 0 (one
/// element, not a lattice of kinks): stretches are split there and graded towards it, with the
/// panel widths and node counts of history_quadrature; the last corner's history takes panels
/// growing geometrically to 40ℓ. Agrees with history_quadrature's kernels to 1e-11 of the
/// largest coefficient (test_viscous_kernel).
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
