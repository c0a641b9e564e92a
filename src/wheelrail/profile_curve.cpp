#include "wheelrail/profile_curve.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "rollcontact/errors.hpp"
#include "wheelrail/smoothing_spline.hpp"

namespace rollcontact::wheelrail {

namespace {

/// Direction change at each interior node [rad, signed, in (−π, π]]; 0 at both ends.
std::vector<double> direction_changes(const std::vector<double>& y, const std::vector<double>& z) {
  const std::size_t n = y.size();
  std::vector<double> turn(n, 0.0);
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const double a0 = std::atan2(z[i] - z[i - 1], y[i] - y[i - 1]);
    const double a1 = std::atan2(z[i + 1] - z[i], y[i + 1] - y[i]);
    turn[i] = std::remainder(a1 - a0, 2.0 * std::numbers::pi);
  }
  return turn;
}

/// §8.3 step 2: two successive direction changes beyond the threshold are a zig-zag; its two
/// points are replaced by their mean. Returns the number of points removed.
std::size_t remove_zigzags(std::vector<double>& y, std::vector<double>& z, double threshold) {
  std::size_t removed = 0;
  for (bool again = true; again && y.size() >= 4;) {
    again = false;
    const std::vector<double> turn = direction_changes(y, z);
    for (std::size_t i = 1; i + 2 < y.size(); ++i) {
      if (std::abs(turn[i]) > threshold && std::abs(turn[i + 1]) > threshold) {
        y[i] = 0.5 * (y[i] + y[i + 1]);
        z[i] = 0.5 * (z[i] + z[i + 1]);
        y.erase(y.begin() + static_cast<std::ptrdiff_t>(i) + 1);
        z.erase(z.begin() + static_cast<std::ptrdiff_t>(i) + 1);
        ++removed;
        again = true;
        break;
      }
    }
  }
  return removed;
}

/// Kinks (physics.md §13.1): a direction change above KINKHIGH while every other node within
/// ±KINKWID (chord length) turns less than KINKLOW.
std::vector<std::size_t> find_kinks(const std::vector<double>& s, const std::vector<double>& turn,
                                    const model::ProfileSmoothing& opt) {
  std::vector<std::size_t> kinks;
  for (std::size_t i = 1; i + 1 < s.size(); ++i) {
    if (std::abs(turn[i]) <= opt.kink_high_rad) continue;
    bool isolated = true;
    for (std::size_t j = i; j-- > 1 && s[i] - s[j] <= opt.kink_window_mm;)
      if (std::abs(turn[j]) >= opt.kink_low_rad) isolated = false;
    for (std::size_t j = i + 1; j + 1 < s.size() && s[j] - s[i] <= opt.kink_window_mm; ++j)
      if (std::abs(turn[j]) >= opt.kink_low_rad) isolated = false;
    if (isolated) kinks.push_back(i);
  }
  return kinks;
}

/// Weights and λ of the smoothing spline of one section (spec-additions §A1).
void smoothing_of(const model::ProfileSmoothing& opt, const std::vector<double>& s,
                  std::vector<double>& weights, double& lambda) {
  weights.clear();
  lambda = 0.0;
  if (opt.smooth <= 0.0) return;
  if (opt.method == 0) {
    lambda = opt.smooth;
    return;
  }
  // Weighted: half the neighbouring chord lengths, λ = (L_filt / 2π)^4 (ISMOOTH = 2, the
  // third-order penalty: (L_filt / 2π)^6).
  const std::size_t n = s.size();
  weights.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double lo = i > 0 ? s[i] - s[i - 1] : 0.0;
    const double hi = i + 1 < n ? s[i + 1] - s[i] : 0.0;
    weights[i] = std::max(0.5 * (lo + hi), 1e-9);
  }
  lambda = std::pow(opt.smooth / (2.0 * std::numbers::pi), opt.method == 2 ? 6 : 4);
}

}  // namespace

ProfileCurve::ProfileCurve(const model::WheelRailProfile& profile, bool upper_surface)
    : ProfileCurve(profile, upper_surface, 0.0, 0.0, 0.0) {}

ProfileCurve::ProfileCurve(const model::WheelRailProfile& profile, bool upper_surface,
                           double roll_rad, double dy_mm, double dz_mm)
    : upper_(upper_surface) {
  const std::vector<double>& py = profile.points.y;
  const std::vector<double>& pz = profile.points.z;
  std::vector<double> y(py.size()), z(pz.size());
  const double c = std::cos(roll_rad), sn = std::sin(roll_rad);
  for (std::size_t i = 0; i < py.size(); ++i) {
    y[i] = dy_mm + c * py[i] - sn * pz[i];
    z[i] = dz_mm + sn * py[i] + c * pz[i];
  }
  build(std::move(y), std::move(z), profile);
}

