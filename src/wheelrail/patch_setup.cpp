#include "wheelrail/patch_setup.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

#include "rollcontact/errors.hpp"
#include "wheelrail/conformal_patch.hpp"

namespace rollcontact::wheelrail {

namespace {

/// Undeformed distance per element along the local normal (ix fastest), minimum shifted to 0.
/// `rail_n`: the rail surface's normal coordinate per element [mm] (NaN where there is none).
std::vector<double> undeformed_distance(const PlacedProfiles& prof, const WheelsetPose& pose,
                                        const ContactFrame& f, const PatchSetup& s, int mx, int my,
                                        double& pen, std::vector<double>& rail_n) {
  std::vector<double> h(static_cast<std::size_t>(mx) * static_cast<std::size_t>(my), kFarAway);
  rail_n.assign(h.size(), std::numeric_limits<double>::quiet_NaN());
  double h_min = kFarAway;
  RowStart carry;
  for (int j = 0; j < my; ++j) {
    const Vec3 on_line = f.origin + (s.ds_mm * (s.iy0 + j) - s.origin_y_mm) * f.es;
    trace_row(
        prof, pose, f, on_line, mx, s.dx_mm, s.ix0, s.origin_x_mm,
        [&](int i, Vec3, double t_rail, double t_wheel) {
          const double v = t_rail - t_wheel;
          const std::size_t e = static_cast<std::size_t>(j) * static_cast<std::size_t>(mx) +
                                static_cast<std::size_t>(i);
          h[e] = v;
          rail_n[e] = t_rail;
          h_min = std::min(h_min, v);
        },
        &carry);
  }
  pen = -h_min;
  for (double& v : h)
    if (v < kFarAway) v -= h_min;
  return h;
}

/// Release 25.1's check of the planar approach (wheelrail-advanced.md §6.1): where the rail
/// surface between two lateral neighbours deep in the interpenetration (more than 0.04 mm
/// before the approach is split off) is inclined more than 13.9° to the patch plane, the planar
/// gap is more than 3 % off. Returns the warning, or an empty string.
std::string angle_variation_warning(const std::vector<double>& h, const std::vector<double>& rail_n,
                                    double pen, int mx, int my, double ds) {
  constexpr double kDeep = -0.04, kMinTangent = 1.0 / 1.03;
  int pairs = 0;
  double t_min = 1.0;
  for (int j = 0; j + 1 < my; ++j)
    for (int i = 0; i < mx; ++i) {
      const std::size_t a =
          static_cast<std::size_t>(j) * static_cast<std::size_t>(mx) + static_cast<std::size_t>(i);
      const std::size_t b = a + static_cast<std::size_t>(mx);
      if (!(h[a] - pen < kDeep && h[b] - pen < kDeep)) continue;
      const double dn = rail_n[b] - rail_n[a];
      const double t_s = ds / std::hypot(ds, dn);
      if (!(t_s < kMinTangent)) continue;
      ++pairs;
      t_min = std::min(t_min, t_s);
    }
  if (pairs == 0) return {};
  return fmt::format(
      "large angle variation within contact patch, ignored in the planar contact approach: {} "
      "element pairs where the rail is inclined up to {:.1f} deg to the patch plane (gap error up "
      "to {:.0f} %); conformal contact (D=4) accounts for it",
      pairs, std::acos(t_min) * 180.0 / std::numbers::pi, 100.0 * (1.0 / t_min - 1.0));
}

/// Regions combined at a distance between D_COMB and D_SEP: IPLAN=4 rectangles, one lateral
/// band per region split half-way between them, with the regions' interaction factors.
void set_attenuated_parts(const PlacedProfiles& prof, const ContactRegion& region,
                          const ContactFrame& f, model::UndeformedDistance& gap) {
  const std::size_t n = region.parts.size();
  if (n < 2) return;
  constexpr double kAll = 1e6;  // [mm] beyond any grid
  std::vector<double> bounds{-kAll};
  for (std::size_t a = 0; a + 1 < n; ++a) {
    const double y_mid = 0.5 * (region.parts[a].y_max + region.parts[a + 1].y_min);
    const Vec3 on_rail{f.origin.x, y_mid, prof.rail_at_track_y(y_mid).z};
    bounds.push_back(dot(on_rail - f.origin, f.es));
  }
  bounds.push_back(kAll);
  gap.iplan = 4;
  gap.npatch = static_cast<int>(n);
  gap.planform.clear();
  for (std::size_t a = 0; a < n; ++a) {
    const double lo = std::min(bounds[a], bounds[a + 1]), hi = std::max(bounds[a], bounds[a + 1]);
    gap.planform.insert(gap.planform.end(), {-kAll, kAll, lo, hi});
  }
  gap.patch_factors.clear();
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n; ++b)
      gap.patch_factors.push_back(region.part_factors[a * n + b]);
}

/// Element centres at multiples of (DX, DS) covering [x_lo, x_hi] × [s_lo, s_hi] (in the frame
/// whose origin the reference point has at s.origin_*) plus a guard element per side; sets
/// s.ix0, s.iy0, s.dx_mm, s.ds_mm and returns (mx, my). DX, DS are doubled while the grid has
/// NPOT_MAX elements or more — except on a super grid, whose element positions must stay.
std::pair<int, int> size_grid(const model::WheelRailProblem& p, double x_lo, double x_hi,
                              double s_lo, double s_hi, PatchSetup& s,
                              std::vector<std::string>& warnings) {
  s.dx_mm = p.search.dx_mm;
  s.ds_mm = p.search.ds_mm;
  int mx = 0, my = 0;
  const bool fixed = on_super_grid(p);
  for (int doubling = 0;; ++doubling) {
    const GridAxis ax = cover_axis(x_lo, x_hi, s.dx_mm);
    const GridAxis ay = cover_axis(std::min(s_lo, s_hi), std::max(s_lo, s_hi), s.ds_mm);
    s.ix0 = ax.first;
    s.iy0 = ay.first;
    mx = ax.count;
    my = ay.count;
    if (static_cast<long>(mx) * my < p.search.max_elements || doubling > 20 || fixed) break;
    s.dx_mm *= 2.0;
    s.ds_mm *= 2.0;
    warnings.push_back(fmt::format(
        "the patch grid would have {} elements, more than NPOT_MAX = {}: DX, DS doubled to "
        "{:g}, {:g} mm",
        static_cast<long>(mx) * my, p.search.max_elements, s.dx_mm, s.ds_mm));
  }
  return {mx, my};
}

/// True when the undeformed surfaces interpenetrate (h < PEN) in the first or last column.
bool interpenetrates_at_x_ends(const std::vector<double>& h, int mx, int my, double pen) {
  for (int j = 0; j < my; ++j) {
    const std::size_t row = static_cast<std::size_t>(j) * static_cast<std::size_t>(mx);
    if (h[row] < pen || h[row + static_cast<std::size_t>(mx) - 1] < pen) return true;
  }
  return false;
}

}  // namespace

