#pragma once
// Profile: the raw points of a rail or wheel profile after reading and the cheap clean-up steps
// of spec/inp-format.md §8.3 (shifts, bounds, mirroring, scaling, ordering, chord-length check).
// Smoothing splines, kink detection and contact search work on these points later. Plain data.

#include <string>
#include <vector>

namespace rollcontact {

/// File format of a profile, from the file name extension (spec/inp-format.md §5.1).
enum class ProfileFormat {
  Simpack,   ///< `.prr` (rail) / `.prw` (wheel): SIMPACK keyword file (§8.1)
  Miniprof,  ///< `.ban` / `.whl`: Miniprof `Key=Value` header plus columns (§8.2)
  Plain,     ///< any other extension: table of y z columns (§8.2)
  Slices,    ///< `.slcs` (rail along the track) / `.slcw` (wheel around its axle) (§8.4)
};

/// One cross-section profile in canonical form: mm, z positive downwards, y positive towards
/// the field side of a right-side rail/wheel; rail points ordered by ascending y, wheel points
/// by descending y.
struct Profile {
  std::string file;  ///< the file the points came from (as resolved, for messages)
  ProfileFormat format = ProfileFormat::Plain;
  std::vector<double> y;  ///< lateral coordinates [mm]
  std::vector<double> z;  ///< vertical coordinates [mm], positive downwards
  /// Optional Miniprof `K` column (shear yield strength, file units as read); empty if absent.
  std::vector<double> k_yield;
};

/// A variable profile: a series of slices along the track (rail, u = s [mm]) or around the
/// wheel (u = θ [rad]), spec/inp-format.md §8.4.
struct SlicedProfile {
  std::string file;                      ///< the slices file (resolved)
  double u_offset = 0.0, u_scale = 1.0;  ///< u_fc = U_SCALE * (U_OFFSET + U_SLC)
  int nfeat = 0, nkink = 0, naccel = 0;  ///< feature, kink and acceleration point counts
  int u_intpol = 1;                      ///< 1 interpolating spline, 2 approximating spline
  std::vector<double> u;                 ///< slice positions after scaling [mm] or [rad]
  std::vector<Profile> slices;           ///< one profile per slice, same order as u
  std::vector<int> kinks, accels;        ///< NKINK / NACCEL feature numbers as read
  /// NFEAT > 1: feature positions per slice (nfeat values each, negative: absent) [mm].
  std::vector<std::vector<double>> features;
};

}  // namespace rollcontact
