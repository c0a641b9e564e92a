#include "contact/force_iteration.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>

namespace rollcontact {

namespace {

/// Perturbation for the finite-difference start: CONTACT's fallback step.
constexpr double fd_step = 3e-6;

/// The first step from x0 with the previous case's slope, if that slope is usable: finite, not
/// zero, and giving a step of at most 100 times the larger of |x0| and the finite-difference step
/// (a slope from full sliding is nearly zero and would throw the start far away).
std::optional<double> newton_start(double x0, double r0, double slope) {
  if (!std::isfinite(slope) || slope == 0.0) return std::nullopt;
  const double step = -r0 / slope;
  if (!std::isfinite(step) || std::abs(step) > 100.0 * std::max(std::abs(x0), fd_step))
    return std::nullopt;
  return x0 + step;
}

ForceIterationResult one_unknown(const ForceIterationInput& in,
                                 const std::function<std::array<double, 2>(double, double)>& f) {
  ForceIterationResult r;
  r.eta = in.fixed_eta;
  auto residual = [&](double ksi) { return f(ksi, in.fixed_eta)[0] - in.target_x; };
  double x0 = in.start_ksi, r0 = residual(x0);
  r.ksi = x0;
  if (std::abs(r0) <= in.eps) {
    r.converged = true;
    r.jacobian = in.start_jacobian;  // kept for the next case of the sequence
    return r;
  }
  double x1 = newton_start(x0, r0, in.start_jacobian[0]).value_or(x0 + fd_step);
  if (x1 == x0) x1 = x0 + fd_step;
  const double r1 = residual(x1);
  double slope = (r1 - r0) / (x1 - x0);
  // Bracket [lo, hi] with residual(lo) and residual(hi) of opposite sign, once known.
  bool bracketed = (r0 < 0.0) != (r1 < 0.0);
  double lo = x0, hi = x1, rlo = r0, rhi = r1;
  double x = x1, rx = r1;
  for (int it = 1; it <= in.max_iterations; ++it) {
    r.iterations = it;
    r.ksi = x;
    r.jacobian[0] = slope;
    if (std::abs(rx) <= in.eps) {
      r.converged = true;
      return r;
    }
    double next = slope != 0.0 && std::isfinite(slope) ? x - rx / slope : x + 10.0 * fd_step;
    if (bracketed && !(next > std::min(lo, hi) && next < std::max(lo, hi))) next = 0.5 * (lo + hi);
    const double rnext = residual(next);
    if (next != x) slope = (rnext - rx) / (next - x);
    // Keep a bracket around the root.
    if (bracketed) {
      if ((rnext < 0.0) == (rlo < 0.0)) {
        lo = next;
        rlo = rnext;
      } else {
        hi = next;
        rhi = rnext;
      }
    } else if ((rnext < 0.0) != (rx < 0.0)) {
      bracketed = true;
      lo = x;
      rlo = rx;
      hi = next;
      rhi = rnext;
    }
    x = next;
    rx = rnext;
  }
  (void)rhi;
  r.ksi = x;
  r.converged = std::abs(rx) <= in.eps;
  if (!r.converged)
    r.message = fmt::format(
        "the force iteration (F=1) did not converge in MAXNR = {} steps: |FX/(mu FN) - target| = "
        "{:.3e}",
        in.max_iterations, std::abs(rx));
  return r;
}

ForceIterationResult two_unknowns(const ForceIterationInput& in,
                                  const std::function<std::array<double, 2>(double, double)>& f) {
  ForceIterationResult r;
  double x = in.start_ksi, y = in.start_eta;
  auto res = [&](double a, double b) {
    const auto v = f(a, b);
    return std::array<double, 2>{v[0] - in.target_x, v[1] - in.target_y};
  };
  auto size = [](const std::array<double, 2>& v) { return std::abs(v[0]) + std::abs(v[1]); };
  std::array<double, 2> rv = res(x, y);
  r.ksi = x;
  r.eta = y;
  if (size(rv) <= in.eps) {
    r.converged = true;
    r.jacobian = in.start_jacobian;  // kept for the next case of the sequence
    return r;
  }
  // The previous case's Jacobian, else finite differences at the start.
  std::array<double, 4> j = in.start_jacobian;
  const double det0 = j[0] * j[3] - j[1] * j[2];
  if (!std::isfinite(det0) || std::abs(det0) <= 1e-12 * (j[0] * j[0] + j[3] * j[3])) {
    const auto rx = res(x + fd_step, y);
    const auto ry = res(x, y + fd_step);
    j = {(rx[0] - rv[0]) / fd_step, (ry[0] - rv[0]) / fd_step, (rx[1] - rv[1]) / fd_step,
         (ry[1] - rv[1]) / fd_step};
  }
  for (int it = 1; it <= in.max_iterations; ++it) {
    r.iterations = it;
    const double det = j[0] * j[3] - j[1] * j[2];
    double dx, dy;
    if (det != 0.0 && std::isfinite(det)) {
      dx = -(j[3] * rv[0] - j[1] * rv[1]) / det;
      dy = -(-j[2] * rv[0] + j[0] * rv[1]) / det;
    } else {
      dx = dy = fd_step;
    }
    // Damped step: halve while the residual grows (full sliding makes the Jacobian small).
    std::array<double, 2> rn{};
    double t = 1.0;
    for (int k = 0; k < 6; ++k) {
      rn = res(x + t * dx, y + t * dy);
      if (size(rn) < size(rv) || k == 5) break;
      t *= 0.5;
    }
    const double sx = t * dx, sy = t * dy;
    // Broyden update J += (Δr − J s) sᵀ / (sᵀ s).
    const double ss = sx * sx + sy * sy;
    if (ss > 0.0) {
      const double ex = (rn[0] - rv[0]) - (j[0] * sx + j[1] * sy);
      const double ey = (rn[1] - rv[1]) - (j[2] * sx + j[3] * sy);
      j[0] += ex * sx / ss;
      j[1] += ex * sy / ss;
      j[2] += ey * sx / ss;
      j[3] += ey * sy / ss;
    }
    x += sx;
    y += sy;
    rv = rn;
    r.ksi = x;
    r.eta = y;
    r.jacobian = j;
    if (size(rv) <= in.eps) {
      r.converged = true;
      return r;
    }
  }
  r.message =
      fmt::format("the force iteration (F=2) did not converge in MAXNR = {} steps: residual {:.3e}",
                  in.max_iterations, size(rv));
  return r;
}

}  // namespace

ForceIterationResult force_iteration(
    const ForceIterationInput& in,
    const std::function<std::array<double, 2>(double, double)>& evaluate) {
  return in.unknowns == 2 ? two_unknowns(in, evaluate) : one_unknown(in, evaluate);
}

}  // namespace rollcontact
