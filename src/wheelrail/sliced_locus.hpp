#pragma once
// The contact locus of a sliced wheel (spec/physics.md §13.9, "iterative contact locus"): at a
// lateral position of the wheel profile the locus point is the point of the wheel's
// circumference that reaches deepest into the track. A round wheel has it in closed form
// (§13.3 step 1); with a flat or an out-of-round wheel the radius varies around the
// circumference and the deepest point moves — to the edges of a flat, for instance — so it is
// searched for along the circumference.

#include <cstddef>
#include <map>

#include "wheelrail/frames.hpp"
#include "wheelrail/placed_profiles.hpp"
#include "wheelrail/sliced_surface.hpp"
#include "wheelrail/wheelset_pose.hpp"

namespace rollcontact::wheelrail {

struct LocusPoint {
  Vec3 point;  ///< track coordinates [mm]
  bool found = false;
};

/// The cross-sections of the angles a locus search scans, kept for the next lateral position
/// (one contact search; no state beyond it): without yaw every position scans the same angles,
/// and a section blended once makes its points cheap. At most `capacity` angles are kept; a
/// yawed wheelset, whose angles differ by position, evaluates the others directly.
class LocusScanSections {
 public:
  explicit LocusScanSections(std::size_t capacity) : capacity_(capacity) {}
  /// The section at material angle u, or nullptr when it is not kept (and the cache is full).
  const SurfaceSection* at(const SlicedSurface& surface, double u);

 private:
  std::size_t capacity_;
  std::map<double, SurfaceSection> sections_;
};

/// The deepest point (largest track z) of the wheel at profile position `y_profile_mm` within
/// ±0.08 rad (≈ ±40 mm on a 490 mm wheel: beyond a flat's half-length) of the angle
/// `phi_start_rad` from the bottom (the round wheel's locus), to 1e-7 rad. `scan`: sections of
/// the scanned angles shared between calls (nullptr: none).
LocusPoint sliced_locus_point(const PlacedProfiles& profiles, const WheelsetPose& pose,
                              double y_profile_mm, double phi_start_rad,
                              LocusScanSections* scan = nullptr);

/// The number of angles one locus search scans (the capacity that serves an unyawed wheelset).
std::size_t locus_scan_angles();

}  // namespace rollcontact::wheelrail
