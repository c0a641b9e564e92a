// cntc_getprofilevalues (spec library-api.md §2.5): a rail or wheel profile of a module-1
// element sampled on the smooth curve the contact search uses (wheelrail::ProfileCurve).

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "bindings/c/cntc_export.hpp"
#include "bindings/c/cntc_library.hpp"
#include "format/inp/to_wheelrail.hpp"
#include "rollcontact/errors.hpp"
#include "wheelrail/profile_curve.hpp"

namespace rollcontact::cntc {
namespace {

struct Samples {
  std::vector<double> y, z, s, angle;
};

/// The curve sampled as isampl asks: −1 the input points, 0 the spline nodes, 1 every ds_out mm
/// of arc length, 2..100 that many points per spline interval.
Samples sample(const wheelrail::ProfileCurve& c, const Profile& points, int isampl, double ds_out) {
  Samples out;
  std::vector<double> at;
  const auto& s = c.node_s();
  if (isampl == 1 && ds_out >= 1e-4) {
    const int n = static_cast<int>(std::floor(c.length() / ds_out + 1e-9));
    for (int k = 0; k <= n; ++k) at.push_back(k * ds_out);
  } else if (isampl >= 2 && isampl <= 100) {
    for (std::size_t k = 0; k + 1 < s.size(); ++k)
      for (int j = 0; j < isampl; ++j) at.push_back(s[k] + (s[k + 1] - s[k]) * j / isampl);
    if (!s.empty()) at.push_back(s.back());
  } else if (isampl != -1) {
    at = s;
  }
  const double direction =
      c.node_y().size() >= 2 && c.node_y().back() < c.node_y().front() ? -1.0 : 1.0;
  auto add = [&](const wheelrail::CurvePoint& p) {
    out.y.push_back(p.y);
    out.z.push_back(p.z);
    out.s.push_back(p.s);
    out.angle.push_back(std::atan2(direction * p.dz_dy, direction));
  };
  if (isampl == -1) {
    for (std::size_t i = 0; i < points.y.size(); ++i) {
      wheelrail::CurvePoint p = c.at_y(points.y[i]);
      p.y = points.y[i];
      p.z = points.z[i];
      add(p);
    }
  } else {
    for (double v : at) add(c.at_s(v));
  }
  return out;
}

}  // namespace
}  // namespace rollcontact::cntc

using namespace rollcontact;
using namespace rollcontact::cntc;