GridAxis cover_axis(double lo, double hi, double h) {
  GridAxis a;
  a.first = static_cast<int>(std::floor(lo / h)) - 1;
  a.count = static_cast<int>(std::ceil(hi / h)) + 1 - a.first + 1;
  // Grid sizes rounded up to multiples of 8 (extra elements split over both ends): the
  // influence kernels and FFT plans depend on the size only, so the force iteration and
  // neighbouring cases reuse them instead of recomputing (measured: most of the solve time).
  const int pad = (8 - a.count % 8) % 8;
  a.first -= pad / 2;
  a.count += pad;
  return a;
}

ContactFrame contact_frame(const ContactRegion& region) {
  ContactFrame f;
  f.origin = region.reference;
  f.delta_rad = region.delta_rad;
  const double c = std::cos(f.delta_rad), s = std::sin(f.delta_rad);
  f.es = {0.0, c, s};
  f.en = {0.0, -s, c};
  return f;
}

namespace {

/// Creepages from the material velocities v of the rail (P) and wheel (Q) points and the bodies'
/// angular velocities ω, relative to the rolling speed: ξ, η = (v_P − v_Q)·(e_x, e_s)/V,
/// φ = (ω_P − ω_Q)·e_n/V (physics.md §13.5).
void set_creepages(PatchKinematics& k, const ContactFrame& f, Vec3 v_P, Vec3 v_Q, Vec3 omega_P,
                   Vec3 omega_Q) {
  if (!(k.veloc_mm_s >= 1e-6)) return;
  const Vec3 dv = v_P - v_Q;
  k.xi = dot(dv, f.ex) / k.veloc_mm_s;
  k.eta = dot(dv, f.es) / k.veloc_mm_s;
  k.phi_per_mm = dot(omega_P - omega_Q, f.en) / k.veloc_mm_s;
}

}  // namespace

