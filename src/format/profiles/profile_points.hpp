#pragma once
// Points of a profile as read from a file, before the clean-up steps of spec/inp-format.md §8.3,
// and those steps: removal of points closer than the minimum spacing, shifts and bounding box,
// mirroring in y and z (explicit or auto-detected), scaling to mm and ordering.
// Zig-zag removal, kinks and smoothing (steps 2 and 9) belong to the profile-smoothing code.

#include <string>
#include <vector>

#include "rollcontact/model/profile.hpp"

namespace rollcontact::format {

/// Points and file-level settings of one profile file, in file units.
struct RawProfile {
  std::string file;
  ProfileFormat format = ProfileFormat::Plain;
  std::vector<double> y, z, k_yield;
  double min_spacing = 1e-4;            ///< delete points closer than this to their predecessor
  double shift_y = 0.0, shift_z = 0.0;  ///< added to the data (SIMPACK shift, Miniprof offsets)
  double bound_y_min = 1.0, bound_y_max = 0.0;  ///< min < max: delete points outside
  double bound_z_min = 1.0, bound_z_max = 0.0;  ///< min < max: clamp z into the interval
  int mirror_y_flag = 0, mirror_z_flag = 0;     ///< SIMPACK mirror.y / mirror.z (0 or 1)
  int inversion = -1;                           ///< SIMPACK: 1 reverse the point order, -1 absent
  double length_to_mm = 1.0;                    ///< SIMPACK: 1000 / units.len.f
};

/// Options of the .inp profile line that act on the points (spec/inp-format.md §5.1).
struct ProfileOptions {
  bool is_wheel = false;  ///< wheel profiles are ordered by descending y
  int mirror_y = 0;       ///< 1: mirror y (combined with the SIMPACK flag: mirror when sum is 1)
  int mirror_z = 0;       ///< 0 auto-detect (Miniprof/plain), -1 as is, 1 mirror z
  double scale_yz = 1.0;  ///< file units -> mm
};

/// Applies §8.3 steps 1, 3-7 and returns the profile in canonical form (mm, z downwards, rail
/// ascending y, wheel descending y). `warnings` receives one line per notable adjustment.
Profile finish_profile(RawProfile raw, const ProfileOptions& options,
                       std::vector<std::string>& warnings);

/// Length of the polyline through the points [mm] (CONTACT requires 5..500 mm).
double profile_chord_length(const Profile& profile);
/// The admissible profile lengths [mm] (release 25.1): outside, SCALEYZ or the units are wrong.
inline constexpr double kMinProfileLength_mm = 5.0, kMaxProfileLength_mm = 500.0;

/// True for a chord length [mm] within the admissible range (false for NaN).
inline bool is_admissible_profile_length(double chord_mm) {
  return chord_mm >= kMinProfileLength_mm && chord_mm <= kMaxProfileLength_mm;
}

}  // namespace rollcontact::format
