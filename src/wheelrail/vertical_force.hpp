#pragma once
// The vertical-force iteration (N=1, spec/physics.md §13.7, spec-additions §A4): the wheelset
// height z_ws at which the vertical force on the rail equals FZ. Iterate 0 is geometry only (the
// height at which contact starts); iterate 1 a Hertz estimate; then proposals of a power-law
// model of every patch (F_n,i = C_i·pen_i^1.5) inside a bracket that shrinks with every full
// solve, with bisection as the fall-back.

#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "rollcontact/wheelrail.hpp"

namespace rollcontact::wheelrail {

/// What a full solve at one height says about each patch, for the power-law model.
struct PatchForceSample {
  double pen_mm = 0.0;     ///< approach of the patch
  double delta_rad = 0.0;  ///< contact angle
  double fn_N = 0.0, fs_N = 0.0;
  int contact_elements = -1;  ///< elements in contact (−1: not known)
};

struct HeightSample {
  double z_mm = 0.0;
  double fz_N = 0.0;  ///< vertical force on the rail at this height
  std::vector<PatchForceSample> patches;
};

struct VerticalForceSettings {
  double target_N = 0.0;
  double tolerance = 1e-5;  ///< EPS: relative on the force, absolute [mm] on steps of z
  int max_iterations = 30;  ///< MAXNR
  /// The massless rail with prescribed z_ws (N=0, F=3): z is the wheel height over the undeflected
  /// rail, z_shift = z_ws − δz, and the equation F_z(z) − kz·(z_ws − z) + fz = 0 is solved as
  /// F_z(z) + spring·z = target with spring = kz, target = kz·z_ws − fz [N/mm, N]. 0: F_z = target.
  double spring_N_per_mm = 0.0;
  /// > 0: the force tolerance is tolerance·force_scale_N instead of tolerance·target [N].
  double force_scale_N = 0.0;
  /// F_z(z) is continuous (pressures of the half-space theory). KPEC's and ANALYN's F_z jumps
  /// where their equivalent ellipse changes, and where the answer is a bracket around a jump
  /// the path decides its side: solve_vertical_force_split then takes no shortcuts (the full
  /// solve as the estimates' first sample, the share correction without estimates).
  bool continuous_force = true;
};

struct VerticalForceResult {
  double z_mm = 0.0;
  bool converged = false;
  std::string message;
  std::vector<VerticalForceStep> trace;
  /// Not converged because F_z jumps over the target between these heights [mm]; NaN otherwise.
  double jump_lo_mm = std::numeric_limits<double>::quiet_NaN();
  double jump_hi_mm = std::numeric_limits<double>::quiet_NaN();
};

/// `start_mm`: the height where contact starts (iterate 0), `first_guess_mm` the Hertz estimate.
/// `solve_at(z)` runs the full contact problem and returns the forces; the last call is the one
/// whose results stand.
/// `known`, if given, is a sample of the same F_z(z) solved before (not traced again): the
/// bracket and the secant start from it.
VerticalForceResult solve_vertical_force(const VerticalForceSettings& settings, double start_mm,
                                         double first_guess_mm,
                                         const std::function<HeightSample(double)>& solve_at,
                                         const HeightSample* known = nullptr);

/// Estimates F_z from normal solves only: `fs_ratio[i]` = F_s/F_n of patch i at the last full
/// solve (the tangential share of F_z = F_n cos δ + F_s sin δ).
using NormalOnlySolve = std::function<HeightSample(double z, const std::vector<double>& fs_ratio)>;

/// The same iteration with cheap iterates: a full solve (`full_at`) at the first guess, then z_ws
/// iterated on normal solves (`normal_at`) whose F_z takes the tangential share of the last
/// full solve, and a full solve at each converged estimate, which decides. After 6 rounds the
/// plain iteration on full solves takes over. The last full solve's results stand, as above.
/// (Tried: the previous case's shares instead of the first full solve; their error of a few
/// newtons in F_z costs a second round more often than it saves one.) `rough_first_at`, if
/// given, makes the first full solve instead: one whose tangential tractions need only inform
/// the first round (a looser tolerance); should it meet the target already, full_at repeats it.
VerticalForceResult solve_vertical_force_split(
    const VerticalForceSettings& settings, double start_mm, double first_guess_mm,
    const std::function<HeightSample(double)>& full_at, const NormalOnlySolve& normal_at,
    const std::function<HeightSample(double)>* rough_first_at = nullptr);

}  // namespace rollcontact::wheelrail
