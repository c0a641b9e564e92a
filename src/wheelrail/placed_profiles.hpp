#pragma once
// The rail and wheel profiles as curves, placed (spec/physics.md §13.2): the rail rotated by its
// roll (−CANT + DROLLR) and shifted to its gauge-point or absolute position in the track, the
// wheel profile's origin on the wheelset (FBDIST, FBPOS, NOMRADW, YTAPE). Building the curves is
// the expensive part; it is done once per profile pair and rail roll and reused while they stay
// the same (same_curves()).

#include <memory>
#include <optional>

#include "rollcontact/model/wheelrail.hpp"
#include "wheelrail/profile_curve.hpp"
#include "wheelrail/sliced_surface.hpp"

namespace rollcontact::wheelrail {

/// The rail (or roller) surface above a point of the track plane: height z [mm, down] and its
/// slopes (found = false outside the profile).
struct RailSurfacePoint {
  bool found = false;
  double z = 0.0, dz_dx = 0.0, dz_dy = 0.0;
};

class PlacedProfiles {
 public:
  explicit PlacedProfiles(const model::WheelRailProblem& problem);

  /// True when `problem` has the same profiles, smoothing, rail roll and tape circle, so that
  /// the curves can be reused (the shifts are recomputed by place()).
  bool same_curves(const model::WheelRailProblem& problem) const;
  /// Sets the rail's and wheel's offsets for `problem` (cheap).
  void place(const model::WheelRailProblem& problem);

  /// The rail profile rotated by its roll, origin not shifted; track y = rail_y + curve y. For a
  /// sliced rail its cross-section at the wheelset (u = S_WS, remade by place()).
  const ProfileCurve& rail() const noexcept { return rail_; }
  /// The wheel profile; for a sliced wheel its cross-section at the contact (material angle
  /// wheel_theta_rad(), remade by place() when the pitch changes).
  const ProfileCurve& wheel() const noexcept { return wheel_; }
  /// The wheel surface of a sliced wheel (physics.md §13.9); nullptr for a plain profile.
  const SlicedSurface* wheel_surface() const noexcept { return wheel_surface_.get(); }
  /// Material angle θ of the wheel point straight below the axle: −PITCH_WS − DPITCHW [rad]. A
  /// point at angle φ = atan2(x, z) from the axle (wheelset frame) is the material angle θ + φ.
  double wheel_theta_rad() const noexcept { return wheel_theta_; }
  double rail_y_mm() const noexcept { return rail_y_; }
  double rail_z_mm() const noexcept { return rail_z_; }
  double rail_roll_rad() const noexcept { return rail_roll_; }
  /// Rail height z [mm, down] and slope dz/dy at track position y (found = false outside): the
  /// rail's cross-section, on a roller rig its principal profile (the section at x = 0).
  CurvePoint rail_at_track_y(double y) const;
  /// The rail surface at (x, y): the prismatic rail's cross-section, or the roller's body of
  /// revolution, which falls away from x = 0 (rises towards the wheel on an internal roller).
  RailSurfacePoint rail_surface_at(double x, double y) const;
  bool roller() const noexcept { return roller_; }
  /// The rail's surface changes along x: a roller, or a rail whose profile varies along the
  /// track (slices). Contact search and undeformed distance then evaluate it in 3-D.
  bool rail_varies_along_x() const noexcept { return roller_ || rail_surface_ != nullptr; }
  /// A sliced rail's surface (physics.md §13.9); nullptr for a plain rail profile.
  const SlicedSurface* rail_surface() const noexcept { return rail_surface_.get(); }
  /// Track position u of the sliced rail's cross-section at x = 0 (S_WS) [mm]; 0 otherwise.
  double rail_u_mm() const noexcept { return rail_u_; }
  /// Roller rig: height of the roller axle [mm, down] (the profile origin's + NOMRADR).
  double roller_axle_z_mm() const noexcept { return roller_axle_z_; }
  /// Wheel-profile y of the wheelset-frame lateral coordinate: y_p = y_ws − offset.
  double wheel_y_offset_mm() const noexcept { return wheel_y_offset_; }
  /// Radius of the wheel at profile z: r = r0 + z, r0 = NOMRADW − z_w(YTAPE).
  double wheel_r0_mm() const noexcept { return wheel_r0_; }
  /// The gauge point of the canted rail in profile coordinates (GAUGHT > 0).
  std::optional<double> gauge_y_mm() const noexcept { return gauge_y_; }
  double rail_top_z_mm() const noexcept { return rail_top_z_; }

 private:
  model::WheelRailProfile rail_profile_, wheel_profile_;
  double rail_roll_ = 0.0, gauge_height_ = 0.0, ytape_ = 0.0;
  ProfileCurve rail_, wheel_;
  std::shared_ptr<const SlicedSurface> wheel_surface_, rail_surface_;
  double rail_u_ = 0.0;
  double wheel_theta_ = 0.0;
  std::optional<double> gauge_y_;
  double rail_top_z_ = 0.0;
  double z_tape_ = 0.0;
  double rail_y_ = 0.0, rail_z_ = 0.0;
  double wheel_y_offset_ = 0.0, wheel_r0_ = 0.0;
  bool roller_ = false;
  double roller_axle_z_ = 0.0;
  double roller_sign_ = 1.0;  ///< +1 external roller (axle below), −1 internal (axle above)
};

}  // namespace rollcontact::wheelrail