void ProfileCurve::build(std::vector<double> y, std::vector<double> z,
                         const model::WheelRailProfile& p) {
  const model::ProfileSmoothing& opt = p.smoothing;
  const std::size_t n_read = y.size();
  if (n_read < 2)
    throw GeometryError(fmt::format("profile {}: fewer than 2 points", p.points.file));
  const double zig = std::max(opt.zigzag_threshold_rad, std::numbers::pi / 4);
  const std::size_t removed = zig < std::numbers::pi ? remove_zigzags(y, z, zig) : 0;
  if (static_cast<double>(removed) > opt.max_omitted_fraction * static_cast<double>(n_read))
    throw GeometryError(fmt::format(
        "profile {}: the clean-up would remove {} of {} points (more than MAXOMIT = {}); "
        "check the file",
        p.points.file, removed, n_read, opt.max_omitted_fraction));
  const std::size_t n = y.size();
  std::vector<double> s(n, 0.0);
  for (std::size_t i = 1; i < n; ++i)
    s[i] = s[i - 1] + std::hypot(y[i] - y[i - 1], z[i] - z[i - 1]);
  const std::vector<std::size_t> kinks = find_kinks(s, direction_changes(y, z), opt);

  // Sections [start, end] share the kink node; each is fitted on its own.
  std::vector<std::size_t> bounds{0};
  bounds.insert(bounds.end(), kinks.begin(), kinks.end());
  bounds.push_back(n - 1);
  for (std::size_t k = 0; k + 1 < bounds.size(); ++k) {
    const auto b = static_cast<std::ptrdiff_t>(bounds[k]);
    const auto e = static_cast<std::ptrdiff_t>(bounds[k + 1]) + 1;
    const std::vector<double> ss(s.begin() + b, s.begin() + e);
    std::vector<double> w;
    double lambda = 0.0;
    smoothing_of(opt, ss, w, lambda);
    std::vector<double> ys(y.begin() + b, y.begin() + e), zs(z.begin() + b, z.begin() + e);
    if (opt.method == 2 && lambda > 0.0) {
      // ISMOOTH = 2: the third-order penalty smooths the values, a cubic interpolates them.
      ys = smooth_third_order(ss, ys, w, lambda);
      zs = smooth_third_order(ss, zs, w, lambda);
      lambda = 0.0;
    }
    const SplineNodes fy = fit_smoothing_spline(ss, ys, w, lambda);
    const SplineNodes fz = fit_smoothing_spline(ss, zs, w, lambda);
    if (!s_.empty()) segment_break_.back() = 1;  // the zero-length step onto the shared node
    section_start_.push_back(s_.size());
    for (std::size_t i = 0; i < ss.size(); ++i) {
      s_.push_back(ss[i]);
      y_.push_back(fy.value[i]);
      z_.push_back(fz.value[i]);
      y2_.push_back(fy.second[i]);
      z2_.push_back(fz.second[i]);
      segment_break_.push_back(0);
    }
  }
  segment_break_.pop_back();  // one flag per segment (nodes − 1)

  y_min_ = *std::min_element(y_.begin(), y_.end());
  y_max_ = *std::max_element(y_.begin(), y_.end());
  increasing_ = y_.back() > y_.front();
  monotone_ = true;
  for (std::size_t k = 0; k + 1 < y_.size(); ++k) {
    if (segment_break_[k]) continue;
    if (increasing_ ? !(y_[k + 1] > y_[k]) : !(y_[k + 1] < y_[k])) monotone_ = false;
  }
}

void ProfileCurve::eval_segment(std::size_t k, double t, double& y, double& z, double& dy,
                                double& dz) const {
  const double h = s_[k + 1] - s_[k];
  const double u = t / h, v = 1.0 - u;
  const double c = h * h / 6.0;
  y = y_[k] * v + y_[k + 1] * u + c * (y2_[k] * (v * v * v - v) + y2_[k + 1] * (u * u * u - u));
  z = z_[k] * v + z_[k + 1] * u + c * (z2_[k] * (v * v * v - v) + z2_[k + 1] * (u * u * u - u));
  const double d = h / 6.0;
  dy = (y_[k + 1] - y_[k]) / h +
       d * (y2_[k] * (1.0 - 3.0 * v * v) + y2_[k + 1] * (3.0 * u * u - 1.0));
  dz = (z_[k + 1] - z_[k]) / h +
       d * (z2_[k] * (1.0 - 3.0 * v * v) + z2_[k + 1] * (3.0 * u * u - 1.0));
}

