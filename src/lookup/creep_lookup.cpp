// CreepLookupTable: construction checks and multilinear interpolation (the part an MBS code
// calls at every wheel and time step: no allocation, a binary search per axis, 16 nodes).

#include "rollcontact/creep_lookup.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "rollcontact/errors.hpp"

namespace rollcontact {

namespace {

void check_axis(const std::vector<double>& axis, const char* name) {
  if (axis.size() < 2)
    throw InvalidValueError(name, fmt::format("needs at least 2 values, has {}", axis.size()));
  for (std::size_t i = 0; i < axis.size(); ++i) {
    if (!std::isfinite(axis[i]))
      throw InvalidValueError(name, fmt::format("value {} is not finite", i + 1));
    if (i > 0 && !(axis[i] > axis[i - 1]))
      throw InvalidValueError(
          name, fmt::format("must increase strictly: {} follows {}", axis[i], axis[i - 1]));
  }
}

/// The interval [lo, lo+1] of `axis` holding x (clamped to the axis) and the weight of lo+1.
struct Bracket {
  std::size_t lo;
  double t;
};

/// `logarithmic`: the weight from ln x (the semi-axis ratio, whose values span decades and on
/// which the creep coefficients depend about linearly in ln(a/b)).
Bracket bracket(const std::vector<double>& axis, double x, bool logarithmic = false) {
  const std::size_t n = axis.size();
  if (!(x > axis.front())) return {0, 0.0};  // also NaN: the first node
  if (x >= axis.back()) return {n - 2, 1.0};
  const std::size_t hi =
      static_cast<std::size_t>(std::upper_bound(axis.begin(), axis.end(), x) - axis.begin());
  const std::size_t lo = hi - 1;
  if (logarithmic) return {lo, std::log(x / axis[lo]) / std::log(axis[hi] / axis[lo])};
  return {lo, (x - axis[lo]) / (axis[hi] - axis[lo])};
}

}  // namespace

CreepLookupTable::CreepLookupTable(CreepLookupAxes axes, std::vector<CreepLookupValue> values,
                                   CreepLookupInfo info)
    : axes_(std::move(axes)), values_(std::move(values)), info_(std::move(info)) {
  check_axis(axes_.a_over_b, "a_over_b");
  check_axis(axes_.ksi, "ksi");
  check_axis(axes_.eta, "eta");
  check_axis(axes_.phi, "phi");
  if (!(axes_.a_over_b.front() > 0.0))
    throw InvalidValueError("a_over_b", "semi-axis ratios must be positive");
  const std::size_t nodes =
      axes_.a_over_b.size() * axes_.ksi.size() * axes_.eta.size() * axes_.phi.size();
  if (values_.size() != nodes)
    throw InvalidValueError(
        "values", fmt::format("{} values for {} nodes of the axes", values_.size(), nodes));
  for (std::size_t i = 0; i < nodes; ++i) {
    const CreepLookupValue& v = values_[i];
    if (!std::isfinite(v.fx) || !std::isfinite(v.fy) || !std::isfinite(v.mz))
      throw InvalidValueError("values", fmt::format("node {} is not finite", i));
  }
}

CreepLookupValue CreepLookupTable::evaluate(double a_over_b, double ksi_n, double eta_n,
                                            double phi_n) const noexcept {
  CreepLookupValue out;
  if (values_.empty()) return out;
  // (ξ̃, η̃) outside its box: back onto the border along the ray from the origin.
  const double kx = ksi_n > 0.0 ? ksi_n / axes_.ksi.back() : ksi_n / axes_.ksi.front();
  const double ky = eta_n > 0.0 ? eta_n / axes_.eta.back() : eta_n / axes_.eta.front();
  const double over = std::max({1.0, std::isfinite(kx) ? kx : 1.0, std::isfinite(ky) ? ky : 1.0});
  const Bracket a = bracket(axes_.a_over_b, a_over_b, true);
  const Bracket x = bracket(axes_.ksi, ksi_n / over);
  const Bracket y = bracket(axes_.eta, eta_n / over);
  const Bracket z = bracket(axes_.phi, phi_n);
  for (int da = 0; da < 2; ++da) {
    const double wa = da ? a.t : 1.0 - a.t;
    if (wa == 0.0) continue;
    for (int dx = 0; dx < 2; ++dx) {
      const double wx = wa * (dx ? x.t : 1.0 - x.t);
      if (wx == 0.0) continue;
      for (int dy = 0; dy < 2; ++dy) {
        const double wy = wx * (dy ? y.t : 1.0 - y.t);
        if (wy == 0.0) continue;
        for (int dz = 0; dz < 2; ++dz) {
          const double w = wy * (dz ? z.t : 1.0 - z.t);
          if (w == 0.0) continue;
          const CreepLookupValue& v =
              values_[node_index(a.lo + da, x.lo + dx, y.lo + dy, z.lo + dz)];
          out.fx += w * v.fx;
          out.fy += w * v.fy;
          out.mz += w * v.mz;
        }
      }
    }
  }
  return out;
}

CreepLookupForces CreepLookupTable::forces(double a_mm, double b_mm, double fn_N, double g_N_mm2,
                                           double mu, double ksi, double eta,
                                           double phi_rad_mm) const noexcept {
  CreepLookupForces f;
  if (!(a_mm > 0.0 && b_mm > 0.0 && fn_N > 0.0 && g_N_mm2 > 0.0 && mu > 0.0)) return f;
  const double c = std::sqrt(a_mm * b_mm);
  const double mufn = mu * fn_N;
  const double scale = g_N_mm2 * c * c / mufn;
  const CreepLookupValue v =
      evaluate(a_mm / b_mm, scale * ksi, scale * eta, scale * c * phi_rad_mm);
  f.fx_N = v.fx * mufn;
  f.fy_N = v.fy * mufn;
  f.mz_Nmm = v.mz * mufn * c;
  return f;
}

}  // namespace rollcontact
