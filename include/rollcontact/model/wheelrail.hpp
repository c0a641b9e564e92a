#pragma once
// WheelRailProblem: one wheel on one rail (CONTACT's module 1, spec/physics.md §13) — physics
// only. The .inp reader, the TOML reader and a C++ program build it; the WheelsetSolver solves
// it: profiles → placement → contact search → one PatchProblem per contact patch → totals,
// with the vertical-force iteration when FZ is prescribed.
//
// Frames (spec/physics.md §13.2): track coordinates x along the track, y lateral towards the
// field side of the rail, z downwards; all geometry is computed for a right-side wheel. A left
// wheel is described in the mirrored frame (its inputs read as those of a right wheel) and its
// printed y-components change sign. Units: mm, N, rad, s; velocities mm/s, rad/s.

#include <numbers>
#include <string>
#include <vector>

#include "rollcontact/model/patch_problem.hpp"
#include "rollcontact/model/profile.hpp"

namespace rollcontact::model {

enum class WheelSide { Left, Right };

/// How a profile's points become a smooth curve (spec/inp-format.md §5.1, physics.md §13.1).
struct ProfileSmoothing {
  int method = 0;       ///< ISMOOTH: 0 unweighted spline (λ = smooth), 1 weighted (L_filt)
  double smooth = 0.0;  ///< ISMOOTH 0: λ; 1: filter wavelength L_filt [mm]; <= 0: interpolate
  double zigzag_threshold_rad = 5.0 * std::numbers::pi / 6.0;  ///< ZIGTHRS
  double kink_high_rad = std::numbers::pi / 6.0;               ///< KINKHIGH
  double kink_low_rad = std::numbers::pi / 30.0;               ///< KINKLOW
  double kink_window_mm = 2.0;                                 ///< KINKWID
  double max_omitted_fraction = 0.5;                           ///< MAXOMIT
};

/// A rail or wheel profile in canonical form (Profile: mm, z down, y to the field side).
/// A profile that varies (spec/physics.md §13.9): for a wheel, slices around its circumference
/// (`.slcw`, θ [rad]); for a rail, slices along the track (`.slcs`, u = S_WS + x [mm]: switches
/// and crossings; the rail then placed absolutely, GAUGHT ≤ 0). Each slice is smoothed like
/// `points`. Empty: a plain profile.
struct WheelRailProfile {
  Profile points;
  ProfileSmoothing smoothing;
  SlicedProfile slices;  ///< `points` then holds the first slice
};

/// How the contact search finds the wheel's lowest points (CONTACT's D digit).
enum class ContactSearch {
  Locus,    ///< D=2: the contact locus, one point per wheel-profile circle (physics.md §13.3)
  GapGrid,  ///< D=5: the vertical gap minimised along x at every lateral sample (§A2)
};

/// Contact search and patch grids (the D=2 line).
struct ContactSearchSettings {
  double dx_mm = 0.2;                       ///< element size in rolling direction
  double ds_mm = 0.2;                       ///< element size along the contact curve
  double dq_rel = 1.0;                      ///< rolling step relative to dx
  double a_sep_rad = std::numbers::pi / 2;  ///< angle above which patches are separate
  double d_sep_mm = 8.0;                    ///< distance above which patches are separate
  double d_comb_mm = 4.0;                   ///< distance below which patches are combined
  double d_turn_mm = 12.0;                  ///< distance above which patches are independent
  /// G_MISS: CONTACT keeps near misses below this gap as tentative patches for its force
  /// iteration's predictions; they carry no force, and the Brent iteration here needs no
  /// prediction, so they are accepted and not reported (docs/decisions.md).
  double g_miss_mm = -1.0;
  int max_elements = 20000;  ///< NPOT_MAX: larger grids are coarsened (dx, ds ×2)
  /// GAPWGT: how the reference point weighs the gap samples, by ∫g² dx over the interpenetrated
  /// length (false, CONTACT's default) or ∫g dx (true; spec/physics.md §13.3 step 4).
  bool linear_gap_weights = false;
  ContactSearch method = ContactSearch::Locus;
  /// D=4, conformal contact: each patch found by the search is solved on a curved reference
  /// surface between rail and wheel (gap along the local normals, rigid slip per element,
  /// forces in the curvilinear and the planar frame; spec/wheelrail-advanced.md §1) instead of
  /// the reference point's tangent plane. Steady rolling and static cases on a track.
  bool conformal = false;
};

/// Track and rail position (Z=1,3). On a roller rig the same placement positions the roller
/// profile (GAUGHT > 0: laterally only, its origin at DZRAIL) and the cant is ignored.
struct Track {
  double gauge_height_mm = 14.0;              ///< > 0: the rail is placed by its gauge point
  double gauge_width_mm = 1435.0;             ///< used when gauge_height_mm > 0
  double rail_y0_mm = 0.0, rail_z0_mm = 0.0;  ///< used when gauge_height_mm <= 0
  double cant_rad = 0.0;
  double curvature_per_mm = 0.0;
};

/// A roller rig instead of a track (CONTACT's C1 = 4, 5; spec/wheelrail-advanced.md §4): the
/// rail profile is the roller's, a body of revolution about an axle parallel to the track's y
/// axis at x = 0, NOMRADR below the profile origin (z down). The wheelset does not move forward
/// (VS = 0); the roller turns at RPITCH and carries its surface past the contact.
struct RollerRig {
  bool enabled = false;
  /// NOMRADR: distance from the roller axle to the roller profile's origin [mm]. Negative: an
  /// internal roller (a ring, the wheel runs on its inside, the axle lies above the contact);
  /// its magnitude must exceed the wheel's radius.
  double nominal_radius_mm = 0.0;
  /// RPITCH: the roller's angular velocity about its axle [rad/s]; on an external roller,
  /// positive for forward rolling (the wheel's VPITCH then negative).
  double pitch_rate_rad_s = 0.0;
  /// Speed of the roller surface at its nominal radius, RPITCH·NOMRADR [mm/s]: the rolling speed
  /// that VS is on a track.
  double surface_speed_mm_s() const noexcept { return pitch_rate_rad_s * nominal_radius_mm; }
};

/// Rail deviations from the track design and their rates.
struct RailState {
  double dy_mm = 0.0, dz_mm = 0.0, droll_rad = 0.0;
  double vy_mm_s = 0.0, vz_mm_s = 0.0, vroll_rad_s = 0.0;
};

/// Where the wheel profile sits on the wheelset.
struct WheelsetGeometry {
  double flange_back_distance_mm = 1360.0;  ///< FBDIST
  double flange_back_position_mm = -70.0;   ///< FBPOS, in wheel-profile y
  double nominal_radius_mm = 460.0;         ///< NOMRADW
  double tape_circle_y_mm = 1000.0;         ///< YTAPE (|y| >= 999: no correction)
};

/// Wheelset position, orientation and velocities in track coordinates.
struct WheelsetState {
  double s_mm = 0.0;  ///< S_WS along the track (roller rig: X_WS, reported only)
  double y_mm = 0.0;
  double z_mm = 0.0;  ///< vertical position (prescribed position)
  double fz_N = 0.0;  ///< vertical force on the rail (prescribed force)
  double roll_rad = 0.0, yaw_rad = 0.0, pitch_rad = 0.0;
  double vs_mm_s = 0.0;  ///< forward velocity VS (roller rig: 0, the roller turns instead)
  double vy_mm_s = 0.0, vz_mm_s = 0.0;
  double vroll_rad_s = 0.0, vyaw_rad_s = 0.0, vpitch_rad_s = 0.0;
  /// Longitudinal force on the rail in wheelset coordinates FX_WS [N] (LongitudinalLoading::Force
  /// only; CONTACT's F=1): the pitch velocity is then solved for.
  double fx_ws_N = 0.0;
  /// Pitch moment on the rail about the wheelset's axle, in wheelset coordinates, MY_WS [N·mm]
  /// (LongitudinalLoading::Moment only; CONTACT's experimental F=2): the pitch velocity is then
  /// solved for.
  double my_ws_Nmm = 0.0;
};

/// A flexible wheelset (CONTACT's E = 4, 5; spec/wheelrail-advanced.md §5.1): the wheel's
/// deviation from its place on the rigid wheelset, in wheelset coordinates, and its rates. The
/// wheel turns by DROLLW about x and DYAWW about z around its profile origin (the marker, at
/// the tape circle's lowest point) and shifts by (DXWHL, DYWHL, DZWHL); DPITCHW turns an
/// out-of-round wheel's slices only. Lateral values are signed as the rail deviations: positive
/// towards +y of the track for either wheel (a left wheel's are mirrored with its other inputs).
/// A static deviation changes the geometry only; creepage comes from the rates.
struct WheelDeviation {
  double dx_mm = 0.0, dy_mm = 0.0, dz_mm = 0.0;
  double droll_rad = 0.0, dyaw_rad = 0.0, dpitch_rad = 0.0;
  double vx_mm_s = 0.0, vy_mm_s = 0.0, vz_mm_s = 0.0;
  double vroll_rad_s = 0.0, vyaw_rad_s = 0.0, vpitch_rad_s = 0.0;
  bool any() const noexcept {
    return dx_mm != 0.0 || dy_mm != 0.0 || dz_mm != 0.0 || droll_rad != 0.0 || dyaw_rad != 0.0 ||
           dpitch_rad != 0.0 || rates();
  }
  bool rates() const noexcept {
    return vx_mm_s != 0.0 || vy_mm_s != 0.0 || vz_mm_s != 0.0 || vroll_rad_s != 0.0 ||
           vyaw_rad_s != 0.0 || vpitch_rad_s != 0.0;
  }
};

enum class VerticalLoading { Position, Force };

/// What fixes the wheelset's rolling: its pitch velocity VPITCH (F=0), or the longitudinal
/// force FX_WS on the rail with VPITCH solved for (CONTACT's experimental F=1; requires the
/// vertical force prescribed, spec-additions §A6).
enum class LongitudinalLoading { PitchVelocity, Force, Moment };

/// The massless rail model (CONTACT's F=3, spec/wheelrail-advanced.md §2): the rail deflects
/// laterally by δy and vertically by δz [mm] until the contact force on it, a linear spring and a
/// prescribed external load balance: F_y(tr) − ky·δy + fy = 0, F_z(tr) − kz·δz + fz = 0. A
/// time-integrating caller models damping c with k = k_rail + c/Δt, f = f_ext + c·δ_prev/Δt.
/// δy, δz shift the rail's placement like DYRAIL, DZRAIL (y in the case's own frame, as DYRAIL).
struct MasslessRail {
  bool enabled = false;
  double ky_N_per_mm = 0.0, fy_N = 0.0;  ///< KYRAIL, FYRAIL
  double kz_N_per_mm = 0.0, fz_N = 0.0;  ///< KZRAIL, FZRAIL
  double dystep0_mm = 1.0;               ///< DYSTEP0: expected order of δy (first step)
};

/// Friction that varies with where the contact is (CONTACT's V digit in module 1): Coulomb
/// coefficients at control points, interpolated linearly in between and constant outside.
struct FrictionVariation {
  enum class Along {
    None,             ///< V=0: the patch template's friction everywhere
    RailInclination,  ///< V=1: by the contact angle at the patch's reference point [rad]
    TrackPosition,    ///< V=2: by the contact's position along the track, S_WS + x [mm]
  };
  Along along = Along::None;
  std::vector<double> positions;  ///< strictly increasing control points
  std::vector<Friction> values;   ///< one Coulomb pair per control point
};

struct WheelRailProblem {
  WheelSide side = WheelSide::Right;
  /// Bodies (1 = rail, 2 = wheel), friction, kind of tangential problem, pressure model, solver
  /// options and the sequence link: everything every patch shares. The wheel/rail solver fills in
  /// each patch's grid, undeformed distance, approach, creepages and rolling.
  PatchProblem patch;
  WheelRailProfile rail, wheel;
  Track track;
  RollerRig roller;  ///< C1 = 4, 5; disabled: the wheel runs on a track
  RailState rail_state;
  WheelsetGeometry wheelset;
  WheelsetState motion;
  WheelDeviation wheel_deviation;  ///< E = 4, 5; all zero: a rigid wheelset
  VerticalLoading vertical = VerticalLoading::Force;
  LongitudinalLoading longitudinal = LongitudinalLoading::PitchVelocity;
  MasslessRail massless_rail;  ///< F=3; disabled: a rigid rail (δy = δz = 0)
  ContactSearchSettings search;
  /// The first case of a sequence: contact at a profile end is an error (misplaced wheel).
  bool first_of_sequence = true;
  /// CONTACT's I ≥ 1: the vertical-force iteration starts from the previous case's approach
  /// (scaled to this FZ) instead of a Hertz estimate — the start, not the answer; for time steps
  /// of an MBS code, whose consecutive cases differ little.
  bool estimate_from_previous_case = false;
  FrictionVariation friction_variation;  ///< V=1, 2; Along::None: patch.friction
  /// Refuse (NotSupportedError) what is known to differ from CONTACT's references
  /// (docs/decisions.md): KPEC with interpenetration beyond the equivalent ellipse, ANALYN on a
  /// patch combined from several regions, patches whose angles the D_TURN rule turned, and
  /// wheel slices (the contact location on a flat). False: solve them, each with a warning in
  /// WheelRailSolution::warnings ("not validated against CONTACT: ..."). The `.inp` route sets
  /// it unless the run asks for unvalidated features (`rollcontact run --unvalidated`).
  bool validated_only = false;
};

/// The rolling speed of a problem [mm/s]: VS on a track, RPITCH·NOMRADR on a roller rig (the
/// wheel's free-rolling VPITCH is about −speed/NOMRADW in both).
inline double rolling_speed_mm_s(const WheelRailProblem& p) noexcept {
  return p.roller.enabled ? p.roller.surface_speed_mm_s() : p.motion.vs_mm_s;
}

}  // namespace rollcontact::model
