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
  /// Row i lies at (k_first + i)·ds along the rail's arc length, counted from the reference
  /// point (steady and static problems) or from the rail profile's origin (a super grid,
  /// s_origin_mm = the reference's arc length).
  int k_first = 0;
  double s_origin_mm = 0.0;
  std::vector<Vec3> point;    ///< midpoint of the rail and wheel samples (track; x = x_ref)
  std::vector<Vec3> normal;   ///< averaged normal (n_rail − n_wheel)/2, not renormalised (up)
  std::vector<double> alpha;  ///< inclination atan2(n̄_y, −n̄_z) [rad], as the contact angle

  std::size_t rows() const noexcept { return point.size(); }
  /// Curvilinear position s̃ of row i from the reference point [mm].
  double s_tilde(std::size_t i) const noexcept {
    return ds_mm * static_cast<double>(k_first + static_cast<int>(i)) - s_origin_mm;
  }
  /// The row's tangent along the curve and its normal into the rail (the frame of its
  /// tractions: e_x, e_s, e_n right-handed, as the planar ContactFrame).
  Vec3 tangent(std::size_t i) const { return {0.0, std::cos(alpha[i]), std::sin(alpha[i])}; }
  Vec3 inward_normal(std::size_t i) const { return {0.0, -std::sin(alpha[i]), std::cos(alpha[i])}; }
};

/// Where the rows of a curved reference lie.
struct CurvedRows {
  double ds_mm = 0.0;
  /// Rows at multiples of DS of the rail's own arc length (the super grid of shifts and
  /// transient rolling, wheelrail-advanced.md §1.9) instead of from the reference point.
  bool on_super_grid = false;
  /// Curvilinear range [mm, from the reference point] the rows must cover besides the region
  /// (a continued patch's previous contact); empty when lo > hi.
  double cover_lo_mm = 1.0, cover_hi_mm = -1.0;
};

/// The curved reference of `region`. Throws GeometryError when no sample survives the trimming.
CurvedReference curved_reference(const PlacedProfiles& profiles, const WheelsetPose& pose,
                                 const ContactRegion& region, const CurvedRows& rows);

}  // namespace rollcontact::wheelrail
