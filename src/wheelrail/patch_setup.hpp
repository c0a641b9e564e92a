#pragma once
// From a contact region to a module-3 patch problem (spec/physics.md §13.4, §13.5): the local
// frame (origin at the reference point, turned by the contact angle δ about the track x-axis),
// the grid of element centres at multiples of (DX, DS) covering the region, the undeformed
// distance along the local normal, the approach, and the creepages from the kinematics.

#include <optional>

#include "rollcontact/model/patch_problem.hpp"
#include "rollcontact/model/wheelrail.hpp"
#include "wheelrail/contact_search.hpp"
#include "wheelrail/curved_reference.hpp"
#include "wheelrail/frames.hpp"
#include "wheelrail/wheelset_pose.hpp"

namespace rollcontact::wheelrail {

/// The local contact frame of a patch in track coordinates.
struct ContactFrame {
  Vec3 origin;               ///< reference point on the rail
  double delta_rad = 0.0;    ///< contact angle
  Vec3 ex{1, 0, 0}, es, en;  ///< rolling direction, along the contact, normal into the rail
};

ContactFrame contact_frame(const ContactRegion& region);

/// Creepages and rolling of a patch (physics.md §13.5).
struct PatchKinematics {
  double xi = 0.0, eta = 0.0, phi_per_mm = 0.0;
  double chi_rad = 0.0, dq_mm = 1.0, veloc_mm_s = 1.0;
};

PatchKinematics patch_kinematics(const model::WheelRailProblem& problem, const WheelsetPose& pose,
                                 const PlacedProfiles& profiles, const ContactFrame& frame,
                                 double pen_mm);

/// A rectangle of a sequence's super grid [mm]: x along the track frame (T=1: the world),
/// y the rail arc length.
struct SuperGridBox {
  double x_lo = 0.0, x_hi = 0.0, y_lo = 0.0, y_hi = 0.0;
};

struct PatchSetup {
  ContactFrame frame;
  double dx_mm = 0.0, ds_mm = 0.0;  ///< element sizes in effect (doubled for NPOT_MAX)
  /// The grid's origin (the reference point) on the super grid of a transient sequence (T=1, 2;
  /// spec/wheelrail-advanced.md §5.2): element centres lie at multiples of (DX, DS) there, at
  /// local x = ix·dx − origin_x. 0, 0 otherwise (centres at multiples from the reference).
  double origin_x_mm = 0.0, origin_y_mm = 0.0;
  int ix0 = 0, iy0 = 0;  ///< super-grid index of the first element centre (X = ix·dx)
  /// Super grid: the patch continues the previous case's patch given to setup_patch (their
  /// areas overlap; wheelrail-advanced.md §5.3), and its grid covers that one's contact.
  bool continued = false;
  double pen_mm = 0.0;  ///< approach: −min h
  PatchKinematics kinematics;
  model::PatchProblem problem;  ///< ready for PatchSolver::solve
  /// Conformal contact (D=4): the curved reference, one sample per grid row; the grid's y is
  /// the curvilinear s̃ and each row has its own normal (conformal_patch.hpp).
  std::optional<CurvedReference> curved;
};

/// Velocity v and angular velocity ω of the wheel's material point at Q [track]: the wheelset's
/// motion, plus on a flexible wheelset the wheel's deviation rates about its marker m
/// (wheelrail-advanced.md §5.1): v_Q = v_ws + ω_ws × r_Q + R·(v_w + ω_w × (q − m)), ω_Q = ω_ws
/// + R·ω_w, q = Rᵀ·r_Q the point in wheelset coordinates.
struct WheelPointMotion {
  Vec3 v, omega;
};
WheelPointMotion wheel_point_motion(const model::WheelRailProblem& problem,
                                    const WheelsetPose& pose, const PlacedProfiles& profiles,
                                    Vec3 Q);

/// Velocity of the rail's material point P of a track [track, mm/s]: the rail's deviation rates
/// (VYRAIL, VZRAIL, VROLLR about its origin) and the track's yaw rate −VS·CURV in a curve.
Vec3 rail_point_velocity(const model::WheelRailProblem& problem, const PlacedProfiles& profiles,
                         Vec3 P);

/// Velocity of a roller's material point P [track, mm/s]: its rotation RPITCH about the axle
/// (yawing at −r·RPITCH·CURV, r the distance from the axle) and the rail deviation rates
/// (wheelrail-advanced.md §4.3).
Vec3 roller_point_velocity(const model::WheelRailProblem& problem, const PlacedProfiles& profiles,
                           Vec3 P);

/// Element centres at multiples of h covering [lo, hi] plus one guard element per side, their
/// number rounded up to a multiple of 8 (kernels and FFT plans are reused by size): centre k of
/// the axis lies at (first + k)·h.
struct GridAxis {
  int first = 0, count = 0;
};
GridAxis cover_axis(double lo_mm, double hi_mm, double h_mm);

/// True for the tangential problems whose patches live on a super grid (T=1 shifts, T=2
/// transient rolling).
bool on_super_grid(const model::WheelRailProblem& problem);

/// The undeformed distance of an element whose line meets no wheel: never in contact [mm].
inline constexpr double kFarAway = 1e3;

/// Where the previous row's rail and first wheel point were found: the next row, DS away,
/// starts its Newton iterations there (trace_row's `carry`).
struct RowStart {
  bool valid = false;
  double t_rail = 0.0, t_wheel = 0.0;
  CurveHint hint;
};

/// One grid row of a patch: from the row's point `on_line` in the patch plane, the lines along
/// the patch normal f.en through its mx elements (x = dx·(ix0 + i) − origin_x), where they meet
/// the rail and the wheel (distances t_rail, t_wheel along f.en). Calls visit(i, point, t_rail,
/// t_wheel) for each element where both are found; nothing when the rail is not below the row.
/// The wheel's profile segment and distance carry from element to element (a prismatic rail's
/// distance is the row's; a roller's or sliced rail's is found per element), and with `carry`
/// from row to row (read as this row's start, replaced by its first element's).
template <class Visit>
void trace_row(const PlacedProfiles& prof, const WheelsetPose& pose, const ContactFrame& f,
               Vec3 on_line, int mx, double dx_mm, int ix0, double origin_x_mm, Visit&& visit,
               RowStart* carry = nullptr) {
  double t_rail = 0.0;
  const bool from_last_row = carry != nullptr && carry->valid;
  if (!rail_surface_along(prof, on_line, f.en, from_last_row ? carry->t_rail : 0.0, t_rail)) return;
  double t_wheel = t_rail;
  CurveHint hint;  // the wheel profile segment, carried along the row
  if (from_last_row) {
    t_wheel = carry->t_wheel;
    hint = carry->hint;
  }
  bool first_found = false;
  // The last three elements' solutions on one profile segment: the next one starts from their
  // quadratic extrapolation. The wheel's distance varies like x²/2R along a row, so a linear
  // extrapolation from two is off by dx²/R (~5e-4 mm) and Newton needs a second evaluation to
  // confirm its step; the quadratic one is off by the third difference (~1e-9 mm at DX 0.5 mm),
  // below the convergence step, and one evaluation does.
  int known = 0;  // consecutive elements solved on segment hint.segment, up to 3
  double t_hist[3] = {0.0, 0.0, 0.0}, u_hist[3] = {0.0, 0.0, 0.0};  // [0]: the latest
  for (int i = 0; i < mx; ++i) {
    const Vec3 point = on_line + (dx_mm * (ix0 + i) - origin_x_mm) * f.ex;
    double t_rail_here = t_rail;
    if (prof.rail_varies_along_x() && !rail_surface_along(prof, point, f.en, t_rail, t_rail_here)) {
      known = 0;
      continue;
    }
    double t_start = t_wheel;
    if (known == 3) {
      t_start = 3.0 * (t_hist[0] - t_hist[1]) + t_hist[2];
      hint.t = 3.0 * (u_hist[0] - u_hist[1]) + u_hist[2];
    } else if (known == 2) {
      t_start = 2.0 * t_hist[0] - t_hist[1];
      hint.t = 2.0 * u_hist[0] - u_hist[1];
    }
    const std::size_t segment_before = hint.segment;
    if (!wheel_surface_along(prof, pose, point, f.en, t_start, t_wheel, &hint)) {
      t_wheel = t_rail_here;
      known = 0;
      continue;
    }
    if (hint.segment != segment_before) known = 0;
    if (carry != nullptr && !first_found) {
      *carry = {true, t_rail, t_wheel, hint};
      first_found = true;
    }
    t_hist[2] = t_hist[1];
    t_hist[1] = t_hist[0];
    t_hist[0] = t_wheel;
    u_hist[2] = u_hist[1];
    u_hist[1] = u_hist[0];
    u_hist[0] = hint.t;
    known = std::min(known + 1, 3);
    visit(i, point, t_rail_here, t_wheel);
  }
}

/// Builds the patch problem of `region`; the grid is coarsened (DX, DS doubled) until it has
/// fewer than NPOT_MAX elements (not on a super grid). `warnings` receives such adjustments.
/// `previous_contact` (super grid only): the continued patch's contact area in the previous
/// case, which the grid is enlarged to cover.
PatchSetup setup_patch(const model::WheelRailProblem& problem, const PlacedProfiles& profiles,
                       const WheelsetPose& pose, const ContactRegion& region,
                       std::vector<std::string>& warnings,
                       const SuperGridBox* previous_contact = nullptr);

}  // namespace rollcontact::wheelrail
