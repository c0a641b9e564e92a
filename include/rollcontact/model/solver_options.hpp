#pragma once
// How (not what) a patch is solved: tolerances, iteration limits and the solver choice.

namespace rollcontact::model {

/// Which iteration solves the tangential problem of the exact theory.
enum class TangentialMethod {
  Default,   ///< semismooth Newton with Krylov inner solves (docs/decisions.md); for steady
             ///< rolling in the role of CONTACT's SteadyGS
  ConvexGS,  ///< Gauss–Seidel with the exact element solution ("ConvexGS")
};

/// Where the slip-velocity iteration of a velocity-dependent friction law starts (INISLP,
/// physics.md §10.3); with falling friction the choice can select between several solutions.
enum class InitialSlipVelocity {
  Previous,        ///< INISLP = 0: the previous case's slip velocities (zero without one)
  Zero,            ///< INISLP > 0: from below, μ = μ_static everywhere
  RollingVelocity  ///< INISLP < 0: from above, s_a = V in every contact element
};

struct SolverOptions {
  double tolerance = 1e-5;  ///< relative tolerance of every iteration [-]
  /// Relative tolerance of the tangential iterations when larger than `tolerance`: an iterate
  /// whose solution only informs the next step (the first full solve of the vertical-force
  /// iteration); 0: `tolerance`. The normal problem keeps `tolerance` (its force is a sample of
  /// the iteration). Such a solution has no displacements beyond the normal solve's u_n and no
  /// elastic energy (nothing uses them).
  double rough_tolerance = 0.0;
  /// KPEC/ANALYN pressures (B=5, 6): leave out u_n = A·p_n and the elastic energy, which cost a
  /// half-space product the pressures themselves never need. For a caller that makes many trial
  /// solves (the vertical-force iteration) and completes the one it keeps with
  /// PatchSolver::complete_elastic_energy().
  bool defer_elastic_energy = false;
  int max_inner_iterations = 999;        ///< CG / Gauss–Seidel / Krylov products
  int max_newton_iterations = 30;        ///< force iteration (prescribed tangential forces)
  int max_normal_tangential_passes = 1;  ///< Panagiotopoulos passes (1: Johnson's process)
  TangentialMethod tangential_method = TangentialMethod::Default;
  /// Gauss–Seidel relaxation in adhesion and slip (ConvexGS); 0: the solver's default.
  double relaxation_adhesion = 0.0, relaxation_slip = 0.0;
  /// Velocity-dependent friction: start, over-relaxation ω_slp (OMGSLP) and the most passes of
  /// the slip-velocity fixed point (CONTACT: max(1, MAXIN − 10)).
  InitialSlipVelocity initial_slip_velocity = InitialSlipVelocity::Previous;
  double slip_velocity_relaxation = 1.0;
  int max_slip_velocity_passes = 90;
};

}  // namespace rollcontact::model
