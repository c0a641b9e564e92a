#pragma once
// Wheel/rail problems with analytic answers for the geometry tests: profiles made of straight
// lines and circular arcs, placed absolutely (no gauge point), the wheel profile origin at
// y = 750 mm on the wheelset.

#include <cmath>
#include <functional>

#include "rollcontact/model/wheelrail.hpp"

namespace rollcontact::test_support {

/// Profile points z(y) on [y0, y1] with spacing dy (rail: ascending y; wheel: descending y).
inline Profile sampled_profile(const std::function<double(double)>& z, double y0, double y1,
                               double dy, bool wheel) {
  Profile p;
  p.file = wheel ? "wheel (test)" : "rail (test)";
  const int n = static_cast<int>(std::round((y1 - y0) / dy));
  for (int i = 0; i <= n; ++i) {
    const double y = wheel ? y1 - i * dy : y0 + i * dy;
    p.y.push_back(y);
    p.z.push_back(z(y));
  }
  return p;
}

/// A rail whose head is a circle of radius `rail_radius_mm` (top at profile y = 0, z = 0) under
/// a cylindrical or conical wheel (z_w = −conicity·y) of nominal radius 460 mm; frictionless
/// normal contact, position prescribed.
inline model::WheelRailProblem crowned_rail_problem(double rail_radius_mm, double conicity = 0.0) {
  model::WheelRailProblem p;
  p.side = model::WheelSide::Right;
  const double r = rail_radius_mm;
  p.rail.points = sampled_profile([r](double y) { return r - std::sqrt(r * r - y * y); }, -30.0,
                                  30.0, 0.25, false);
  p.wheel.points =
      sampled_profile([conicity](double y) { return -conicity * y; }, -60.0, 70.0, 0.5, true);
  p.track.gauge_height_mm = 0.0;  // absolute placement
  p.track.rail_y0_mm = 750.0;
  p.track.rail_z0_mm = 0.0;
  p.wheelset.flange_back_distance_mm = 1500.0;
  p.wheelset.flange_back_position_mm = 0.0;  // wheel profile origin at y = 750
  p.wheelset.nominal_radius_mm = 460.0;
  p.patch.bodies.body1 = p.patch.bodies.body2 = {0.28, 82000.0};
  p.patch.friction = {0.3, 0.3};
  p.patch.tangential.kind = model::TangentialKind::None;
  p.patch.solver.tolerance = 1e-6;
  p.search.dx_mm = p.search.ds_mm = 0.2;
  p.vertical = model::VerticalLoading::Position;
  p.motion.vs_mm_s = 2000.0;
  p.motion.vpitch_rad_s = -2000.0 / 460.0;
  return p;
}

/// crowned_rail_problem(300 mm, conicity 0.05) in steady rolling with FZ = 10 kN prescribed.
inline model::WheelRailProblem rolling_conical_wheel() {
  model::WheelRailProblem p = crowned_rail_problem(300.0, 0.05);
  p.patch.tangential.kind = model::TangentialKind::SteadyRolling;
  p.vertical = model::VerticalLoading::Force;
  p.motion.fz_N = 10000.0;
  return p;
}

/// rolling_conical_wheel() off centre (y = 1.5 mm) and yawed (4 mrad): the right wheel of the
/// left/right mirror tests.
inline model::WheelRailProblem yawed_conical_wheel() {
  model::WheelRailProblem p = rolling_conical_wheel();
  p.motion.y_mm = 1.5;
  p.motion.yaw_rad = 0.004;
  return p;
}

/// The same problem on a left wheel: its inputs are track coordinates in the left wheel's
/// mirrored frame, so every lateral input changes sign — the wheelset's lateral position, yaw
/// and lateral velocity, the rail's absolute lateral placement, the wheel's lateral deviations
/// and their rates, and the massless rail's lateral load. The left wheel's results are then the
/// right's with their lateral components mirrored.
inline model::WheelRailProblem mirrored_left(model::WheelRailProblem p) {
  p.side = model::WheelSide::Left;
  p.motion.y_mm = -p.motion.y_mm;
  p.motion.yaw_rad = -p.motion.yaw_rad;
  p.motion.vy_mm_s = -p.motion.vy_mm_s;
  p.track.rail_y0_mm = -p.track.rail_y0_mm;
  model::WheelDeviation& d = p.wheel_deviation;
  d.dy_mm = -d.dy_mm;
  d.droll_rad = -d.droll_rad;
  d.dyaw_rad = -d.dyaw_rad;
  d.vy_mm_s = -d.vy_mm_s;
  d.vroll_rad_s = -d.vroll_rad_s;
  d.vyaw_rad_s = -d.vyaw_rad_s;
  p.massless_rail.fy_N = -p.massless_rail.fy_N;
  return p;
}

}  // namespace rollcontact::test_support
