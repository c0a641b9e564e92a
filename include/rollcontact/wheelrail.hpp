#pragma once
// The wheel/rail solver API (CONTACT's module 1): a WheelsetSolver takes a
// model::WheelRailProblem — profiles, track, wheelset position and velocities — and returns the
// contact patches with their reference locations, creepages, tractions and forces, and the
// totals, iterating the wheelset height when the vertical force is prescribed.
//
// Sign conventions (spec/physics.md §13): forces act on the rail; track coordinates x along the
// track, y lateral, z down. For a left wheel all lateral components (y, contact angle, FY, FS,
// MN, η, φ) are given in the left wheel's mirrored frame, as CONTACT prints them.

#include <memory>
#include <string>
#include <vector>

#include "rollcontact/model/wheelrail.hpp"
#include "rollcontact/solution.hpp"
#include "rollcontact/solve.hpp"

namespace rollcontact {

struct Vector3 {
  double x = 0.0, y = 0.0, z = 0.0;
};

/// What a conformal patch (CONTACT's D=4, spec/wheelrail-advanced.md §1) adds: its curved
/// reference surface, one row of the patch grid per sample, and the forces both as integrals in
/// the curvilinear frame (x, s̃, ñ) ("tilde") and turned row by row into the reference's tangent
/// plane ("bar"). For a left wheel, lateral components are mirrored as everywhere else.
struct ConformalPatch {
  bool active = false;  ///< the patch was solved on a curved reference (D=4)
  /// The curved reference per grid row (track coordinates, midway between rail and wheel): y, z
  /// [mm] and the inclination α of its averaged normal [rad], same sense as the contact angle.
  std::vector<double> row_y_mm{}, row_z_mm{}, row_alpha_rad{};
  double ds_mm = 0.0;      ///< row spacing along the curve
  double row0_s_mm = 0.0;  ///< curvilinear position s̃ of row 0's centre (reference at 0)
  int contact_row_first = -1, contact_row_last = -1;  ///< rows with contact (0-based; −1: none)
  double tilde_fn = 0.0, tilde_fx = 0.0, tilde_fs = 0.0;  ///< ∫ p in (x, s̃, ñ) [N]
  double bar_fn = 0.0, bar_fx = 0.0, bar_fs = 0.0;        ///< ∫ R(α − δ)·p, planar frame [N]
  /// Moments about the planar reference axes, the curved grid in planar coordinates [N mm]:
  /// Mxp, Msp, Mnp (MN, the patch's printed torsional moment, is Mnp).
  Vector3 moment_planar{};
  /// V=1: the friction coefficient of each row (at its α); empty otherwise.
  std::vector<double> row_friction{};
};

/// One contact patch.
struct WheelRailPatch {
  Vector3 reference_tr;          ///< reference point in track coordinates [mm]
  double contact_angle_rad = 0;  ///< δ: rotation of the contact plane about the track x-axis
  double y_rail_mm = 0, z_rail_mm = 0;     ///< reference point in rail-profile coordinates
  Vector3 reference_wheel;                 ///< reference point relative to the wheel-profile origin
  double xi = 0, eta = 0, phi_per_mm = 0;  ///< creepages ξ, η [-], spin φ [rad/mm]
  double chi_rad = 0, dq_mm = 1, veloc_mm_s = 1;  ///< rolling direction, step, velocity
  double dx_mm = 0, ds_mm = 0;                    ///< element sizes in effect
  Vector3 force_tr;                               ///< force on the rail, track coordinates [N]
  Vector3 force_ws;                               ///< force on the rail, wheelset coordinates [N]
  /// Moment of the patch's force on the rail (physics.md §13.6: (r_ref − r_marker) × F plus the
  /// torsional moment MN about the contact normal) about the rail marker, in track coordinates,
  /// and about the wheel marker, in wheelset coordinates [N mm].
  Vector3 moment_tr, moment_ws;
  Vector3 reference_ws;                  ///< reference point in wheelset coordinates [mm]
  double s_rail_mm = 0, s_wheel_mm = 0;  ///< arc length of the reference along the profiles
  double delta_rail_rad = 0, delta_wheel_rad = 0;  ///< contact angle in rail/wheel-profile frames
  double pressure_centre_x_mm = 0, pressure_centre_y_mm = 0;  ///< centre of pressure (track)
  model::Friction friction;  ///< the patch's coefficients (they vary with its place for V=1, 2)
  ConformalPatch conformal;  ///< D=4 only (active)
  /// The patch as a module-3 problem: FN, FX and FS (= fy), MN (= mz, about the reference point),
  /// approach, pmax, energy, power, fields on the patch grid (x rolling, y along the contact).
  Solution solution;
};

/// One step of the vertical-force iteration (N=1): wheelset height and the resulting FZ(TR).
struct VerticalForceStep {
  int iteration = 0;
  double z_ws_mm = 0.0;
  double fz_N = 0.0;
  double dfz_dz_N_per_mm = 0.0;
};

/// A profile's origin (marker) placed in the track: position [mm], roll and yaw [rad].
struct ProfileMarker {
  Vector3 position;
  double roll_rad = 0.0, yaw_rad = 0.0;
};

/// The massless rail's state after the case (F=3): the stiffnesses and loads in effect, the
/// deflections found and what is left of the two balance equations.
struct RailDeflection {
  bool active = false;                   ///< the massless rail model was used
  double ky_N_per_mm = 0.0, fy_N = 0.0;  ///< KY_RAIL, FY_RAIL
  double kz_N_per_mm = 0.0, fz_N = 0.0;  ///< KZ_RAIL, FZ_RAIL (N=1, KZ = 0: FZ_RAIL = −FZ)
  double dy_mm = 0.0, dz_mm = 0.0;       ///< DY_DEFL, DZ_DEFL (y in the case's frame, as DYRAIL)
  /// F_y(tr) − ky·δy + fy and F_z(tr) − kz·δz + fz at the result [N].
  double residual_y_N = 0.0, residual_z_N = 0.0;
  int iterations = 0;  ///< lateral iterates (full vertical solves)
};

struct WheelRailSolution {
  std::vector<WheelRailPatch> patches;  ///< sorted by lateral position; empty: no contact
  Vector3 force_tr, force_ws;           ///< totals on the rail [N]
  Vector3 moment_tr, moment_ws;         ///< totals about the markers (as per patch) [N mm]
  ProfileMarker rail_marker_tr;         ///< rail-profile origin in track coordinates
  ProfileMarker wheel_marker_tr;        ///< wheel-profile origin in track coordinates
  ProfileMarker wheel_marker_ws;        ///< wheel-profile origin in wheelset coordinates
  double z_ws_mm = 0.0;                 ///< wheelset height used (solved when FZ is prescribed)
  /// Combined elastic constants of rail and wheel (spec/physics.md §3.1), for the report.
  CombinedMaterial material;
  double vpitch_rad_s = 0.0;  ///< pitch velocity used (solved when FX_WS is prescribed, F=1)
  /// F=1: the outer iterates on VPITCH (complete N=1 solves), 0 otherwise.
  int pitch_iterations = 0;
  std::vector<VerticalForceStep> trace;  ///< N=1 iterates (iteration 0: geometry only)
  RailDeflection rail_deflection;        ///< F=3 only
  bool converged = true;
  std::string message;                ///< why not converged
  std::vector<std::string> warnings;  ///< adjustments made (grid coarsened, ...)
  /// Wall time of this case [s]: profile placement, contact search and patch set-up (geometry)
  /// and the patch solves, over all vertical-force iterates. Not part of the result files.
  double geometry_seconds = 0.0, patch_solve_seconds = 0.0;
  /// The part of patch_solve_seconds spent setting the patch problems up: discretisation,
  /// influence kernels, operators, FFT plans, preconditioners [s] (`run --timing`'s set-up).
  double patch_setup_seconds = 0.0;
};

/// Solves wheel/rail cases one after another, keeping the profile curves while the profiles stay
/// the same and one PatchSolver per patch position (cached influence operators). Not
/// thread-safe; independent solvers may run in different threads.
class WheelsetSolver {
 public:
  explicit WheelsetSolver(SolveOptions options = {});
  ~WheelsetSolver();
  WheelsetSolver(WheelsetSolver&&) noexcept;
  WheelsetSolver& operator=(WheelsetSolver&&) noexcept;
  WheelsetSolver(const WheelsetSolver&) = delete;
  WheelsetSolver& operator=(const WheelsetSolver&) = delete;

  /// Throws GeometryError for profiles or placements that make no sense (a profile of the wrong
  /// length, contact at a profile end in the first case), ProblemError for inadmissible data.
  /// Non-convergence is reported in the solution, never silent.
  WheelRailSolution solve(const model::WheelRailProblem& problem);

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace rollcontact