CurvePoint ProfileCurve::solve_in_segment(std::size_t k, double y) const {
  return solve_in_segment(k, y, -1.0);
}

CurvePoint ProfileCurve::solve_in_segment(std::size_t k, double y, double t0) const {
  // y(t) = y on [0, h]: Newton from t0 or the chord's estimate, inside a shrinking bracket.
  const double h = s_[k + 1] - s_[k];
  double lo = 0.0, hi = h;
  const bool up = y_[k + 1] > y_[k];
  double t = t0 >= 0.0 && t0 <= h ? t0 : std::clamp((y - y_[k]) / (y_[k + 1] - y_[k]) * h, 0.0, h);
  double yy = 0.0, zz = 0.0, dy = 0.0, dz = 0.0;
  for (int it = 0; it < 40; ++it) {
    eval_segment(k, t, yy, zz, dy, dz);
    const double r = yy - y;
    if (std::abs(r) <= 1e-12 * (1.0 + std::abs(y))) break;
    if ((r < 0) == up)
      lo = t;
    else
      hi = t;
    double next = dy != 0.0 ? t - r / dy : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::abs(next - t) <= 1e-14 * h) break;
    t = next;
  }
  eval_segment(k, t, yy, zz, dy, dz);
  CurvePoint p;
  p.y = y;
  p.z = zz;
  p.dz_dy = dz / dy;
  p.s = s_[k] + t;
  p.found = true;
  return p;
}

CurvePoint ProfileCurve::at_y(double y) const {
  if (y < y_min_ || y > y_max_ || y_.size() < 2) return {};
  if (monotone_) {
    // Segment whose node interval holds y (nodes ascending or descending in y).
    std::size_t k = 0;
    if (increasing_) {
      k = static_cast<std::size_t>(std::upper_bound(y_.begin(), y_.end(), y) - y_.begin());
    } else {
      k = static_cast<std::size_t>(std::upper_bound(y_.begin(), y_.end(), y, std::greater<>()) -
                                   y_.begin());
    }
    k = std::clamp<std::size_t>(k, 1, y_.size() - 1) - 1;
    while (k + 1 < y_.size() && segment_break_[k]) ++k;
    return solve_in_segment(k, y);
  }
  CurvePoint best;
  for (std::size_t k = 0; k + 1 < y_.size(); ++k) {
    if (segment_break_[k]) continue;
    const double a = std::min(y_[k], y_[k + 1]), b = std::max(y_[k], y_[k + 1]);
    if (y < a || y > b || a == b) continue;
    const CurvePoint p = solve_in_segment(k, y);
    if (!best.found || (upper_ ? p.z < best.z : p.z > best.z)) best = p;
  }
  return best;
}

CurvePoint ProfileCurve::at_y(double y, CurveHint& hint) const {
  const std::size_t k = hint.segment;
  if (monotone_ && y_.size() >= 2 && k < y_.size() - 1 && !segment_break_[k] &&
      y >= std::min(y_[k], y_[k + 1]) && y <= std::max(y_[k], y_[k + 1])) {
    const CurvePoint p = solve_in_segment(k, y, hint.t);
    hint.t = p.s - s_[k];
    return p;
  }
  const CurvePoint p = at_y(y);
  if (p.found && monotone_) {
    hint.segment = static_cast<std::size_t>(
        std::clamp<std::ptrdiff_t>(std::upper_bound(s_.begin(), s_.end(), p.s) - s_.begin(), 1,
                                   static_cast<std::ptrdiff_t>(s_.size()) - 1) -
        1);
    hint.t = p.s - s_[hint.segment];
  }
  return p;
}

CurvePoint ProfileCurve::at_s(double s) const {
  CurvePoint p;
  if (s_.size() < 2) return p;
  s = std::clamp(s, s_.front(), s_.back());
  std::size_t k = static_cast<std::size_t>(std::upper_bound(s_.begin(), s_.end(), s) - s_.begin());
  k = std::clamp<std::size_t>(k, 1, s_.size() - 1) - 1;
  while (k + 1 < s_.size() - 1 && segment_break_[k]) ++k;
  double yy = 0.0, zz = 0.0, dy = 0.0, dz = 0.0;
  eval_segment(k, s - s_[k], yy, zz, dy, dz);
  p.y = yy;
  p.z = zz;
  p.dz_dy = dz / dy;
  const double norm = std::hypot(dy, dz);
  p.dy_ds = norm > 0.0 ? dy / norm : 0.0;
  p.dz_ds = norm > 0.0 ? dz / norm : 0.0;
  p.s = s;
  p.found = true;
  return p;
}

}  // namespace rollcontact::wheelrail
