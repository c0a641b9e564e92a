// From patch solutions to the wheel/rail outputs (spec/physics.md §13.6): forces and moments in
// track and wheelset coordinates, reference points in the profiles' frames, markers, the mirror
// image of a left wheel, and the quantities the iterations need of a solution.

#include "wheelrail/wheelset_results.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "simplified/flexibility.hpp"
#include "simplified/kalker_coefficients.hpp"
#include "wheelrail/conformal_patch.hpp"

namespace rollcontact::wheelrail {

namespace {

/// Centre of pressure of a solution in its own grid coordinates [mm] (0, 0 without pressure).
std::pair<double, double> pressure_centre(const Solution& s) {
  double sum = 0.0, sx = 0.0, sy = 0.0;
  for (int iy = 0; iy < s.grid.my; ++iy)
    for (int ix = 0; ix < s.grid.mx; ++ix) {
      const double p = s.pn.empty() ? 0.0 : s.pn[s.grid.index(ix, iy)];
      sum += p;
      sx += p * s.grid.x_centre(ix);
      sy += p * s.grid.y_centre(iy);
    }
  return sum > 0.0 ? std::pair{sx / sum, sy / sum} : std::pair{0.0, 0.0};
}

}  // namespace

/// Combined contact modulus E* = G/(1 − ν) of the two bodies (physics.md §3.1).
double contact_modulus(const model::Bodies& b) {
  const double inv_g =
      0.5 * (1.0 / b.body1.shear_modulus_N_mm2 + 1.0 / b.body2.shear_modulus_N_mm2);
  const double nu_g = 0.5 * (b.body1.poisson_ratio / b.body1.shear_modulus_N_mm2 +
                             b.body2.poisson_ratio / b.body2.shear_modulus_N_mm2);
  const double g = 1.0 / inv_g, nu = nu_g * g;
  return g / (1.0 - nu);
}

WheelRailPatch describe_patch(const model::WheelRailProblem& p, const PlacedProfiles& prof,
                              const WheelsetPose& pose, const PatchSetup& s, Solution sol) {
  WheelRailPatch w;
  const Vec3 ref = s.frame.origin;
  const double d = s.frame.delta_rad;
  w.reference_tr = to_public(ref);
  w.contact_angle_rad = d;
  // Rail-profile coordinates: undo the rail's shift and roll.
  // A roller's reference lies below its principal profile when x ≠ 0; the profile point is the
  // one at the same lateral position.
  const double z_profile = prof.roller() ? prof.rail_at_track_y(ref.y).z : ref.z;
  const double ry = ref.y - prof.rail_y_mm(), rz = z_profile - prof.rail_z_mm();
  const double a = prof.rail_roll_rad();
  w.y_rail_mm = std::cos(a) * ry + std::sin(a) * rz;
  w.z_rail_mm = -std::sin(a) * ry + std::cos(a) * rz;
  w.s_rail_mm = prof.rail().at_y(ry).s;
  w.delta_rail_rad = d - a;
  const Vec3 q = pose.rotation.transposed_times(ref - pose.centre);
  w.reference_ws = to_public(q);
  // Wheel-profile coordinates: in the wheel's own frame (turned on a flexible wheelset).
  const Vec3 qw = pose.wheel_rotation.transposed_times(ref - pose.wheel_centre);
  w.reference_wheel = {qw.x, qw.y - prof.wheel_y_offset_mm(), qw.z - prof.wheel_r0_mm()};
  w.s_wheel_mm = prof.wheel().at_y(w.reference_wheel.y).s;
  w.delta_wheel_rad = d - p.motion.roll_rad - p.wheel_deviation.droll_rad;
  w.xi = s.kinematics.xi;
  w.eta = s.kinematics.eta;
  w.phi_per_mm = s.kinematics.phi_per_mm;
  w.chi_rad = s.kinematics.chi_rad;
  w.dq_mm = s.kinematics.dq_mm;
  w.veloc_mm_s = s.kinematics.veloc_mm_s;
  w.dx_mm = s.dx_mm;
  w.ds_mm = s.ds_mm;
  // A conformal patch's force in the planar frame is the bar force: each row's tractions turned
  // from its own frame into the reference's (wheelrail-advanced.md §1.8).
  if (s.curved) w.conformal = conformal_forces(s, sol);
  const ConformalPatch& c = w.conformal;
  const double fn = c.active ? c.bar_fn : sol.totals.fn;
  const double fx = c.active ? c.bar_fx : sol.totals.fx;
  const double fs = c.active ? c.bar_fs : sol.totals.fy;
  const double mz = c.active ? c.moment_planar.z : sol.totals.mz;
  const Vec3 f_tr{fx, fs * std::cos(d) - fn * std::sin(d), fn * std::cos(d) + fs * std::sin(d)};
  w.force_tr = to_public(f_tr);
  w.force_ws = to_public(pose.rotation.transposed_times(f_tr));
  // Moments (physics.md §13.6): (r_ref − r_marker) × F + R_ref·(0, 0, MN), MN about the normal.
  const Vec3 mn = mz * Vec3{0.0, -std::sin(d), std::cos(d)};
  const Vec3 rail_marker{0.0, prof.rail_y_mm(), prof.rail_z_mm()};
  const Vec3 wheel_marker = pose.centre + pose.rotation * wheelrail::wheel_marker_ws(p, prof);
  w.moment_tr = to_public(cross(ref - rail_marker, f_tr) + mn);
  w.moment_ws = to_public(pose.rotation.transposed_times(cross(ref - wheel_marker, f_tr) + mn));
  const auto [xc, yc] = pressure_centre(sol);
  w.pressure_centre_x_mm = ref.x + xc;
  w.pressure_centre_y_mm = ref.y + std::cos(d) * yc;
  w.solution = std::move(sol);
  return w;
}

PlanarForces pressure_part(const WheelRailPatch& w) {
  const Solution& sol = w.solution;
  if (!w.conformal.active) return {sol.totals.fn, 0.0};
  PlanarForces f;
  if (sol.pn.empty()) return f;
  for (int iy = 0; iy < sol.grid.my; ++iy) {
    const double d = w.conformal.row_alpha_rad[static_cast<std::size_t>(iy)] - w.contact_angle_rad;
    double row = 0.0;
    for (int ix = 0; ix < sol.grid.mx; ++ix) row += std::max(sol.pn[sol.grid.index(ix, iy)], 0.0);
    f.fn += row * std::cos(d);
    f.fs -= row * std::sin(d);
  }
  const double area = sol.grid.dx * sol.grid.dy;
  return {f.fn * area, f.fs * area};
}

/// The rail and wheel markers of the placement (physics.md §13.2).
void describe_markers(const model::WheelRailProblem& p, const PlacedProfiles& prof,
                      const WheelsetPose& pose, WheelRailSolution& out) {
  out.rail_marker_tr = {{0.0, prof.rail_y_mm(), prof.rail_z_mm()}, prof.rail_roll_rad(), 0.0};
  const Vec3 w = wheelrail::wheel_marker_ws(p, prof);
  const model::WheelDeviation& d = p.wheel_deviation;
  out.wheel_marker_ws = {to_public(w), d.droll_rad, d.dyaw_rad};
  out.wheel_marker_tr = {to_public(pose.centre + pose.rotation * w),
                         p.motion.roll_rad + d.droll_rad, p.motion.yaw_rad + d.dyaw_rad};
}

/// A left wheel is computed as a right one; its lateral components change sign.
void mirror_to_left(WheelRailSolution& s) {
  auto flip = [](Vector3& v) { v.y = -v.y; };
  // A moment is an axial vector: mirrored in y its x and z components change sign.
  auto flip_moment = [](Vector3& m) {
    m.x = -m.x;
    m.z = -m.z;
  };
  auto flip_marker = [&](ProfileMarker& m) {
    flip(m.position);
    m.roll_rad = -m.roll_rad;
    m.yaw_rad = -m.yaw_rad;
  };
  flip(s.force_tr);
  flip(s.force_ws);
  flip_moment(s.moment_tr);
  flip_moment(s.moment_ws);
  flip_marker(s.rail_marker_tr);
  flip_marker(s.wheel_marker_tr);
  flip_marker(s.wheel_marker_ws);
  for (WheelRailPatch& w : s.patches) {
    flip(w.reference_tr);
    flip(w.reference_wheel);
    flip(w.reference_ws);
    flip(w.force_tr);
    flip(w.force_ws);
    flip_moment(w.moment_tr);
    flip_moment(w.moment_ws);
    w.delta_rail_rad = -w.delta_rail_rad;
    w.delta_wheel_rad = -w.delta_wheel_rad;
    w.pressure_centre_y_mm = -w.pressure_centre_y_mm;
    w.contact_angle_rad = -w.contact_angle_rad;
    w.y_rail_mm = -w.y_rail_mm;
    w.eta = -w.eta;
    w.phi_per_mm = -w.phi_per_mm;
    Totals& t = w.solution.totals;
    t.fy = -t.fy;
    t.mz = -t.mz;
    if (w.conformal.active) {
      ConformalPatch& c = w.conformal;
      c.tilde_fs = -c.tilde_fs;
      c.bar_fs = -c.bar_fs;
      flip_moment(c.moment_planar);
      for (double& y : c.row_y_mm) y = -y;
      for (double& a : c.row_alpha_rad) a = -a;
    }
    t.creep_y = -t.creep_y;
    t.spin = -t.spin;
  }
}

/// The contact area of a patch's solution on the super grid (its elements with pressure).
wheelrail::SuperGridBox contact_box(const Solution& s, const PatchSetup& setup) {
  wheelrail::SuperGridBox b{1e300, -1e300, 1e300, -1e300};
  for (int iy = 0; iy < s.grid.my; ++iy)
    for (int ix = 0; ix < s.grid.mx; ++ix) {
      if (s.pn.empty() || !(s.pn[s.grid.index(ix, iy)] > 0.0)) continue;
      const double x = s.grid.x_centre(ix) + setup.origin_x_mm;
      const double y = s.grid.y_centre(iy) + setup.origin_y_mm;
      b = {std::min(b.x_lo, x), std::max(b.x_hi, x), std::min(b.y_lo, y), std::max(b.y_hi, y)};
    }
  return b;
}

/// The pitch moment on the rail about the wheelset's axle, in wheelset coordinates [N·mm]: the
/// moment about the wheel marker m plus m × F (F=2's MY_WS). The marker lies about the wheel's
/// radius below the axle, so M_y ≈ r·F_x(ws).
double axle_pitch_moment(const WheelRailSolution& s) {
  const Vector3& m = s.wheel_marker_ws.position;
  return s.moment_ws.y + m.z * s.force_ws.x - m.x * s.force_ws.z;
}

/// Linear theory's d(F_x/F_z)/dVPITCH [s/rad] (spec-additions §A6): Σ G·a·b·C11·r/|V| over the
/// patches (a, b the equivalent ellipse of each patch's contact, G and ν its combined constants),
/// r the distance of the contact point below the axle, over F_z.
double linear_pitch_slope(const WheelRailSolution& s, double v) {
  double slope = 0.0;
  for (const WheelRailPatch& w : s.patches) {
    const Solution& sol = w.solution;
    if (sol.pn.empty()) continue;
    const simplified::Ellipse e = simplified::equivalent_ellipse(sol.grid, sol.pn);
    if (!(e.a > 0.0 && e.b > 0.0)) continue;
    const double c11 = simplified::kalker_coefficients(e.a / e.b, sol.material.nu).c11;
    slope += sol.material.g * e.a * e.b * c11 * std::abs(w.reference_ws.z) / std::abs(v);
  }
  return slope / std::max(std::abs(s.force_tr.z), 1.0);
}

/// A left wheel's inputs are given in its mirrored frame (y towards its field side); the
/// geometry is computed for a right wheel, so the lateral inputs change sign here and the
/// lateral outputs in mirror_to_left().
model::WheelRailProblem as_right_side(model::WheelRailProblem p) {
  if (p.side != model::WheelSide::Left) return p;
  model::WheelsetState& m = p.motion;
  m.y_mm = -m.y_mm;
  m.roll_rad = -m.roll_rad;
  m.yaw_rad = -m.yaw_rad;
  m.vy_mm_s = -m.vy_mm_s;
  m.vroll_rad_s = -m.vroll_rad_s;
  m.vyaw_rad_s = -m.vyaw_rad_s;
  // The wheel's deviations are signed like the rail's (positive towards +y of the track).
  model::WheelDeviation& w = p.wheel_deviation;
  w.dy_mm = -w.dy_mm;
  w.droll_rad = -w.droll_rad;
  w.dyaw_rad = -w.dyaw_rad;
  w.vy_mm_s = -w.vy_mm_s;
  w.vroll_rad_s = -w.vroll_rad_s;
  w.vyaw_rad_s = -w.vyaw_rad_s;
  model::RailState& r = p.rail_state;
  r.dy_mm = -r.dy_mm;
  r.droll_rad = -r.droll_rad;
  r.vy_mm_s = -r.vy_mm_s;
  r.vroll_rad_s = -r.vroll_rad_s;
  p.track.rail_y0_mm = -p.track.rail_y0_mm;
  p.track.curvature_per_mm = -p.track.curvature_per_mm;
  return p;
}

}  // namespace rollcontact::wheelrail