WheelPointMotion wheel_point_motion(const model::WheelRailProblem& p, const WheelsetPose& pose,
                                    const PlacedProfiles& prof, Vec3 Q) {
  const model::WheelsetState& m = p.motion;
  const Vec3 r_Q = Q - pose.centre;
  WheelPointMotion w;
  w.omega = pose.rotation * Vec3{m.vroll_rad_s, m.vpitch_rad_s, m.vyaw_rad_s};
  w.v = Vec3{m.vs_mm_s, m.vy_mm_s, m.vz_mm_s} + cross(w.omega, r_Q);
  const model::WheelDeviation& d = p.wheel_deviation;
  if (d.rates()) {
    const Vec3 omega_w{d.vroll_rad_s, d.vpitch_rad_s, d.vyaw_rad_s};
    const Vec3 lever = pose.rotation.transposed_times(r_Q) - wheel_marker_ws(p, prof);
    w.v = w.v + pose.rotation * (Vec3{d.vx_mm_s, d.vy_mm_s, d.vz_mm_s} + cross(omega_w, lever));
    w.omega = w.omega + pose.rotation * omega_w;
  }
  return w;
}

Vec3 rail_point_velocity(const model::WheelRailProblem& p, const PlacedProfiles& prof, Vec3 P) {
  const model::RailState& rs = p.rail_state;
  const double yaw_rate_track = -p.motion.vs_mm_s * p.track.curvature_per_mm;
  const Vec3 rail_origin{0.0, prof.rail_y_mm(), prof.rail_z_mm()};
  return Vec3{0.0, rs.vy_mm_s, rs.vz_mm_s} +
         cross(Vec3{rs.vroll_rad_s, 0.0, 0.0}, P - rail_origin) +
         cross(Vec3{0.0, 0.0, yaw_rate_track}, P);
}

Vec3 roller_point_velocity(const model::WheelRailProblem& p, const PlacedProfiles& prof, Vec3 P) {
  const model::RailState& rs = p.rail_state;
  const Vec3 axle{0.0, 0.0, prof.roller_axle_z_mm()};
  const double rpitch = p.roller.pitch_rate_rad_s;
  const double yaw_rate = -std::abs(P.z - axle.z) * rpitch * p.track.curvature_per_mm;
  const Vec3 rail_origin{0.0, prof.rail_y_mm(), prof.rail_z_mm()};
  return cross(Vec3{0.0, rpitch, yaw_rate}, P - axle) + Vec3{0.0, rs.vy_mm_s, rs.vz_mm_s} +
         cross(Vec3{rs.vroll_rad_s, 0.0, 0.0}, P - rail_origin);
}