CNTC_EXPORT void cntc_getprofilevalues(int* ire, int* itask, int* nints, int* iparam, int* nreals,
                                       double* rparam, int* lenarr, double* values) {
  constexpr const char* name = "cntc_getprofilevalues";
  if (itask == nullptr || lenarr == nullptr || values == nullptr) return;
  const int whole = -1;
  Module1Problem* p = open_target(ire, &whole, Access::Module1, name).m1;
  if (p == nullptr) return;
  const int n_i = nints != nullptr ? *nints : 0, n_r = nreals != nullptr ? *nreals : 0;
  const bool wheel = n_i >= 1 && iparam != nullptr && std::clamp(iparam[0], 0, 1) == 1;
  const int isampl = n_i >= 2 && iparam != nullptr ? iparam[1] : 0;
  const double ds_out = n_r >= 1 && rparam != nullptr ? rparam[0] : 1.0;
  const format::ProfileSpec& spec = wheel ? p->record.wheel : p->record.rail;
  const std::string& error = wheel ? p->wheel_error : p->rail_error;
  const bool missing = spec.profile->y.empty() || !error.empty();
  auto put = [&](const std::vector<double>& v, int offset) {
    for (std::size_t k = 0; k < v.size() && offset + static_cast<int>(k) < *lenarr; ++k)
      values[offset + static_cast<int>(k)] = v[k];
  };
  if (*itask == -1) return put({missing ? -32.0 : 0.0, missing ? 1.0 : 0.0}, 0);
  if (missing) return put({-32.0}, 0);
  if (*itask >= 6 && *itask <= 8) {  // slices exist for variable profiles only (§2.5)
    library().log(
        fmt::format("{}: task {} needs a variable profile; this one is not", name, *itask));
    return;
  }
  if (*itask < 0 || *itask > 9) {
    library().log(fmt::format("{}: task {} not available (-1 to 9)", name, *itask));
    return;
  }
  if ((*itask == 2 || *itask == 3) && !p->result) {
    library().log(
        fmt::format("{}: task {} (track coordinates) needs a calculation first", name, *itask));
    return;
  }
  if (*itask == 3) {
    if (wheel) return put({-32.0}, 0);
    // [ygauge1, zgauge1] the gauge point in rail-profile coordinates, [yoffs, zoffs] the
    // profile's origin in the track, [ygauge2, zgauge2] the gauge point in the track [L]. The
    // placement puts the gauge point GAUGHT below the rail top at half the gauge (physics.md
    // §13.2); without a gauge height (GAUGHT <= 0) the gauge values are 0.
    const format::WheelRailRecord& r = p->record;
    const ProfileMarker& m = p->result->rail_marker_tr;
    const double side = r.is_left() ? -1.0 : 1.0, len = p->units.length;
    std::vector<double> out = {0.0, 0.0, m.position.y / len, m.position.z / len, 0.0, 0.0};
    if (r.track.gaught > 0.0) {
      const double yt = side * (0.5 * r.track.gaugwd + r.rail_deviations.dy);
      const double zt = r.track.gaught + r.rail_deviations.dz;
      const double dy = yt - m.position.y, dz = zt - m.position.z, a = m.roll_rad;
      out[0] = side * (std::cos(a) * dy + std::sin(a) * dz) / len;
      out[1] = (-std::sin(a) * dy + std::cos(a) * dz) / len;
      out[4] = yt / len;
      out[5] = zt / len;
    }
    return put(out, 0);
  }
  try {
    const wheelrail::ProfileCurve curve(format::to_wheelrail_profile(spec), !wheel);
    const Samples s = sample(curve, *spec.profile, *itask == 9 ? 0 : isampl, ds_out);
    const int n = static_cast<int>(s.y.size());
    switch (*itask) {
      case 0:
        return put({double(n)}, 0);
      case 1:  // own coordinates, mm (not scaled)
        put(s.y, 0);
        return put(s.z, n);
      case 2: {  // track coordinates with the last calculation's markers, z down (mm)
        const ProfileMarker& m = wheel ? p->result->wheel_marker_tr : p->result->rail_marker_tr;
        const double side = p->record.is_left() ? -1.0 : 1.0, a = m.roll_rad;
        const double stretch = wheel ? std::cos(m.yaw_rad) : 1.0;
        std::vector<double> y(s.y.size()), z(s.z.size());
        for (std::size_t k = 0; k < y.size(); ++k) {
          const double yp = side * s.y[k] * stretch, zp = s.z[k];
          y[k] = m.position.y + std::cos(a) * yp - std::sin(a) * zp;
          z[k] = m.position.z + std::sin(a) * yp + std::cos(a) * zp;
        }
        put(y, 0);
        return put(z, n);
      }
      case 4:
        return put(s.s, 0);
      case 9:  // the curve's nodes: s, y, z (the spline data, for debugging)
        put(s.s, 0);
        put(s.y, n);
        return put(s.z, 2 * n);
      default:  // 5: surface angle atan2(dz, dy) [rad]
        return put(s.angle, 0);
    }
  } catch (const Error& e) {
    library().log(std::string(name) + ": " + e.what());
    put({-32.0}, 0);
  }
}

CNTC_EXPORT void cntc_getprofilevalues_new(int* ire, int* itask, int* nints, int* iparam,
                                           int* nreals, double* rparam, int* lenarr,
                                           double* values) {
  cntc_getprofilevalues(ire, itask, nints, iparam, nreals, rparam, lenarr, values);
}
