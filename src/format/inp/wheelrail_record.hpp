#pragma once
// WheelRailRecord: the plain-data description of one module-1 (wheel/rail) case of a CONTACT
// .inp file (spec/inp-format.md §5), fully resolved: "keep" digits carry the values of the
// previous case of the same result element. Units as in CONTACT: mm, N, N/mm², s, rad; velocities
// in mm/s, angular velocities in rad/s.

#include <cmath>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "format/inp/case_record.hpp"
#include "rollcontact/model/profile.hpp"

namespace rollcontact::format {

/// At most this many control points of a V=1,2 friction variation (NVF ≤ 10, inp-format.md §3).
inline constexpr int kMaxFrictionSets = 10;

/// V=1,2 friction variation (spec/inp-format.md §5, line 7'): one set of law values per control
/// point. The scalar members of WheelRailRecord::friction hold the first set.
struct VariableFriction {
  int v = 0;  ///< 0 one set, 1 vs. rail surface inclination, 2 vs. track position
  /// Control points, strictly increasing: ALPHA [rad] (V=1) or SVF [mm] (V=2).
  std::vector<double> positions;
  std::vector<FrictionValues> sets;  ///< law values per control point
};

/// Discretisation line (D=2..9): `DX DS DQREL A_SEP D_SEP D_COMB {D_TURN {G_MISS}}`.
struct WheelRailDiscretisation {
  int method = 2;       ///< D digit in effect: 2 planar/locus, 4 conformal, 5 planar/brute force
  double dx = 0.2;      ///< element size in rolling direction [mm]
  double ds = 0.2;      ///< element size along the contact curve [mm]
  double dqrel = 1.0;   ///< rolling step relative to DX [-], in [5e-7, 10]
  double a_sep = 0.0;   ///< angle separating contact patches [rad] (negative input: 0)
  double d_sep = 0.0;   ///< distance separating patches [mm] (negative input: 0)
  double d_comb = 0.0;  ///< distance below which patches are combined [mm] (<= d_sep)
  double d_turn =
      0.0;  ///< turning point of the combination weights [mm] (default 2 d_sep - d_comb)
  double g_miss = -1.0;  ///< gap below which near misses are kept [mm] (negative: ignored)
};

/// Track dimensions (Z=1,3). Which members are meaningful depends on GAUGHT and the C1 digit.
struct TrackDimensions {
  double gaught = 14.0;    ///< gauge height [mm]; <= 0: rail position given by RAILY0, RAILZ0
  double gaugsq = 0.0;     ///< GAUGHT > 0: gauge square (unused by CONTACT)
  double gaugwd = 1435.0;  ///< GAUGHT > 0: gauge width [mm]
  double raily0 = 0.0, railz0 = 0.0;  ///< GAUGHT <= 0: rail profile origin position [mm]
  double cant = 0.0;                  ///< rail cant [rad] (track, C1=0,1)
  double nomradr = 0.0;               ///< nominal roller radius [mm] (roller rigs, C1=4,5)
  double curv = 0.0;                  ///< track curvature [1/mm]
};

/// Rail profile or wheel profile line (spec/inp-format.md §5.1) plus the profile it names.
struct ProfileSpec {
  std::string file;       ///< name as written in the .inp file
  std::string path;       ///< resolved against the .inp folder
  int mirror_y = 0;       ///< -1/0 as is, 1 mirror y
  double scale_yz = 1.0;  ///< file units -> mm (values <= 1e-6 clamped to 1e-6)
  double smooth = 0.0;    ///< spline parameter λ or filter wavelength [mm]; <= 0 none
  int mirror_z = 0;       ///< 0 auto-detect (Miniprof/plain), -1 as is, 1 mirror z
  int prfopt = 0;         ///< number of extra option lines read (0..2)
  int ismooth = 0;        ///< 0 unweighted spline, 1 weighted spline, 2 weighted B-spline
  double zigthrs = 5.0 * std::numbers::pi / 6.0;  ///< zig-zag threshold [rad]
  double kinkhigh = std::numbers::pi / 6.0;       ///< kink threshold high [rad]
  double kinklow = std::numbers::pi / 30.0;       ///< kink threshold low [rad]
  double kinkwid = 2.0;                           ///< half window for kink detection [mm]
  int errhnd = 0;                                 ///< error handling verbosity -2..1
  double maxomit = 0.5;  ///< max fraction of points removed in clean-up [0..1]
  bool sliced = false;   ///< true: `slices` holds the profile (.slcs/.slcw), else `profile`
  /// The points as read, never null. Shared and immutable: every later case that keeps the
  /// profile copies its record from the one before (spec/inp-format.md §5), and a sweep of
  /// thousands of cases holds one copy of each profile instead of one per case.
  std::shared_ptr<const Profile> profile = std::make_shared<const Profile>();
  std::shared_ptr<const SlicedProfile> slices = std::make_shared<const SlicedProfile>();
};

/// Rail deviations and their rates (Z=2,3).
struct RailDeviations {
  double dy = 0.0, dz = 0.0;  ///< lateral / vertical rail shift [mm]
  double droll = 0.0;         ///< rail roll [rad]
  double vy = 0.0, vz = 0.0;  ///< rates [mm/s]
  double vroll = 0.0;         ///< roll rate [rad/s]
};

/// Massless rail model (F=3, Z=2,3).
struct MasslessRail {
  double ky = 0.0, fy = 0.0;  ///< lateral stiffness [N/mm] and force [N]
  double kz = 0.0, fz = 0.0;  ///< vertical stiffness [N/mm] and force [N]
  double dystep0 = 1.0;       ///< initial step of the lateral iteration [mm]
};

/// Wheelset geometry (E=3,5).
struct WheelsetDimensions {
  double fbdist = 1360.0;  ///< flange back distance [mm]
  double fbpos = -70.0;    ///< flange back position in the wheel profile [mm]
  double nomradw = 460.0;  ///< nominal wheel radius [mm], >= 1e-3
  double ytape = 1000.0;   ///< tape circle position [mm] (1000: no correction)
};

/// Wheelset position (E=1..5) and velocity (E=2..5). For T=1 the velocities are increments per
/// step (shift of s, y, z [mm], roll, yaw, pitch [rad]).
struct WheelsetMotion {
  double s = 0.0;   ///< C1=0,1: position along the track S_WS [mm]; C1=4,5: X_WS [mm]
  double y = 0.0;   ///< lateral position Y_WS [mm]
  double z = 0.0;   ///< vertical position Z_WS [mm] (N=0)
  double fz = 0.0;  ///< vertical force FZ [N] (N=1)
  double roll = 0.0, yaw = 0.0, pitch = 0.0;  ///< orientation [rad]
  double vs = 0.0;                            ///< C1=0,1: forward velocity VS_WS [mm/s]
  double rpitch = 0.0;                        ///< C1=4,5: roller angular velocity [rad/s]
  double vy = 0.0, vz = 0.0;                  ///< [mm/s]
  double vroll = 0.0, vyaw = 0.0;             ///< [rad/s]
  double vpitch = 0.0;                        ///< F=0,3: wheelset angular velocity [rad/s]
  double fx = 0.0;  ///< F=1 (experimental): longitudinal force FX_WS [N] replaces VPITCH
  double my = 0.0;  ///< F=2 (experimental): pitch moment MY_WS [N·mm] replaces VPITCH
};

/// Flexible wheel deviations and their rates (E=4,5).
struct WheelDeviations {
  double dx = 0.0, dy = 0.0, dz = 0.0;           ///< [mm]
  double droll = 0.0, dyaw = 0.0, dpitch = 0.0;  ///< [rad]
  double vx = 0.0, vy = 0.0, vz = 0.0;           ///< [mm/s]
  double vroll = 0.0, vyaw = 0.0, vpitch = 0.0;  ///< [rad/s]

