#pragma once
// The wheelset's pose in the track (spec/physics.md §13.2) and the wheel surface it carries: a
// body of revolution of the wheel profile about the axle.

#include "rollcontact/model/wheelrail.hpp"
#include "wheelrail/frames.hpp"
#include "wheelrail/placed_profiles.hpp"

namespace rollcontact::wheelrail {

struct WheelsetPose {
  Mat3 rotation;  ///< wheelset → track, R_x(roll)·R_z(yaw)
  Vec3 centre;    ///< axle centre in track coordinates: (0, Y_WS, Z_WS − NOMRADW)
  /// The wheel's surface frame: the wheel is the body of revolution of its profile about this
  /// frame's y-axis, profile y = frame y − wheel_y_offset. The wheelset's frame for a rigid
  /// wheelset; moved and turned by the wheel's deviation on a flexible one (E = 4, 5).
  Mat3 wheel_rotation;
  Vec3 wheel_centre;
};

/// The pose for the problem's motion with the wheelset's vertical position `z_ws_mm`; the
/// profiles place the wheel on the wheelset (its marker, about which a deviation turns it).
WheelsetPose pose_of(const model::WheelRailProblem& problem, const PlacedProfiles& profiles,
                     double z_ws_mm);
/// The wheel's marker (profile origin) in wheelset coordinates: (0, y_offset, r0) shifted by
/// the wheel's deviation (DXWHL, DYWHL, DZWHL).
Vec3 wheel_marker_ws(const model::WheelRailProblem& problem, const PlacedProfiles& profiles);

/// Distance t along the unit direction `dir` from `from` (track coordinates) at which the line
/// meets the wheel surface, starting the search at `t0`. nullopt-like: returns false when the
/// line leaves the wheel profile's lateral range or does not converge. `hint` (optional) carries
/// the profile segment from one call to the next along a grid row.
bool wheel_surface_along(const PlacedProfiles& profiles, const WheelsetPose& pose, Vec3 from,
                         Vec3 dir, double t0, double& t, CurveHint* hint = nullptr);

/// Same for the rail surface: the prismatic rail in the track's y-z plane, or the roller.
bool rail_surface_along(const PlacedProfiles& profiles, Vec3 from, Vec3 dir, double t0, double& t);

}  // namespace rollcontact::wheelrail
