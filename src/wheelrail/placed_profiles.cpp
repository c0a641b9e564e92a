#include "wheelrail/placed_profiles.hpp"

#include <algorithm>
#include <cmath>

#include "rollcontact/errors.hpp"

namespace rollcontact::wheelrail {

namespace {

/// The rail's roll: DROLLR against the cant (a roller rig has none).
double rail_roll_of(const model::WheelRailProblem& p) {
  return (p.roller.enabled ? 0.0 : -p.track.cant_rad) + p.rail_state.droll_rad;
}

bool same_slices(const SlicedProfile& a, const SlicedProfile& b) {
  if (a.u != b.u || a.u_intpol != b.u_intpol || a.nfeat != b.nfeat ||
      a.slices.size() != b.slices.size())
    return false;
  for (std::size_t i = 0; i < a.slices.size(); ++i)
    if (a.slices[i].y != b.slices[i].y || a.slices[i].z != b.slices[i].z) return false;
  return true;
}

bool same_profile(const model::WheelRailProfile& a, const model::WheelRailProfile& b) {
  const model::ProfileSmoothing &s = a.smoothing, &t = b.smoothing;
  return a.points.y == b.points.y && a.points.z == b.points.z && same_slices(a.slices, b.slices) &&
         s.method == t.method && s.smooth == t.smooth &&
         s.zigzag_threshold_rad == t.zigzag_threshold_rad && s.kink_high_rad == t.kink_high_rad &&
         s.kink_low_rad == t.kink_low_rad && s.kink_window_mm == t.kink_window_mm &&
         s.max_omitted_fraction == t.max_omitted_fraction;
}

/// The gauge point (physics.md §13.2): on the canted profile, among the points on the track side
/// of the highest point that lie less than GAUGHT below it, the one furthest to the track side —
/// at depth GAUGHT exactly when the range ends there (found on the spline), else the point where
/// the profile turns back (vertical tangent).
double find_gauge_point(const ProfileCurve& rail, double gaught, double& top_z) {
  const std::vector<double>& y = rail.node_y();
  const std::vector<double>& z = rail.node_z();
  const std::size_t top =
      static_cast<std::size_t>(std::min_element(z.begin(), z.end()) - z.begin());
  top_z = z[top];
  const double depth = top_z + gaught;
  double y_min = y[top];
  for (std::size_t i = top; i-- > 0;) {
    if (z[i] > depth) {
      // Crossing between nodes i and i+1: bisection on the spline parameter.
      double lo = rail.node_s()[i], hi = rail.node_s()[i + 1];
      const CurvePoint a = rail.at_s(lo);
      if (a.z < depth) return std::min(y_min, a.y);  // not a crossing after all
      for (int it = 0; it < 60; ++it) {
        const double mid = 0.5 * (lo + hi);
        (rail.at_s(mid).z > depth ? lo : hi) = mid;
      }
      return std::min(y_min, rail.at_s(0.5 * (lo + hi)).y);
    }
    y_min = std::min(y_min, y[i]);
  }
  return y_min;
}

std::shared_ptr<const SlicedSurface> surface_of(const model::WheelRailProfile& profile,
                                                SurfaceBody body, double roll_rad) {
  if (profile.slices.u.empty()) return nullptr;
  return std::make_shared<const SlicedSurface>(profile.slices, profile.smoothing, body, roll_rad);
}

/// The cross-section of a sliced wheel at material angle θ, or of a sliced (and rolled) rail at
/// track position u, as a curve: the surface is already smooth, so the curve interpolates its
/// points (no second smoothing).
ProfileCurve cross_section_curve(const SlicedSurface& surface,
                                 const model::ProfileSmoothing& smoothing, double u, bool rail) {
  model::ProfileSmoothing interpolate = smoothing;
  interpolate.smooth = 0.0;
  return ProfileCurve(model::WheelRailProfile{surface.cross_section(u), interpolate, {}}, rail);
}

}  // namespace

PlacedProfiles::PlacedProfiles(const model::WheelRailProblem& p)
    : rail_profile_(p.rail),
      wheel_profile_(p.wheel),
      rail_roll_(rail_roll_of(p)),
      gauge_height_(p.track.gauge_height_mm),
      ytape_(p.wheelset.tape_circle_y_mm),
      rail_(p.rail, true, rail_roll_of(p), 0.0, 0.0),
      wheel_(p.wheel, false),
      wheel_surface_(surface_of(p.wheel, SurfaceBody::Wheel, 0.0)),
      rail_surface_(surface_of(p.rail, SurfaceBody::Rail, rail_roll_of(p))),
      roller_(p.roller.enabled) {
  if (wheel_surface_) {
    // The tape circle of a sliced wheel is taken at θ = 0 (a fixed r0 for every rotation).
    wheel_ = cross_section_curve(*wheel_surface_, p.wheel.smoothing, 0.0, false);
    wheel_theta_ = 0.0;
  }
  if (rail_surface_) {
    if (gauge_height_ > 0.0)
      throw ProblemError(
          "a rail that varies along the track (rail slices) is placed absolutely: the gauge "
          "height GAUGHT must be ≤ 0 (spec/physics.md §13.9)");
    rail_u_ = p.motion.s_mm;
    rail_ = cross_section_curve(*rail_surface_, p.rail.smoothing, rail_u_, true);
  }
  if (gauge_height_ > 0.0) {
    gauge_y_ = find_gauge_point(rail_, gauge_height_, rail_top_z_);
  } else {
    const auto& z = rail_.node_z();
    rail_top_z_ = *std::min_element(z.begin(), z.end());
  }
  if (std::abs(ytape_) < 999.0) {
    const CurvePoint t = wheel_.at_y(ytape_);
    if (t.found) z_tape_ = t.z;
  }
  place(p);
}

bool PlacedProfiles::same_curves(const model::WheelRailProblem& p) const {
  return p.roller.enabled == roller_ && rail_roll_of(p) == rail_roll_ &&
         p.track.gauge_height_mm == gauge_height_ && p.wheelset.tape_circle_y_mm == ytape_ &&
         same_profile(p.rail, rail_profile_) && same_profile(p.wheel, wheel_profile_);
}

void PlacedProfiles::place(const model::WheelRailProblem& p) {
  if (gauge_y_) {
    rail_y_ = 0.5 * p.track.gauge_width_mm - *gauge_y_ + p.rail_state.dy_mm;
    // A track's rail top lies in the track plane; a roller's profile origin does (its z values
    // are offsets to NOMRADR, spec/wheelrail-advanced.md §4.2).
    rail_z_ = (roller_ ? 0.0 : -rail_top_z_) + p.rail_state.dz_mm;
  } else {
    rail_y_ = p.track.rail_y0_mm + p.rail_state.dy_mm;
    rail_z_ = p.track.rail_z0_mm + p.rail_state.dz_mm;
  }
  const model::WheelsetGeometry& w = p.wheelset;
  wheel_y_offset_ = 0.5 * w.flange_back_distance_mm - w.flange_back_position_mm;
  wheel_r0_ = w.nominal_radius_mm - z_tape_;
  if (roller_) {
    roller_axle_z_ = rail_z_ + p.roller.nominal_radius_mm;
    roller_sign_ = p.roller.nominal_radius_mm < 0.0 ? -1.0 : 1.0;
  }
  // A sliced rail's cross-section under the wheelset, at u = S_WS.
  if (rail_surface_ && p.motion.s_mm != rail_u_) {
    rail_u_ = p.motion.s_mm;
    rail_ = cross_section_curve(*rail_surface_, rail_profile_.smoothing, rail_u_, true);
  }
  // The wheel's own pitch deviation DPITCHW turns its slices with the wheelset's pitch.
  const double theta = -(p.motion.pitch_rad + p.wheel_deviation.dpitch_rad);
  if (wheel_surface_ && theta != wheel_theta_) {
    wheel_theta_ = theta;
    wheel_ = cross_section_curve(*wheel_surface_, wheel_profile_.smoothing, wheel_theta_, false);
  }
}

CurvePoint PlacedProfiles::rail_at_track_y(double y) const {
  CurvePoint c = rail_.at_y(y - rail_y_);
  c.y = y;
  c.z += rail_z_;
  return c;
}

RailSurfacePoint PlacedProfiles::rail_surface_at(double x, double y) const {
  const CurvePoint c = rail_at_track_y(y);
  RailSurfacePoint s;
  if (!c.found) return s;
  if (rail_surface_) {
    // The section at u = S_WS + x, in the rail's profile coordinates (rolled, not shifted).
    const SurfacePoint r = rail_surface_->at(rail_u_ + x, y - rail_y_);
    if (r.found) s = {true, r.z + rail_z_, r.dz_du, r.dz_dy};
    return s;
  }
  if (!roller_) {
    s = {true, c.z, 0.0, c.dz_dy};
    return s;
  }
  // The section at y is a circle of radius r about the axle: z = z_axle ∓ √(r² − x²), written
  // as the fall from the top, x²/(r + √(r² − x²)), to keep its digits for a large roller.
  const double r = std::abs(c.z - roller_axle_z_);
  const double root2 = r * r - x * x;
  if (!(root2 > 0.0)) return s;
  const double root = std::sqrt(root2);
  s.found = true;
  s.z = c.z + roller_sign_ * x * x / (r + root);
  s.dz_dx = roller_sign_ * x / root;
  s.dz_dy = c.dz_dy * r / root;
  return s;
}

}  // namespace rollcontact::wheelrail