namespace {

/// T=1 (shifts): the velocity line holds the increments of one step, so the "velocity"
/// differences are the shift distances themselves: V = 1, χ = 0, δq = 1
/// (wheelrail-advanced.md §5.2).
bool is_shift(const model::WheelRailProblem& p) {
  return p.patch.tangential.kind == model::TangentialKind::Shift;
}
void as_shift(PatchKinematics& k) {
  k.veloc_mm_s = 1.0;
  k.chi_rad = 0.0;
  k.dq_mm = 1.0;
}

/// Roller rig (spec/wheelrail-advanced.md §4.3): the contact stays where it is and both bodies
/// turn through it — the roller about its axle (0, y, z_axle) at RPITCH (yawing at
/// −r·RPITCH·CURV, r the contact's distance from the axle), the wheel about its own. V is the
/// mean material speed through the contact, χ = 0 when the material leaves towards −x.
PatchKinematics roller_kinematics(const model::WheelRailProblem& p, const WheelsetPose& pose,
                                  const PlacedProfiles& prof, const ContactFrame& f,
                                  double pen_mm) {
  const model::RailState& rs = p.rail_state;
  const Vec3 P = f.origin;
  const Vec3 axle{0.0, 0.0, prof.roller_axle_z_mm()};
  const double rpitch = p.roller.pitch_rate_rad_s;
  const double yaw_rate = -std::abs(P.z - axle.z) * rpitch * p.track.curvature_per_mm;
  const Vec3 omega_P{rs.vroll_rad_s, rpitch, yaw_rate};
  const Vec3 v_P = roller_point_velocity(p, prof, P);
  const WheelPointMotion q = wheel_point_motion(p, pose, prof, P + pen_mm * f.en);
  const Vec3 v_Q = q.v, omega_Q = q.omega;
  PatchKinematics k;
  const double vp = dot(v_P, f.ex), vq = dot(v_Q, f.ex);
  k.veloc_mm_s = 0.5 * std::abs(vp + vq);
  const bool forward =
      (std::abs(vp) >= std::abs(vq) && vp <= 0.0) || (std::abs(vq) > std::abs(vp) && vq <= 0.0);
  k.chi_rad = forward ? 0.0 : std::numbers::pi;
  k.dq_mm = p.search.dq_rel * p.search.dx_mm;
  if (is_shift(p)) as_shift(k);
  set_creepages(k, f, v_P, v_Q, omega_P, omega_Q);
  return k;
}

/// Track (physics.md §13.5): the rail at rest but for its deviation rates and the curve's yaw;
/// V the mean of the wheelset's forward speed and its rolling speed, χ from their signs.
PatchKinematics track_kinematics(const model::WheelRailProblem& p, const WheelsetPose& pose,
                                 const PlacedProfiles& prof, const ContactFrame& f, double pen_mm) {
  const model::WheelsetState& m = p.motion;
  const model::RailState& rs = p.rail_state;
  // Rail material point P: rail deviation rates and the track's yaw rate in a curve.
  const Vec3 P = f.origin;
  const double yaw_rate_track = -m.vs_mm_s * p.track.curvature_per_mm;
  const Vec3 omega_P{rs.vroll_rad_s, 0.0, yaw_rate_track};
  const Vec3 rail_origin{0.0, prof.rail_y_mm(), prof.rail_z_mm()};
  Vec3 v_P =
      Vec3{0.0, rs.vy_mm_s, rs.vz_mm_s} + cross(Vec3{rs.vroll_rad_s, 0.0, 0.0}, P - rail_origin);
  v_P.x += -yaw_rate_track * P.y;
  // Wheel point Q at distance PEN along the normal (the undeformed wheel surface).
  const Vec3 r_Q = (P + pen_mm * f.en) - pose.centre;
  const WheelPointMotion q = wheel_point_motion(p, pose, prof, P + pen_mm * f.en);
  const Vec3 v_Q = q.v, omega_Q = q.omega;
  const double v_roll = cross(pose.rotation * Vec3{0.0, m.vpitch_rad_s, 0.0}, r_Q).x;
  const double v_est = v_Q.x - v_P.x - v_roll;

  PatchKinematics k;
  k.veloc_mm_s = 0.5 * (std::abs(v_est) + std::abs(v_roll));
  const bool forward = (std::abs(v_est) >= std::abs(v_roll) && v_est >= 0.0) ||
                       (std::abs(v_roll) > std::abs(v_est) && v_roll <= 0.0);
  k.chi_rad = forward ? 0.0 : std::numbers::pi;
  k.dq_mm = p.search.dq_rel * p.search.dx_mm;
  if (is_shift(p)) as_shift(k);
  set_creepages(k, f, v_P, v_Q, omega_P, omega_Q);
  return k;
}

}  // namespace

