#include "wheelrail/sliced_locus.hpp"

#include <cmath>

#include "wheelrail/golden_section.hpp"

namespace rollcontact::wheelrail {

namespace {

constexpr double kWindow_rad = 0.08;     ///< search half-width around the round wheel's locus
constexpr double kScanStep_rad = 0.002;  ///< ≈ 1 mm: finer than any flat's edge rounding

}  // namespace

LocusPoint sliced_locus_point(const PlacedProfiles& prof, const WheelsetPose& pose, double y_p,
                              double phi_start) {
  const SlicedSurface& surface = *prof.wheel_surface();
  const double y_ws = prof.wheel_y_offset_mm() + y_p, r0 = prof.wheel_r0_mm();
  bool found = true;
  const auto point_at = [&](double phi) {
    const SurfacePoint w = surface.at(prof.wheel_theta_rad() + phi, y_p);
    if (!w.found) found = false;
    const double r = r0 + w.z;
    return pose.wheel_centre +
           pose.wheel_rotation * Vec3{r * std::sin(phi), y_ws, r * std::cos(phi)};
  };
  // Scan the window for the deepest sample (a flat can make two local maxima: its edges), then
  // narrow the bracket around it by golden sections.
  double best_phi = phi_start, best_z = point_at(phi_start).z;
  const int steps = static_cast<int>(kWindow_rad / kScanStep_rad);
  for (int i = -steps; i <= steps; ++i) {
    const double phi = phi_start + kScanStep_rad * i;
    const double z = point_at(phi).z;
    if (z > best_z) {
      best_z = z;
      best_phi = phi;
    }
  }
  if (!found) return {};
  // The deepest point is the lowest: the minimum of −z (bracket down to 1e-7 rad).
  const GoldenBracket br =
      golden_section_minimum([&](double phi) { return -point_at(phi).z; }, best_phi - kScanStep_rad,
                             best_phi + kScanStep_rad, 1e-7, 1000);
  const double phi = 0.5 * (br.a + br.b);
  const Vec3 pt = point_at(phi);
  return {pt.z >= best_z ? pt : point_at(best_phi), found};
}

}  // namespace rollcontact::wheelrail
