#include "wheelrail/sliced_locus.hpp"

#include <cmath>

#include "wheelrail/golden_section.hpp"

namespace rollcontact::wheelrail {

namespace {

constexpr double kWindow_rad = 0.08;     ///< search half-width around the round wheel's locus
constexpr double kScanStep_rad = 0.002;  ///< ≈ 1 mm: finer than any flat's edge rounding

}  // namespace

const SurfaceSection* LocusScanSections::at(const SlicedSurface& surface, double u) {
  if (const auto it = sections_.find(u); it != sections_.end()) return &it->second;
  if (sections_.size() >= capacity_) return nullptr;
  return &sections_.emplace(u, surface.section(u)).first->second;
}

std::size_t locus_scan_angles() {
  return 2 * static_cast<std::size_t>(kWindow_rad / kScanStep_rad) + 1;
}

LocusPoint sliced_locus_point(const PlacedProfiles& prof, const WheelsetPose& pose, double y_p,
                              double phi_start, LocusScanSections* scan) {
  const SlicedSurface& surface = *prof.wheel_surface();
  const double r0 = prof.wheel_r0_mm();
  // Track coordinates of the wheel's point at angle phi, profile position y_profile, radius r.
  const auto placed = [&](double phi, double y_profile, double r) {
    return pose.wheel_centre + pose.wheel_rotation * Vec3{r * std::sin(phi),
                                                          prof.wheel_y_offset_mm() + y_profile,
                                                          r * std::cos(phi)};
  };
  bool found = true;
  const auto point_at = [&](double phi, bool scanned = false) {
    const double u = prof.wheel_theta_rad() + phi;
    const SurfaceSection* section = scanned && scan != nullptr ? scan->at(surface, u) : nullptr;
    const SurfacePoint w = section != nullptr ? surface.at(*section, y_p) : surface.at(u, y_p);
    if (!w.found) found = false;
    return placed(phi, y_p, r0 + w.z);
  };
  // The wheel's point at angle phi and another profile position (for the lateral slope).
  const auto point_at_profile = [&](double phi, double y_profile) {
    const SurfacePoint w = surface.at(prof.wheel_theta_rad() + phi, y_profile);
    return placed(phi, y_profile, r0 + (w.found ? w.z : 0.0));
  };
  // The locus is the deepest point along a line of constant track y, not along the circle: with
  // yaw or roll the circle runs across the track, and on a steep flank (the flange) its lowest
  // point lies beside the locus (a flange contact 20 mrad yawed was missed by 0.19 mm). At the
  // deepest point of the surface along y = const, dz/dφ = s·dy/dφ with s = ∂z/∂y across the
  // profile at fixed φ, so the depth measured is z − s·y with s taken at the start angle (for a
  // round wheel the start is the closed-form locus, where this holds exactly).
  // Without yaw and roll the circle keeps its track y, and z alone decides.
  constexpr double kSlopeStep_mm = 0.05;
  const Mat3& R = pose.wheel_rotation;
  double slope = 0.0;
  if (std::abs(R.r[1][0]) + std::abs(R.r[1][2]) > 1e-14) {
    const Vec3 across_lo = point_at_profile(phi_start, y_p - kSlopeStep_mm);
    const Vec3 across_hi = point_at_profile(phi_start, y_p + kSlopeStep_mm);
    const double dy = across_hi.y - across_lo.y;
    if (std::abs(dy) > 1e-12) slope = (across_hi.z - across_lo.z) / dy;
  }
  const auto depth = [&](const Vec3& q) { return q.z - slope * q.y; };
  // Scan the window for the deepest sample (a flat can make two local maxima: its edges), then
  // narrow the bracket around it.
  double best_phi = phi_start, best_depth = depth(point_at(phi_start, true));
  const int steps = static_cast<int>(kWindow_rad / kScanStep_rad);
  for (int i = -steps; i <= steps; ++i) {
    const double phi = phi_start + kScanStep_rad * i;
    const double d = depth(point_at(phi, true));
    if (d > best_depth) {
      best_depth = d;
      best_phi = phi;
    }
  }
  if (!found) return {};
  // The deepest point: the minimum of −depth, by Brent's method to 1e-7 rad (about 8
  // evaluations where golden sections took 22).
  double minus_depth = 0.0;
  const double phi =
      brent_minimum([&](double p) { return -depth(point_at(p)); }, best_phi - kScanStep_rad,
                    best_phi + kScanStep_rad, 1e-7, 100, minus_depth);
  return {-minus_depth >= best_depth ? point_at(phi) : point_at(best_phi), found};
}

}  // namespace rollcontact::wheelrail