bool on_super_grid(const model::WheelRailProblem& p) {
  const model::TangentialKind k = p.patch.tangential.kind;
  return k == model::TangentialKind::Shift || k == model::TangentialKind::TransientRolling;
}

PatchKinematics patch_kinematics(const model::WheelRailProblem& p, const WheelsetPose& pose,
                                 const PlacedProfiles& prof, const ContactFrame& f, double pen_mm) {
  return p.roller.enabled ? roller_kinematics(p, pose, prof, f, pen_mm)
                          : track_kinematics(p, pose, prof, f, pen_mm);
}

namespace {
/// The planar patch (D=2): grid, undeformed distance along the patch normal and approach; the
/// grid is lengthened while a sliced wheel interpenetrates up to its ends.
void setup_planar_grid(const model::WheelRailProblem& p, const PlacedProfiles& prof,
                       const WheelsetPose& pose, double x_lo, double x_hi, double s_lo, double s_hi,
                       PatchSetup& s, std::vector<std::string>& warnings);
}  // namespace

namespace {
/// The inclination table of the influence coefficients' correction (C=4, wheelrail-advanced.md
/// §1.7): a conformal patch's rows at their curvilinear positions with their inclinations, the
/// plane of a planar patch as one inclination (no correction).
void set_inclinations(const PatchSetup& s, model::InclinationCorrection& c) {
  if (!c.active()) return;
  c.y_mm.clear();
  c.alpha_rad.clear();
  if (!s.curved) {
    c.y_mm.push_back(0.0);
    c.alpha_rad.push_back(s.frame.delta_rad);
    return;
  }
  for (std::size_t i = 0; i < s.curved->rows(); ++i) {
    c.y_mm.push_back(s.curved->s_tilde(i));
    c.alpha_rad.push_back(s.curved->alpha[i]);
  }
}
}  // namespace

