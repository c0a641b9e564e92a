#pragma once
// The simplified tangential problem of one case (M = 2, 3, 5; spec/physics.md §11): flexibilities
// from the ellipse, blending and slope reduction, the rigid shift with scaled spin, Fastsim and
// for M=5 the FaStrip correction.

#include <span>
#include <vector>

#include "rollcontact/grid.hpp"
#include "rollcontact/model/patch_problem.hpp"
#include "rollcontact/solution.hpp"
#include "simplified/fastsim.hpp"
#include "simplified/flexibility.hpp"
#include "simplified/kalker_coefficients.hpp"

namespace rollcontact::simplified {

/// Which simplified model and its parameters (the M digit and the M-specific material line).
struct SimplifiedModel {
  int m = 3;             ///< 2: Fastsim with one flexibility; 3: three; 5: FaStrip
  double flx = 0.0;      ///< M=2: the flexibility [mm³/N]
  SlopeReduction slope;  ///< K0_MF, ALFAMF, BETAMF
  bool blend = true;     ///< M=3,5 with prescribed creepages (F=0): blend L1..L3
};

/// The simplified model of a patch problem: its compliance model and parameters, and whether
/// the creepages are prescribed (blending). Throws ProblemError for Fastsim with one
/// flexibility ≤ 0 and for k0 ≤ 0.
SimplifiedModel simplified_model(const model::PatchProblem& problem);

/// Rigid shift per step split into the part without spin and the spin part [mm], so that the
/// spin part can be scaled by L1/L3 and L2/L3 (physics.md §5).
struct RigidShiftParts {
  std::vector<double> wx, wy;          ///< ξ, η (and extra rigid slip) part
  std::vector<double> spin_x, spin_y;  ///< φ part
};
RigidShiftParts rigid_shift_parts(const Grid& grid, const model::PatchProblem& problem,
                                  const EffectiveKinematics& kin, const Creepages& cr);

struct SimplifiedCase {
  Grid grid;
  std::span<const double> pn;  ///< normal pressure [N/mm²]
  /// Semi-axes for the flexibilities and the blending [mm]: Hertz values for Hertzian IPOTCN,
  /// else the equivalent ellipse. Slope reduction and FaStrip always use the equivalent ellipse
  /// of the contact set (computed here).
  Ellipse ellipse;
  double g = 0.0, nu = 0.0;  ///< combined material [N/mm², -]
  double mu = 0.3;           ///< friction coefficient [-]
  /// Velocity-dependent friction (Fastsim only; nullptr: Coulomb with `mu`), with μ of the
  /// previous time for transient rolling (empty: μ_static).
  const FastsimVelocityFriction* velocity = nullptr;
  std::span<const double> mu_prev;
  double fn = 0.0;  ///< total normal force [N]
  SimplifiedModel model;
  Creepages creepages;
  const RigidShiftParts* shift = nullptr;    ///< for these creepages
  bool steady = true;                        ///< T=3 (else T=2 with ux_prev, uy_prev)
  double chi = 0.0;                          ///< rolling direction [rad]
  std::span<const double> ux_prev, uy_prev;  ///< T=2: u′ of the same particles [mm]
};

struct SimplifiedOutcome {
  SimplifiedFields fields;
  Flexibilities flex;  ///< flexibilities after blending, before the slope reduction [mm³/N]
  double k_eff = 1.0;  ///< slope reduction factor (effective flexibilities L/k)
  KalkerCoefficients coefficients;
};

/// Solves the simplified tangential problem. Throws ProblemError for a degenerate ellipse.
SimplifiedOutcome solve_simplified(const SimplifiedCase& c);

}  // namespace rollcontact::simplified
