#include "format/profiles/profile_points.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace rollcontact::format {

namespace {

/// Keeps the points for which keep(k) is true.
template <typename Keep>
void filter_points(RawProfile& p, Keep keep) {
  std::size_t n = 0;
  const bool with_k = p.k_yield.size() == p.y.size();
  for (std::size_t k = 0; k < p.y.size(); ++k) {
    if (!keep(k)) continue;
    p.y[n] = p.y[k];
    p.z[n] = p.z[k];
    if (with_k) p.k_yield[n] = p.k_yield[k];
    ++n;
  }
  p.y.resize(n);
  p.z.resize(n);
  if (with_k) p.k_yield.resize(n);
}

void reverse_points(RawProfile& p) {
  std::reverse(p.y.begin(), p.y.end());
  std::reverse(p.z.begin(), p.z.end());
  std::reverse(p.k_yield.begin(), p.k_yield.end());
}

/// Auto-detection of an upward z axis for Miniprof/plain files (spec §8.3 step 5): a rail in
/// canonical form has z decreasing from both ends towards the middle (the top of the head is
/// the highest point); a wheel has its minimum z (highest point) near one end, not at the flange.
bool z_points_upward(const RawProfile& p, bool is_wheel) {
  const std::size_t n = p.z.size();
  if (n < 3) return false;
  if (!is_wheel) {
    const double mid = p.z[n / 2];
    return p.z.front() < mid && p.z.back() < mid;
  }
  const auto imin =
      static_cast<std::size_t>(std::min_element(p.z.begin(), p.z.end()) - p.z.begin());
  const std::size_t margin = std::max<std::size_t>(1, n / 20);
  return imin >= margin && imin + margin < n;
}

}  // namespace

Profile finish_profile(RawProfile raw, const ProfileOptions& options,
                       std::vector<std::string>& warnings) {
  // 1. points closer than the minimum spacing to their (kept) predecessor
  {
    const std::size_t before = raw.y.size();
    std::size_t last = 0;
    const double min2 = raw.min_spacing * raw.min_spacing;
    filter_points(raw, [&](std::size_t k) {
      if (k == 0) return true;
      const double dy = raw.y[k] - raw.y[last];
      const double dz = raw.z[k] - raw.z[last];
      if (dy * dy + dz * dz < min2) return false;
      last = k;
      return true;
    });
    if (raw.y.size() != before) {
      warnings.push_back(fmt::format("{}: {} point(s) closer than {} to their predecessor removed",
                                     raw.file, before - raw.y.size(), raw.min_spacing));
    }
  }
  // 3. shifts / offsets and the SIMPACK bounding box
  for (double& v : raw.y) v += raw.shift_y;
  for (double& v : raw.z) v += raw.shift_z;
  if (raw.bound_y_min < raw.bound_y_max) {
    filter_points(raw, [&](std::size_t k) {
      return raw.y[k] >= raw.bound_y_min && raw.y[k] <= raw.bound_y_max;
    });
  }
  if (raw.bound_z_min < raw.bound_z_max) {
    for (double& v : raw.z) v = std::clamp(v, raw.bound_z_min, raw.bound_z_max);
  }
  if (raw.inversion == 1) reverse_points(raw);
  // 4. mirror y: the .inp flag and the SIMPACK flag cancel each other
  const int my = std::max(0, options.mirror_y) + raw.mirror_y_flag;
  if (my == 1) {
    for (double& v : raw.y) v = -v;
  }
  // 5. mirror z: explicit, SIMPACK flag, or auto-detected for Miniprof/plain files
  bool mirror_z = std::max(0, options.mirror_z) + raw.mirror_z_flag == 1;
  if (options.mirror_z == 0 && raw.format != ProfileFormat::Simpack &&
      z_points_upward(raw, options.is_wheel)) {
    mirror_z = true;
    warnings.push_back(fmt::format("{}: z axis detected as pointing upwards; mirrored", raw.file));
  }
  if (mirror_z) {
    for (double& v : raw.z) v = -v;
  }
  // 6. scale to mm
  const double scale = std::max(options.scale_yz, 1e-6) * raw.length_to_mm;
  for (double& v : raw.y) v *= scale;
  for (double& v : raw.z) v *= scale;
  // 7. order: rail by ascending y, wheel by descending y
  if (raw.y.size() >= 2) {
    const bool ascending = raw.y.back() > raw.y.front();
    if (ascending == options.is_wheel) reverse_points(raw);
  }

  Profile out;
  out.file = std::move(raw.file);
  out.format = raw.format;
  out.y = std::move(raw.y);
  out.z = std::move(raw.z);
  out.k_yield = std::move(raw.k_yield);
  return out;
}

double profile_chord_length(const Profile& profile) {
  double length = 0.0;
  for (std::size_t k = 1; k < profile.y.size(); ++k) {
    length += std::hypot(profile.y[k] - profile.y[k - 1], profile.z[k] - profile.z[k - 1]);
  }
  return length;
}

}  // namespace rollcontact::format
