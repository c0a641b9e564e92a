#pragma once
// The curved reference surface of a conformal patch (CONTACT's D=4; spec/wheelrail-advanced.md
// §1.3, spec-additions.md §A7): a curve in the lateral plane x = x_ref midway between the rail
// and the wheel profiles, sampled at multiples of DS in the rail's arc length around the
// reference point, trimmed to the interpenetration region (without the samples where rail and
// wheel turn away from each other) plus two guard samples. Each sample becomes one row of the
// patch grid, with its own normal: the gap is measured along it, the rigid slip and tractions
// are resolved in it.

#include <cstddef>
#include <vector>

#include "wheelrail/contact_search.hpp"
#include "wheelrail/frames.hpp"
#include "wheelrail/placed_profiles.hpp"
#include "wheelrail/wheelset_pose.hpp"

namespace rollcontact::wheelrail {

struct CurvedReference {
  double ds_mm = 0.0;
  /// Row i lies at curvilinear position s̃_i = (k_first + i)·ds from the reference point (the
  /// rail's arc length minus the reference's).
  int k_first = 0;
  std::vector<Vec3> point;    ///< midpoint of the rail and wheel samples (track; x = x_ref)
  std::vector<Vec3> normal;   ///< averaged normal (n_rail − n_wheel)/2, not renormalised (up)
  std::vector<double> alpha;  ///< inclination atan2(n̄_y, −n̄_z) [rad], as the contact angle

  std::size_t rows() const noexcept { return point.size(); }
  double s_tilde(std::size_t i) const noexcept {
    return ds_mm * static_cast<double>(k_first + static_cast<int>(i));
  }
  /// The row's tangent along the curve and its normal into the rail (the frame of its
  /// tractions: e_x, e_s, e_n right-handed, as the planar ContactFrame).
  Vec3 tangent(std::size_t i) const { return {0.0, std::cos(alpha[i]), std::sin(alpha[i])}; }
  Vec3 inward_normal(std::size_t i) const { return {0.0, -std::sin(alpha[i]), std::cos(alpha[i])}; }
};

/// The curved reference of `region` with row spacing `ds_mm` for a steady or static problem
/// (the curvilinear origin at the reference point). Throws GeometryError when no sample
/// survives the trimming.
CurvedReference curved_reference(const PlacedProfiles& profiles, const WheelsetPose& pose,
                                 const ContactRegion& region, double ds_mm);

}  // namespace rollcontact::wheelrail
