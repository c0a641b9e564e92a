#include "wheelrail/wheelset_pose.hpp"

#include <cmath>

namespace rollcontact::wheelrail {

namespace {

/// The line q(t) = q0 + t·dq (wheelset frame) meets a sliced wheel: f(t) = ρ − (r0 + z(θ, y_p))
/// with ρ the distance from the axle and θ the material angle of the point, so the radius varies
/// along the line as the wheel's does around its circumference (physics.md §13.9).
bool sliced_wheel_along(const PlacedProfiles& profiles, Vec3 q0, Vec3 dq, double t0, double& t) {
  const SlicedSurface& surface = *profiles.wheel_surface();
  const double y_off = profiles.wheel_y_offset_mm(), r0 = profiles.wheel_r0_mm();
  t = t0;
  for (int it = 0; it < 30; ++it) {
    const Vec3 q = q0 + t * dq;
    const double rho2 = q.x * q.x + q.z * q.z, rho = std::sqrt(rho2);
    const double phi = std::atan2(q.x, q.z);
    const SurfacePoint w = surface.at(profiles.wheel_theta_rad() + phi, q.y - y_off);
    if (!w.found) return false;
    const double f = rho - (r0 + w.z);
    const double dphi = (q.z * dq.x - q.x * dq.z) / rho2;
    const double df = (q.x * dq.x + q.z * dq.z) / rho - w.dz_dy * dq.y - w.dz_du * dphi;
    if (df == 0.0 || !std::isfinite(df)) return false;
    const double step = f / df;
    t -= step;
    if (std::abs(step) < 1e-11) return true;
  }
  return false;
}

}  // namespace

Vec3 wheel_marker_ws(const model::WheelRailProblem& p, const PlacedProfiles& profiles) {
  const model::WheelDeviation& d = p.wheel_deviation;
  return {d.dx_mm, profiles.wheel_y_offset_mm() + d.dy_mm, profiles.wheel_r0_mm() + d.dz_mm};
}

WheelsetPose pose_of(const model::WheelRailProblem& p, const PlacedProfiles& profiles,
                     double z_ws_mm) {
  WheelsetPose pose;
  pose.rotation = roll_yaw_rotation(p.motion.roll_rad, p.motion.yaw_rad);
  pose.centre = {0.0, p.motion.y_mm, z_ws_mm - p.wheelset.nominal_radius_mm};
  pose.wheel_rotation = pose.rotation;
  pose.wheel_centre = pose.centre;
  const model::WheelDeviation& d = p.wheel_deviation;
  if (d.dx_mm != 0.0 || d.dy_mm != 0.0 || d.dz_mm != 0.0 || d.droll_rad != 0.0 ||
      d.dyaw_rad != 0.0) {
    // The wheel turned by R_w about its marker m and moved with it: a point q of the rigid
    // wheel's frame lies at m + R_w·(q − m0) with m0 the undeviated marker, i.e. in a frame of
    // rotation R·R_w centred at centre + R·(m − R_w·m0).
    const Mat3 rw = roll_yaw_rotation(d.droll_rad, d.dyaw_rad);
    const Vec3 m0{0.0, profiles.wheel_y_offset_mm(), profiles.wheel_r0_mm()};
    const Vec3 m = wheel_marker_ws(p, profiles);
    pose.wheel_rotation = product(pose.rotation, rw);
    pose.wheel_centre = pose.centre + pose.rotation * (m - rw * m0);
  }
  return pose;
}

bool wheel_surface_along(const PlacedProfiles& profiles, const WheelsetPose& pose, Vec3 from,
                         Vec3 dir, double t0, double& t, CurveHint* hint) {
  // f(t) = ρ(t) − r(y_p(t)): distance from the axle minus the wheel radius at that section.
  const Vec3 q0 = pose.wheel_rotation.transposed_times(from - pose.wheel_centre);
  const Vec3 dq = pose.wheel_rotation.transposed_times(dir);
  if (profiles.wheel_surface() != nullptr) return sliced_wheel_along(profiles, q0, dq, t0, t);
  const double y_off = profiles.wheel_y_offset_mm(), r0 = profiles.wheel_r0_mm();
  CurveHint local;
  CurveHint& h = hint != nullptr ? *hint : local;
  // Fast way: one Newton iteration in (profile parameter, t) from the previous element's point.
  // Profile y = q.y − y_off, profile z = ρ − r0 along the line q(t) = q0 + t·dq.
  t = t0;
  // ρ by a plain square root: std::hypot's overflow guard cost 5 % of a force sweep, and the
  // distances from the axle are hundreds of millimetres.
  const auto line = [&](double tt, double& a, double& da, double& b, double& db) {
    const Vec3 q = q0 + tt * dq;
    const double rho = std::sqrt(q.x * q.x + q.z * q.z);
    a = q.y - y_off;
    da = dq.y;
    b = rho - r0;
    db = (q.x * dq.x + q.z * dq.z) / rho;
  };
  if (profiles.wheel().meet_line(line, t, h)) return true;
  t = t0;
  for (int it = 0; it < 30; ++it) {
    const Vec3 q = q0 + t * dq;
    const CurvePoint w = profiles.wheel().at_y(q.y - y_off, h);
    if (!w.found) return false;
    const double rho = std::sqrt(q.x * q.x + q.z * q.z);
    const double f = rho - (r0 + w.z);
    const double df = (q.x * dq.x + q.z * dq.z) / rho - w.dz_dy * dq.y;
    if (df == 0.0 || !std::isfinite(df)) return false;
    const double step = f / df;
    t -= step;
    if (std::abs(step) < 1e-11) return true;
  }
  return false;
}

bool rail_surface_along(const PlacedProfiles& profiles, Vec3 from, Vec3 dir, double t0, double& t) {
  t = t0;
  if (profiles.rail_varies_along_x()) {
    // f(t) = z_surface(x(t), y(t)) − z(t) on the 3-D surface (roller, sliced rail).
    for (int it = 0; it < 30; ++it) {
      const Vec3 q = from + t * dir;
      const RailSurfacePoint r = profiles.rail_surface_at(q.x, q.y);
      if (!r.found) return false;
      const double f = r.z - q.z;
      const double df = r.dz_dx * dir.x + r.dz_dy * dir.y - dir.z;
      if (df == 0.0 || !std::isfinite(df)) return false;
      const double step = f / df;
      t -= step;
      if (std::abs(step) < 1e-11) return true;
    }
    return false;
  }
  for (int it = 0; it < 30; ++it) {
    const CurvePoint r = profiles.rail_at_track_y(from.y + t * dir.y);
    if (!r.found) return false;
    const double f = r.z - (from.z + t * dir.z);
    const double df = r.dz_dy * dir.y - dir.z;
    if (df == 0.0 || !std::isfinite(df)) return false;
    const double step = f / df;
    t -= step;
    if (std::abs(step) < 1e-11) return true;
  }
  return false;
}

}  // namespace rollcontact::wheelrail
