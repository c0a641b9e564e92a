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
  const double y_ws = prof.wheel_y_offset_mm() + y_p, r0 = prof.wheel_r0_mm();
  bool found = true;
  const auto point_at = [&](double phi, bool scanned = false) {
    const double u = prof.wheel_theta_rad() + phi;
    const SurfaceSection* section = scanned && scan != nullptr ? scan->at(surface, u) : nullptr;
    const SurfacePoint w = section != nullptr ? surface.at(*section, y_p) : surface.at(u, y_p);
    if (!w.found) found = false;
    const double r = r0 + w.z;
    return pose.wheel_centre +
           pose.wheel_rotation * Vec3{r * std::sin(phi), y_ws, r * std::cos(phi)};
  };
  // Scan the window for the deepest sample (a flat can make two local maxima: its edges), then
  // narrow the bracket around it by golden sections.
  double best_phi = phi_start, best_z = point_at(phi_start, true).z;
  const int steps = static_cast<int>(kWindow_rad / kScanStep_rad);
  for (int i = -steps; i <= steps; ++i) {
    const double phi = phi_start + kScanStep_rad * i;
    const double z = point_at(phi, true).z;
    if (z > best_z) {
      best_z = z;
      best_phi = phi;
    }
  }
  if (!found) return {};
  // The deepest point is the lowest: the minimum of −z, by Brent's method to 1e-7 rad (about 8
  // evaluations where golden sections took 22).
  double minus_z = 0.0;
  const double phi =
      brent_minimum([&](double p) { return -point_at(p).z; }, best_phi - kScanStep_rad,
                    best_phi + kScanStep_rad, 1e-7, 100, minus_z);
  return {-minus_z >= best_z ? point_at(phi) : point_at(best_phi), found};
}

}  // namespace rollcontact::wheelrail
