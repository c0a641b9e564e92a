#include "wheelrail/sliced_weights.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rollcontact::wheelrail {

namespace {

constexpr double kWindow_rad = 0.08;  ///< as the sliced locus's search (sliced_locus.cpp)

}  // namespace

double full_window_mm(const PlacedProfiles& prof) {
  return kWindow_rad * prof.wheel_r0_mm();
}

HeightsAlongX wheel_heights_along_x(const PlacedProfiles& prof, const WheelsetPose& pose, double y,
                                    double x_centre, double z_start, double step,
                                    double half_window_mm) {
  HeightsAlongX h;
  const double half = std::min(half_window_mm, full_window_mm(prof));
  const auto n = static_cast<int>(std::ceil(half / step));
  h.step_mm = step;
  h.x0_mm = x_centre - step * n;
  h.z.reserve(static_cast<std::size_t>(2 * n + 1));
  for (int k = -n; k <= n; ++k) {
    double t = 0.0;
    const bool hit = wheel_surface_along(prof, pose, Vec3{x_centre + step * k, y, 0.0},
                                         Vec3{0.0, 0.0, 1.0}, z_start, t);
    h.z.push_back(hit ? t : std::numeric_limits<double>::quiet_NaN());
  }
  return h;
}

SampleMoments gap_moments_along_x(const HeightsAlongX& wheel, double rail_z, double z_ws,
                                  bool linear) {
  SampleMoments m;
  m.x_min = std::numeric_limits<double>::max();
  m.x_max = -m.x_min;
  for (std::size_t k = 0; k < wheel.z.size(); ++k) {
    const double pen = wheel.z[k] + z_ws - rail_z;
    if (!(pen > 0.0)) continue;  // NaN: the line missed the wheel
    const double x = wheel.x0_mm + wheel.step_mm * static_cast<double>(k);
    const double w = (linear ? pen : pen * pen) * wheel.step_mm;
    m.weight += w;
    m.weight_x += w * x;
    m.x_min = std::min(m.x_min, x);
    m.x_max = std::max(m.x_max, x);
  }
  if (m.weight == 0.0) m.x_min = m.x_max = 0.0;
  return m;
}

bool reaches_window_end(const HeightsAlongX& wheel, const SampleMoments& m) {
  if (!(m.weight > 0.0) || wheel.z.empty()) return false;
  const double last = wheel.x0_mm + wheel.step_mm * static_cast<double>(wheel.z.size() - 1);
  return m.x_min <= wheel.x0_mm || m.x_max >= last;
}

}  // namespace rollcontact::wheelrail
