#include "wheelrail/sliced_surface.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>

#include "rollcontact/errors.hpp"
#include "wheelrail/profile_curve.hpp"

namespace rollcontact::wheelrail {

namespace {

/// Spacing of the resampled points along a slice [mm]: fine against the smoothed profile's
/// curvature radii (≥ ~10 mm), so the cubic spline through them is the slice's curve to ~1e-7 mm.
constexpr double kResampleStep_mm = 0.25;

/// The uniform cubic B-spline basis on one parameter interval u ∈ [0, 1] and its derivative.
void bspline_basis(double u, std::array<double, 4>& b, std::array<double, 4>& db) {
  const double v = 1.0 - u, u2 = u * u, u3 = u2 * u;
  b = {v * v * v / 6.0, (3.0 * u3 - 6.0 * u2 + 4.0) / 6.0,
       (-3.0 * u3 + 3.0 * u2 + 3.0 * u + 1.0) / 6.0, u3 / 6.0};
  db = {-0.5 * v * v, (3.0 * u2 - 4.0 * u) / 2.0, (-3.0 * u2 + 2.0 * u + 1.0) / 2.0, 0.5 * u2};
}

/// Control points (n + 2, with an end phantom each side) of the uniform cubic B-spline that
/// interpolates d at integer parameters with natural ends (the phantoms c₋₁ = 2c₀ − c₁ make the
/// second derivative vanish there): (c_{k−1} + 4c_k + c_{k+1})/6 = d_k.
std::vector<double> interpolating_controls(const std::vector<double>& d) {
  const std::size_t n = d.size();
  std::vector<double> c(n + 2, 0.0);
  c[1] = d.front();
  c[n] = d.back();
  if (n > 2) {
    // Interior rows k = 1..n−2: c_{k−1} + 4c_k + c_{k+1} = 6d_k (Thomas algorithm).
    const std::size_t m = n - 2;
    std::vector<double> diag(m, 4.0), rhs(m);
    for (std::size_t i = 0; i < m; ++i) rhs[i] = 6.0 * d[i + 1];
    rhs.front() -= d.front();
    rhs.back() -= d.back();
    for (std::size_t i = 1; i < m; ++i) {
      const double f = 1.0 / diag[i - 1];
      diag[i] -= f;
      rhs[i] -= f * rhs[i - 1];
    }
    c[m + 1] = rhs[m - 1] / diag[m - 1];
    for (std::size_t i = m - 1; i-- > 0;) c[i + 2] = (rhs[i] - c[i + 3]) / diag[i];
  }
  c[0] = 2.0 * c[1] - c[2];
  c[n + 1] = 2.0 * c[n] - c[n - 1];
  return c;
}

/// Second derivatives of the natural cubic splines through the rows of `rows` (one column per
/// control value, n rows at the increasing positions x): one tridiagonal system, many columns.
std::vector<double> natural_second_derivatives(const std::vector<double>& x,
                                               const std::vector<double>& rows,
                                               std::size_t columns) {
  const std::size_t n = x.size();
  std::vector<double> m(n * columns, 0.0);
  if (n < 3) return m;
  const std::size_t k = n - 2;
  std::vector<double> diag(k), upper(k), lower(k);
  for (std::size_t i = 0; i < k; ++i) {
    const double h0 = x[i + 1] - x[i], h1 = x[i + 2] - x[i + 1];
    lower[i] = h0;
    diag[i] = 2.0 * (h0 + h1);
    upper[i] = h1;
  }
  for (std::size_t i = 1; i < k; ++i) diag[i] -= lower[i] / diag[i - 1] * upper[i - 1];
  std::vector<double> rhs(k);
  for (std::size_t c = 0; c < columns; ++c) {
    for (std::size_t i = 0; i < k; ++i) {
      const double h0 = x[i + 1] - x[i], h1 = x[i + 2] - x[i + 1];
      const double d0 = rows[i * columns + c], d1 = rows[(i + 1) * columns + c],
                   d2 = rows[(i + 2) * columns + c];
      rhs[i] = 6.0 * ((d2 - d1) / h1 - (d1 - d0) / h0);
    }
    for (std::size_t i = 1; i < k; ++i) rhs[i] -= lower[i] / diag[i - 1] * rhs[i - 1];
    std::vector<double> sol(k);
    sol[k - 1] = rhs[k - 1] / diag[k - 1];
    for (std::size_t i = k - 1; i-- > 0;) sol[i] = (rhs[i] - upper[i] * sol[i + 1]) / diag[i];
    for (std::size_t i = 0; i < k; ++i) m[(i + 1) * columns + c] = sol[i];
  }
  return m;
}

double wrap_angle(double theta) {
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  return theta - kTwoPi * std::floor((theta + std::numbers::pi) / kTwoPi);
}

}  // namespace

SlicedSurface::SlicedSurface(const SlicedProfile& sp, const model::ProfileSmoothing& smoothing,
                             SurfaceBody body, double roll_rad)
    : body_(body), intpol_(sp.u_intpol), theta_(sp.u) {
  if (sp.nfeat > 1)
    throw NotSupportedError(
        fmt::format("not supported yet: module 1 slices with features (NFEAT = {}) in '{}'",
                    sp.nfeat, sp.file));
  if (sp.slices.empty() || sp.slices.size() != sp.u.size())
    throw GeometryError(fmt::format("slices file '{}' has no slices", sp.file));
  // Per slice: the plain-profile curve, resampled uniformly in its own arc length.
  std::vector<std::vector<double>> ys, zs;
  for (const Profile& slice : sp.slices) {
    const bool rail = body == SurfaceBody::Rail;
    const ProfileCurve curve =
        rail ? ProfileCurve(model::WheelRailProfile{slice, smoothing, {}}, true, roll_rad, 0.0, 0.0)
             : ProfileCurve(model::WheelRailProfile{slice, smoothing, {}}, false);
    if (points_ == 0)
      points_ = std::max<std::size_t>(
          4, static_cast<std::size_t>(std::ceil(curve.length() / kResampleStep_mm)) + 1);
    std::vector<double> y(points_), z(points_);
    for (std::size_t k = 0; k < points_; ++k) {
      const CurvePoint c =
          curve.at_s(curve.length() * static_cast<double>(k) / static_cast<double>(points_ - 1));
      y[k] = c.y;
      z[k] = c.z;
    }
    for (std::size_t k = 1; k < points_; ++k)
      if ((y[k] - y[k - 1]) * (y.back() - y.front()) <= 0.0)
        throw GeometryError(fmt::format(
            "slice '{}' of '{}': its lateral coordinate turns back (y not monotone along the "
            "profile), which a surface in (u, y) cannot represent",
            slice.file, sp.file));
    y_min_ = ys.empty() ? std::min(y.front(), y.back())
                        : std::max(y_min_, std::min(y.front(), y.back()));
    y_max_ = ys.empty() ? std::max(y.front(), y.back())
                        : std::min(y_max_, std::max(y.front(), y.back()));
    ys.push_back(interpolating_controls(y));
    zs.push_back(interpolating_controls(z));
  }
  ctrl_ = points_ + 2;
  if (theta_.size() == 1) {  // one slice: a body of revolution (constant in θ)
    theta_.push_back(theta_.front() + 1.0);
    ys.push_back(ys.front());
    zs.push_back(zs.front());
  }
  const std::size_t n = theta_.size();
  const auto flatten = [&](const std::vector<std::vector<double>>& rows) {
    std::vector<double> t;
    t.reserve(rows.size() * ctrl_);
    for (const auto& r : rows) t.insert(t.end(), r.begin(), r.end());
    return t;
  };
  ty_ = flatten(ys);
  tz_ = flatten(zs);
  if (n < 4) intpol_ = 1;  // too few slices for the cubic B-spline: interpolate them
  if (intpol_ == 1) {
    const std::vector<double> my = natural_second_derivatives(theta_, ty_, ctrl_);
    const std::vector<double> mz = natural_second_derivatives(theta_, tz_, ctrl_);
    ty_.insert(ty_.end(), my.begin(), my.end());
    tz_.insert(tz_.end(), mz.begin(), mz.end());
  } else {
    // Clamped cubic knots at the slices without the second and the last but one ("not a
    // knot"): n B-splines, one per slice, slice i's supported on [θ_{i−2}, θ_{i+2}].
    knots_.assign(4, theta_.front());
    knots_.insert(knots_.end(), theta_.begin() + 2, theta_.end() - 2);
    knots_.insert(knots_.end(), 4, theta_.back());
  }
  y_nodes_.assign(points_, 0.0);
  for (std::size_t k = 0; k < points_; ++k)
    y_nodes_[k] = (ys[0][k] + 4.0 * ys[0][k + 1] + ys[0][k + 2]) / 6.0;
}

double SlicedSurface::along(double u) const {
  return body_ == SurfaceBody::Wheel ? wrap_angle(u) : u;
}

SlicedSurface::ThetaBlend SlicedSurface::blend_at(double theta_rad) const {
  return intpol_ == 1 ? interpolating_blend(theta_rad) : approximating_blend(theta_rad);
}

SlicedSurface::ThetaBlend SlicedSurface::approximating_blend(double theta_rad) const {
  double th = along(theta_rad);
  const bool outside = th <= theta_.front() || th >= theta_.back();
  th = std::clamp(th, theta_.front(), theta_.back());
  // Knot span k: knots_[k] <= θ < knots_[k + 1]; B-splines k−3..k are nonzero there.
  const std::size_t n = theta_.size();
  std::size_t k =
      static_cast<std::size_t>(std::upper_bound(knots_.begin(), knots_.end(), th) - knots_.begin());
  k = std::clamp<std::size_t>(k, 4, n) - 1;
  // Cox–de Boor recursion up to degree 3; the degree-2 values give the derivatives.
  std::array<std::array<double, 4>, 4> basis{};
  basis[0][0] = 1.0;
  std::array<double, 4> left{}, right{};
  for (std::size_t d = 1; d <= 3; ++d) {
    left[d] = th - knots_[k + 1 - d];
    right[d] = knots_[k + d] - th;
    double saved = 0.0;
    for (std::size_t r = 0; r < d; ++r) {
      const double temp = basis[d - 1][r] / (right[r + 1] + left[d - r]);
      basis[d][r] = saved + right[r + 1] * temp;
      saved = left[d - r] * temp;
    }
    basis[d][d] = saved;
  }
  ThetaBlend b;
  for (std::size_t j = 0; j < 4; ++j) {
    const std::size_t i = k - 3 + j;  // the B-spline's (and its slice's) index
    const double span_lo = knots_[i + 3] - knots_[i], span_hi = knots_[i + 4] - knots_[i + 1];
    double d = 0.0;
    if (j >= 1 && span_lo > 0.0) d += 3.0 * basis[2][j - 1] / span_lo;
    if (j <= 2 && span_hi > 0.0) d -= 3.0 * basis[2][j] / span_hi;
    b.row[j] = i;
    b.w[j] = basis[3][j];
    b.dw[j] = outside ? 0.0 : d;
  }
  return b;
}

SlicedSurface::ThetaBlend SlicedSurface::interpolating_blend(double theta_rad) const {
  double th = along(theta_rad);
  const bool outside = th <= theta_.front() || th >= theta_.back();
  th = std::clamp(th, theta_.front(), theta_.back());
  const std::size_t n = theta_.size();
  std::size_t j =
      static_cast<std::size_t>(std::upper_bound(theta_.begin(), theta_.end(), th) - theta_.begin());
  j = std::clamp<std::size_t>(j, 1, n - 1) - 1;
  const double h = theta_[j + 1] - theta_[j];
  const double a = (theta_[j + 1] - th) / h, bb = 1.0 - a;
  ThetaBlend r;
  r.row = {j, j + 1, n + j, n + j + 1};
  r.w = {a, bb, (a * a * a - a) * h * h / 6.0, (bb * bb * bb - bb) * h * h / 6.0};
  if (!outside)
    r.dw = {-1.0 / h, 1.0 / h, -(3.0 * a * a - 1.0) * h / 6.0, (3.0 * bb * bb - 1.0) * h / 6.0};
  return r;
}

double SlicedSurface::blended(const std::vector<double>& table, const ThetaBlend& b, std::size_t k,
                              double* d) const {
  double v = 0.0, dv = 0.0;
  for (std::size_t a = 0; a < 4; ++a) {
    const double c = table[b.row[a] * ctrl_ + k];
    v += b.w[a] * c;
    dv += b.dw[a] * c;
  }
  if (d != nullptr) *d = dv;
  return v;
}

SurfacePoint SlicedSurface::at(double theta_rad, double y) const {
  const ThetaBlend b = blend_at(theta_rad);
  return evaluate(
      y, [&](std::size_t k, bool z, double* d) { return blended(z ? tz_ : ty_, b, k, d); });
}

SurfacePoint SlicedSurface::at(const SurfaceSection& s, double y) const {
  return evaluate(y, [&](std::size_t k, bool z, double* d) {
    if (d != nullptr) *d = z ? s.dz_du[k] : s.dy_du[k];
    return z ? s.z[k] : s.y[k];
  });
}

SurfaceSection SlicedSurface::section(double theta_rad) const {
  const ThetaBlend b = blend_at(theta_rad);
  SurfaceSection s;
  s.u = theta_rad;
  s.y.resize(ctrl_);
  s.z.resize(ctrl_);
  s.dy_du.resize(ctrl_);
  s.dz_du.resize(ctrl_);
  for (std::size_t k = 0; k < ctrl_; ++k) {
    s.y[k] = blended(ty_, b, k, &s.dy_du[k]);
    s.z[k] = blended(tz_, b, k, &s.dz_du[k]);
  }
  return s;
}

template <class Control>
SurfacePoint SlicedSurface::evaluate(double y, const Control& control) const {
  const auto node_y = [&](std::size_t k) {
    return (control(k, false, nullptr) + 4.0 * control(k + 1, false, nullptr) +
            control(k + 2, false, nullptr)) /
           6.0;
  };
  // Segment [lo, lo+1] of resampled points whose y bracket the target (y monotone along s):
  // the first slice's segment, then walked to this θ's (the nodes move little with θ; a
  // bisection over the blended nodes cost 80 % of a wheel-flat run).
  const double sign = y_nodes_.back() > y_nodes_.front() ? 1.0 : -1.0;
  const auto below = [&](double node) { return sign * (y - node) < 0.0; };
  const auto first_node_after =
      sign > 0.0 ? std::upper_bound(y_nodes_.begin(), y_nodes_.end(), y)
                 : std::upper_bound(y_nodes_.begin(), y_nodes_.end(), y, std::greater<>());
  std::size_t lo = static_cast<std::size_t>(
      std::max<std::ptrdiff_t>(first_node_after - y_nodes_.begin() - 1, 0));
  lo = std::min(lo, points_ - 2);
  double y0 = node_y(lo);
  while (below(y0)) {
    if (lo == 0) return {};
    y0 = node_y(--lo);
  }
  double y1 = node_y(lo + 1);
  while (sign * (y - y1) > 0.0) {
    if (lo + 2 >= points_) return {};
    y0 = y1;
    y1 = node_y(++lo + 1);
  }
  std::array<double, 4> cy{}, cz{}, dcy{}, dcz{};
  for (std::size_t a = 0; a < 4; ++a) {
    cy[a] = control(lo + a, false, &dcy[a]);
    cz[a] = control(lo + a, true, &dcz[a]);
  }
  std::array<double, 4> w{}, dw{};
  double u_lo = 0.0, u_hi = 1.0, u = 0.5, yu = 0.0;
  if (y1 != y0) u = std::clamp((y - y0) / (y1 - y0), 0.0, 1.0);
  for (int it = 0; it < 50; ++it) {
    bspline_basis(u, w, dw);
    double f = -y;
    yu = 0.0;
    for (std::size_t a = 0; a < 4; ++a) {
      f += w[a] * cy[a];
      yu += dw[a] * cy[a];
    }
    (sign * f < 0.0 ? u_lo : u_hi) = u;
    if (std::abs(f) <= 1e-12 * (1.0 + std::abs(y))) break;
    double next = yu != 0.0 ? u - f / yu : 0.5 * (u_lo + u_hi);
    if (!(next >= u_lo && next <= u_hi)) next = 0.5 * (u_lo + u_hi);
    if (std::abs(next - u) < 1e-15) break;
    u = next;
  }
  bspline_basis(u, w, dw);
  SurfacePoint p;
  double zu = 0.0, yth = 0.0, zth = 0.0;
  yu = 0.0;
  for (std::size_t a = 0; a < 4; ++a) {
    p.z += w[a] * cz[a];
    zu += dw[a] * cz[a];
    yu += dw[a] * cy[a];
    yth += w[a] * dcy[a];
    zth += w[a] * dcz[a];
  }
  p.dz_dy = zu / yu;
  p.dz_du = zth - p.dz_dy * yth;
  p.found = std::isfinite(p.z) && std::isfinite(p.dz_dy);
  return p;
}

Profile SlicedSurface::cross_section(double theta_rad) const {
  const ThetaBlend b = blend_at(theta_rad);
  Profile p;
  p.format = ProfileFormat::Plain;
  const bool wheel = body_ == SurfaceBody::Wheel;
  p.file = wheel ? fmt::format("wheel slices at theta = {:.6f} rad", theta_rad)
                 : fmt::format("rail slices at u = {:.6f} mm", theta_rad);
  p.y.resize(points_);
  p.z.resize(points_);
  for (std::size_t k = 0; k < points_; ++k) {
    p.y[k] = (blended(ty_, b, k) + 4.0 * blended(ty_, b, k + 1) + blended(ty_, b, k + 2)) / 6.0;
    p.z[k] = (blended(tz_, b, k) + 4.0 * blended(tz_, b, k + 1) + blended(tz_, b, k + 2)) / 6.0;
  }
  if (wheel == (p.y.front() < p.y.back())) {  // canonical order: a wheel's descending y
    std::reverse(p.y.begin(), p.y.end());
    std::reverse(p.z.begin(), p.z.end());
  }
  return p;
}

}  // namespace rollcontact::wheelrail
