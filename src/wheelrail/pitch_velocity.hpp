#pragma once
// The pitch-velocity iteration of a prescribed longitudinal force (CONTACT's experimental F=1,
// spec-additions §A6): the wheelset's VPITCH at which the longitudinal force on the rail, relative
// to the vertical force, equals FX_WS/FZ. Each iterate is a complete solve with the vertical force
// prescribed. Newton with the slope of linear theory for the first step, secant steps after it;
// a step whose relative force jumps by more than the friction coefficient is halved. The steps
// are taken on the force mapped through the inverse of a saturation curve (Shen–Hedrick–Elkins,
// F/(μF_z) = u − u²/3 + u³/27 up to u = 3), so that near full slip, where the force hardly
// changes with VPITCH, the secant still sees an almost linear function.

#include <functional>
#include <string>

namespace rollcontact::wheelrail {

struct PitchVelocitySettings {
  double start_rad_s = 0.0;  ///< first VPITCH
  double target = 0.0;       ///< FX_WS/FZ
  /// Estimate of d(F_x/F_z)/dVPITCH [s/rad] at small creepage for the first step (linear
  /// theory); positive: more negative VPITCH (faster forward spin) drives the wheel.
  double slope_s_per_rad = 0.0;
  double saturation = 0.3;           ///< μ: the largest F_x/F_z friction allows (about)
  double tolerance = 1e-5;           ///< on F_x/F_z − FX_WS/FZ (EPS·μ_min)
  double vertical_tolerance = 1e-5;  ///< EPS of the vertical iteration near the answer
  double max_jump = 0.3;             ///< μ_min: a larger change of F_x/F_z halves the step
  double max_step_rad_s = 1.0;       ///< the largest VPITCH step
  int max_iterations = 30;           ///< MAXNR
  int max_halvings = 10;
};

struct PitchVelocitySample {
  double ratio = 0.0;  ///< F_x/F_z
  bool usable = true;  ///< false: the solve did not converge
  /// |F_z/FZ − 1| of the solve: a loose vertical iteration moves the ratio too (by about a
  /// third of it, F_x ∝ F_z^(2/3) at small creepage), and a secant must see more than that.
  double vertical_error = 0.0;
};

/// The saturation curve's inverse: u with u − u²/3 + u³/27 = y, odd in y; |y| ≥ 1 is taken
/// as 0.999 (the force cannot tell how far beyond saturation it is).
double inverse_saturation(double y);

struct PitchVelocityResult {
  double vpitch_rad_s = 0.0;
  double residual = 0.0;  ///< F_x/F_z − FX_WS/FZ of the result
  int iterations = 0;     ///< solves after the first
  bool converged = false;
  std::string message;
};

/// `first` is the case solved at `settings.start_rad_s` with the vertical iteration to EPS (the
/// caller needs its patches for the slope). `solve(vpitch, inner_tolerance)` runs the complete
/// case at that pitch velocity, its vertical iteration to `inner_tolerance`; the last solve made
/// (the first one if no other) is the one whose results stand.
PitchVelocityResult solve_pitch_velocity(
    const PitchVelocitySettings& settings, PitchVelocitySample first,
    const std::function<PitchVelocitySample(double vpitch, double inner_tolerance)>& solve);

}  // namespace rollcontact::wheelrail