PatchSetup setup_patch(const model::WheelRailProblem& p, const PlacedProfiles& prof,
                       const WheelsetPose& pose, const ContactRegion& region,
                       std::vector<std::string>& warnings, const SuperGridBox* previous_contact) {
  PatchSetup s;
  s.frame = contact_frame(region);
  // Lateral extent: the region's rail arc length around the reference point.
  const double y_r = prof.rail_y_mm();
  const double s_ref = prof.rail().at_y(region.reference.y - y_r).s;
  double s_lo = prof.rail().at_y(region.y_min - y_r).s - s_ref;
  double s_hi = prof.rail().at_y(region.y_max - y_r).s - s_ref;
  double x_lo = region.x_min - region.reference.x, x_hi = region.x_max - region.reference.x;
  if (s_lo > s_hi) std::swap(s_lo, s_hi);
  if (on_super_grid(p)) {
    // The super grid (wheelrail-advanced.md §5.2): x in the track frame that moves with the
    // wheelset (T=2) or in the world (T=1: S_WS + x), y the rail arc length; the grid covers the
    // continued patch's previous contact area too, so no traction of it is lost.
    s.origin_x_mm = (is_shift(p) ? p.motion.s_mm : 0.0) + region.reference.x;
    s.origin_y_mm = s_ref;
    // Continued when the previous contact area overlaps this region (bounding boxes).
    s.continued = previous_contact != nullptr && previous_contact->x_lo <= x_hi + s.origin_x_mm &&
                  previous_contact->x_hi >= x_lo + s.origin_x_mm &&
                  previous_contact->y_lo <= s_hi + s.origin_y_mm &&
                  previous_contact->y_hi >= s_lo + s.origin_y_mm;
    if (s.continued) {
      x_lo = std::min(x_lo, previous_contact->x_lo - s.origin_x_mm);
      x_hi = std::max(x_hi, previous_contact->x_hi - s.origin_x_mm);
      s_lo = std::min(s_lo, previous_contact->y_lo - s.origin_y_mm);
      s_hi = std::max(s_hi, previous_contact->y_hi - s.origin_y_mm);
    }
  }
  model::PatchProblem& q = s.problem;
  if (p.search.conformal) {
    q = p.patch;
    setup_conformal_patch(p, prof, pose, region, {x_lo, x_hi, s_lo, s_hi}, s, warnings);
  } else {
    setup_planar_grid(p, prof, pose, x_lo, x_hi, s_lo, s_hi, s, warnings);
    // A patch whose plane was turned (D_SEP < d ≤ D_TURN) measures its undeformed distance
    // along the turned normal, 1/cos Δ times the surfaces' own normal distance where they are
    // locally parallel. Its approach is the interpenetration along its own normal, PEN·cos Δ;
    // the shape h − min h stays the turned plane's (mbench_a22_varfric c3: CONTACT's tread PEN
    // 6.464 µm and FN 1536 N, ours 6.481 / 1539, with PEN along the turned normal 6.505 / 1548;
    // docs/decisions.md).
    if (region.angle_turned) s.pen_mm *= std::cos(region.delta_rad - region.delta_own_rad);
    s.kinematics = patch_kinematics(p, pose, prof, s.frame, s.pen_mm);
  }
  set_attenuated_parts(prof, region, s.frame, q.gap);
  set_inclinations(s, q.bodies.inclination);
  q.normal.kind = model::NormalLoadKind::Approach;
  q.normal.approach_mm = s.pen_mm;
  q.tangential.creepage = {s.kinematics.xi, s.kinematics.eta, s.kinematics.phi_per_mm};
  q.rolling.direction_rad = s.kinematics.chi_rad;
  q.rolling.step_mm = s.kinematics.dq_mm;
  q.rolling.velocity_mm_per_s = s.kinematics.veloc_mm_s;
  q.sequence.origin_x_mm = s.origin_x_mm;
  q.sequence.origin_y_mm = s.origin_y_mm;
  return s;
}

namespace {

void setup_planar_grid(const model::WheelRailProblem& p, const PlacedProfiles& prof,
                       const WheelsetPose& pose, double x_lo, double x_hi, double s_lo, double s_hi,
                       PatchSetup& s, std::vector<std::string>& warnings) {
  model::PatchProblem& q = s.problem;
  std::vector<double> rail_n;  // the rail surface per element, for the angle-variation check
  for (int widening = 0;; ++widening) {
    const auto [mx, my] = size_grid(p, x_lo + s.origin_x_mm, x_hi + s.origin_x_mm,
                                    s_lo + s.origin_y_mm, s_hi + s.origin_y_mm, s, warnings);
    q = p.patch;
    q.potential = {};
    q.potential.ipotcn = 1;
    q.potential.mx = mx;
    q.potential.my = my;
    q.potential.values = {(s.ix0 - 0.5) * s.dx_mm - s.origin_x_mm,
                          (s.iy0 - 0.5) * s.ds_mm - s.origin_y_mm, s.dx_mm, s.ds_mm};
    q.gap = {};
    q.gap.ibase = 9;
    q.gap.iplan = 1;
    q.gap.values = undeformed_distance(prof, pose, s.frame, s, mx, my, s.pen_mm, rail_n);
    // The region's length comes from the round wheel's curvature; a sliced wheel can be flatter
    // along x (a worn flat) and interpenetrate up to the grid's ends: lengthen it then.
    if (prof.wheel_surface() == nullptr || widening == 4 ||
        !interpenetrates_at_x_ends(q.gap.values, mx, my, s.pen_mm))
      break;
    const double grow = 0.25 * (x_hi - x_lo);
    x_lo -= grow;
    x_hi += grow;
  }
  const std::string angles = angle_variation_warning(q.gap.values, rail_n, s.pen_mm, q.potential.mx,
                                                     q.potential.my, s.ds_mm);
  if (!angles.empty()) warnings.push_back(angles);
}

}  // namespace

}  // namespace rollcontact::wheelrail
