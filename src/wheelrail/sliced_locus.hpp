#pragma once
// The contact locus of a sliced wheel (spec/physics.md §13.9, "iterative contact locus"): at a
// lateral position of the wheel profile the locus point is the point of the wheel's
// circumference that reaches deepest into the track. A round wheel has it in closed form
// (§13.3 step 1); with a flat or an out-of-round wheel the radius varies around the
// circumference and the deepest point moves — to the edges of a flat, for instance — so it is
// searched for along the circumference.

#include "wheelrail/frames.hpp"
#include "wheelrail/placed_profiles.hpp"
#include "wheelrail/wheelset_pose.hpp"

namespace rollcontact::wheelrail {

struct LocusPoint {
  Vec3 point;  ///< track coordinates [mm]
  bool found = false;
};

/// The deepest point (largest track z) of the wheel at profile position `y_profile_mm` within
/// ±0.08 rad (≈ ±40 mm on a 490 mm wheel: beyond a flat's half-length) of the angle
/// `phi_start_rad` from the bottom (the round wheel's locus), to 1e-7 rad.
LocusPoint sliced_locus_point(const PlacedProfiles& profiles, const WheelsetPose& pose,
                              double y_profile_mm, double phi_start_rad);

}  // namespace rollcontact::wheelrail
