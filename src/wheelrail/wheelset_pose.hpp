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
};

/// The pose for the problem's motion with the wheelset's vertical position `z_ws_mm`.
WheelsetPose pose_of(const model::WheelRailProblem& problem, double z_ws_mm);

/// Distance t along the unit direction `dir` from `from` (track coordinates) at which the line
/// meets the wheel surface, starting the search at `t0`. nullopt-like: returns false when the
/// line leaves the wheel profile's lateral range or does not converge. `hint` (optional) carries
/// the profile segment from one call to the next along a grid row.
bool wheel_surface_along(const PlacedProfiles& profiles, const WheelsetPose& pose, Vec3 from,
                         Vec3 dir, double t0, double& t, CurveHint* hint = nullptr);

/// Same for the rail surface: the prismatic rail in the track's y-z plane, or the roller.
bool rail_surface_along(const PlacedProfiles& profiles, Vec3 from, Vec3 dir, double t0, double& t);

}  // namespace rollcontact::wheelrail