  /// True when a deviation or rate exceeds `threshold` in magnitude (0: any is set).
  [[nodiscard]] bool any_above(double threshold) const noexcept {
    for (const double v : {dx, dy, dz, droll, dyaw, dpitch, vx, vy, vz, vroll, vyaw, vpitch})
      if (std::abs(v) > threshold) return true;
    return false;
  }
};

/// One module-1 wheel/rail case.
struct WheelRailRecord {
  int case_number = 1;     ///< 1-based, per result element (shared with module 3)
  int result_element = 0;  ///< REID
  /// Control digits (spec/inp-format.md §3); `digits.c` is the influence-coefficient digit C3,
  /// `digits.d` the D digit as read. Module 1 has no IPOTCN/IBASE: `digits.z`, `digits.e` are the
  /// track and wheelset digits.
  ControlDigits digits;
  int config = 0;  ///< C1: 0 left / 1 right wheel on track, 4 left / 5 right wheel on roller
  SolverSettings solver;
  int npot_max = 20000;  ///< max elements of the potential contact (clamped to 100..1e6)
  Friction friction;     ///< law in effect (L=1 resolved); V=1,2 sets in `variable_friction`
  VariableFriction variable_friction;
  Materials materials;  ///< body 1 = rail, body 2 = wheel; C=4: conformal.if_meth/variant only
  Damping damping;
  HeatParameters heat;
  WheelRailDiscretisation discretisation;
  TrackDimensions track;
  ProfileSpec rail;
  RailDeviations rail_deviations;
  bool has_massless_rail = false;  ///< F=3 data present
  MasslessRail massless_rail;
  WheelsetDimensions wheelset;
  ProfileSpec wheel;
  WheelsetMotion motion;
  WheelDeviations wheel_deviations;
  Subsurface subsurface;
  SourceInfo source;

  bool is_roller() const noexcept { return config >= 4; }
  bool is_left() const noexcept { return config == 0 || config == 4; }
};

}  // namespace rollcontact::format
