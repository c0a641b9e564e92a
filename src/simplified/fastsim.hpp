#pragma once
// Modified Fastsim (spec/physics.md §11.3): Kalker's simplified theory, in which the surface
// displacement of each element depends on its own traction only, u = L·p/k, integrated along
// the rolling direction with a traction bound μ·p_n per element.

#include <span>
#include <vector>

#include "physics/friction_law.hpp"
#include "rollcontact/grid.hpp"
#include "rollcontact/solution.hpp"
#include "simplified/flexibility.hpp"

namespace rollcontact::simplified {

/// Tractions, displacements and slip of a simplified-theory solution; grid.size() entries each.
struct SimplifiedFields {
  std::vector<double> px, py;  ///< tangential tractions on body 1 [N/mm²]
  std::vector<double> ux, uy;  ///< displacement differences u = L·p [mm]
  std::vector<double> sx, sy;  ///< slip per step S = u − u′ + W [mm]
  std::vector<ElementState> state;
  std::vector<double> mu;  ///< velocity-dependent friction: μ per element (else empty)
};

/// Friction that falls with the slip velocity, with memory (physics.md §10.1-10.2). As in
/// CONTACT, Fastsim evaluates the law at each element's rigid slip velocity V·|w| (one pass, no
/// slip-velocity iteration): μ_I = θ·μ′_I + (1 − θ)·μ_s(V|w_I|), θ = d_c/(d_c + δt·max(V|w_I|,
/// s₀)), μ′ the upstream element's μ (steady; the first element of a row enters with μ_s at its
/// own rigid slip velocity) or the previous time's (transient); μ_I·p_n is the element's
/// traction bound, in adhesion and in slip (docs/decisions.md: CONTACT's tractcurv cases 91-120
/// to the printed digits).
struct FastsimVelocityFriction {
  const physics::FrictionLaw* law = nullptr;
  double memory_distance_mm = 0.0;       ///< d_c (MEMDST)
  double memory_floor_speed_mm_s = 0.0;  ///< s₀ (MEM_S0)
  double dt_s = 1.0;                     ///< time step δq/V [s]
};

struct FastsimInput {
  Grid grid;
  std::span<const double> pn;      ///< normal pressure [N/mm²]; contact where pn > 0
  double mu = 0.3;                 ///< friction coefficient [-]
  std::span<const double> wx, wy;  ///< rigid shift per step W [mm], spin parts already scaled
  Flexibilities flex;              ///< effective flexibilities L/k [mm³/N] (l3 unused here)
  bool steady = true;              ///< T=3: u′ from the upstream element; T=2: from ux_prev
  double chi = 0.0;  ///< rolling direction [rad]; steady: cos χ > 0 sweeps from ix = MX−1 down
  /// Transient rolling: displacement of the same particles at the previous time [mm] (empty: 0).
  std::span<const double> ux_prev, uy_prev;
  /// Velocity-dependent friction (nullptr: the bound μ·p_n); in transient rolling and shifts μ′
  /// is mu_prev, the same particle's μ at the previous time (upstream_memory()), in steady
  /// rolling the upstream element's μ. A particle without one (entering the contact, negative
  /// mu_prev, or none at all) starts with μ_s at its own rigid slip velocity, as the first
  /// element of a row does in steady rolling: a transient run of constant creepage then ends in
  /// the steady state (docs/decisions.md).
  const FastsimVelocityFriction* velocity = nullptr;
  std::span<const double> mu_prev;
  /// With velocity-dependent friction: the rigid slip velocity V·|w| per element [mm/s] (the
  /// rigid shift per step without the spin scaling of the flexibilities, over δt).
  std::span<const double> rigid_speed;
};

/// One Fastsim pass. Per contact element: adhesion trial u = u′ − W, p = u/L; if |p| > μp_n the
/// element slips with p scaled onto the bound and u = L·p. Exterior elements get zeros. With
/// velocity-dependent friction μ is the element's (FastsimVelocityFriction).
SimplifiedFields fastsim(const FastsimInput& in);

/// Displacement of the same particles one step earlier for transient rolling: `u` (previous
/// case, same grid) evaluated at (x + δq cos χ, y + δq sin χ) by bilinear interpolation of the
/// element-centre values, 0 where the point lies outside the grid. δq [mm].
std::vector<double> upstream_field(const Grid& grid, std::span<const double> u, double chi,
                                   double dq);

/// The friction memory μ′ of the same particles one step earlier for transient rolling: `mu`
/// (previous case, same grid) at the upstream points as upstream_field() takes them,
/// interpolated over the neighbours that were in contact (pn > 0) only; −1 where none was (the
/// particle enters the contact). dq = 0: each element's own (a shift moves no particles).
std::vector<double> upstream_memory(const Grid& grid, std::span<const double> mu,
                                    std::span<const double> pn, double chi, double dq);

}  // namespace rollcontact::simplified
