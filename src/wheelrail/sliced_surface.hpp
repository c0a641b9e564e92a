#pragma once
// SlicedSurface: a running surface whose profile varies along a coordinate u (spec/physics.md
// §13.9, spec-additions.md §A9): a wheel's around its circumference (a `.slcw` slices file:
// wheel flats, out-of-round wheels; u = θ [rad], periodic) or a rail's along the track (a
// `.slcs` file: switches and crossings; u = the track position [mm]). Each slice is processed
// like a plain profile of its body (zig-zags, kinks, smoothing spline: ProfileCurve; a rail's
// slices rolled by the rail's roll first), resampled at a common number of points uniformly in
// its own arc length, and the surface is a tensor cubic spline in (u, s):
//   * along the profile (s): the interpolating cubic spline through the resampled points, so a
//     surface made of identical slices is the plain profile to O(h⁴) (h = 0.25 mm);
//   * along u, per resampled point: U_INTPOL = 1 the natural cubic spline through the slices at
//     their u; U_INTPOL = 2 the approximating cubic B-spline with knots at the slices (clamped,
//     "not a knot" at the second and last-but-one) and the slices themselves as coefficients:
//     it passes through the first and last slice only, averages each interior slice with its
//     neighbours (1:4:1 where they are equally spaced) and so smooths measured slices
//     (docs/decisions.md, "Variable wheel profiles": reproduces CONTACT's approach to six digits
//     on `wheelflat`).
// A wheel's θ is wrapped into [−π, π); u is held constant outside the range the slices cover.
// z is the profile's z (down) at lateral profile position y: for a wheel the radius there is
// the placed profile's r0 + z, as for a plain profile.

#include <array>
#include <cstddef>
#include <vector>

#include "rollcontact/model/profile.hpp"
#include "rollcontact/model/wheelrail.hpp"

namespace rollcontact::wheelrail {

/// A point of the surface: height z [mm, down], its slopes ∂z/∂y [-] at constant u and ∂z/∂u
/// (a wheel's [mm/rad], a rail's [-]) at constant y. found = false: y lies outside the surface.
struct SurfacePoint {
  double z = 0.0, dz_dy = 0.0, dz_du = 0.0;
  bool found = false;
};

enum class SurfaceBody { Rail, Wheel };

/// The surface's control values at one u, blended once (SlicedSurface::section): many lateral
/// positions at the same u then cost no blending (the contact locus scans the same angles for
/// every lateral position of a wheelset without yaw).
struct SurfaceSection {
  double u = 0.0;
  std::vector<double> y, z, dy_du, dz_du;  ///< control values and their u-derivatives
};

class SlicedSurface {
 public:
  /// Throws GeometryError naming the slices file when a slice cannot be made a curve or its
  /// lateral coordinate is not monotone, NotSupportedError for features (NFEAT > 1). A rail's
  /// slices are rolled by `roll_rad` about the x-axis first (the cant and DROLLR).
  SlicedSurface(const SlicedProfile& slices, const model::ProfileSmoothing& smoothing,
                SurfaceBody body = SurfaceBody::Wheel, double roll_rad = 0.0);

  SurfacePoint at(double u, double y_mm) const;
  /// The same at the section's u (bit for bit).
  SurfacePoint at(const SurfaceSection& section, double y_mm) const;
  SurfaceSection section(double u) const;
  /// The cross-section at u as profile points in the body's canonical order (a wheel's
  /// descending y, a rail's ascending), one per resampled point: the plain profile the contact
  /// search samples there.
  Profile cross_section(double u) const;
  double y_min() const noexcept { return y_min_; }
  double y_max() const noexcept { return y_max_; }

 private:
  /// The weights of four rows of the control table for one θ, and their θ-derivatives.
  struct ThetaBlend {
    std::array<std::size_t, 4> row{};
    std::array<double, 4> w{}, dw{};
  };
  ThetaBlend blend_at(double theta_rad) const;
  ThetaBlend approximating_blend(double theta_rad) const;
  ThetaBlend interpolating_blend(double theta_rad) const;
  /// Control value k (y or z) of the cross-section at the blend (θ-derivative in d).
  double blended(const std::vector<double>& table, const ThetaBlend& b, std::size_t k,
                 double* d = nullptr) const;
  /// The point at lateral position y from control values control(k, z?, d) of one u.
  template <class Control>
  SurfacePoint evaluate(double y, const Control& control) const;

  /// The slices' coordinate as the tables use it: a wheel's angle wrapped into [−π, π).
  double along(double u) const;

  SurfaceBody body_ = SurfaceBody::Wheel;
  int intpol_ = 2;
  std::vector<double> theta_;  ///< slice positions [rad], increasing
  std::vector<double> knots_;  ///< approximating: the B-splines' knots in θ [rad]
  std::size_t points_ = 0;     ///< resampled points per slice
  std::size_t ctrl_ = 0;       ///< control values per row (points_ + 2)
  /// Rows of ctrl_ s-control values of y and z: one per slice, then (interpolating) their
  /// second θ-derivatives.
  std::vector<double> ty_, tz_;
  std::vector<double> y_nodes_;  ///< y of the mean cross-section at the resampled points
  double y_min_ = 0.0, y_max_ = 0.0;
};

}  // namespace rollcontact::wheelrail
