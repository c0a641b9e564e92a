#include "wheelrail/pitch_velocity.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace rollcontact::wheelrail {

namespace {

/// The inner (vertical) tolerance follows the outer residual: loose far from the answer, EPS
/// near it (spec-additions §A6: max(res/5, EPS)).
double inner_tolerance(double residual, double eps) {
  return std::max(std::abs(residual) / 5.0, eps);
}

}  // namespace

double inverse_saturation(double y) {
  // g(u) = 1 − (1 − u/3)³ on [0, 3]: u = 3·(1 − (1 − y)^(1/3)).
  const double a = std::min(std::abs(y), 0.999);
  return std::copysign(3.0 * (1.0 - std::cbrt(1.0 - a)), y);
}

PitchVelocityResult solve_pitch_velocity(
    const PitchVelocitySettings& st, PitchVelocitySample first,
    const std::function<PitchVelocitySample(double, double)>& solve) {
  const double m = std::max(st.saturation, 1e-6);
  auto residual = [&](const PitchVelocitySample& s) { return s.ratio - st.target; };
  auto mapped = [&](const PitchVelocitySample& s) { return inverse_saturation(s.ratio / m); };
  const double goal = inverse_saturation(st.target / m);
  PitchVelocityResult out;
  double omega = st.start_rad_s;
  PitchVelocitySample at = first;
  const double eps = st.vertical_tolerance;
  double used_tolerance = eps;            // of the vertical iteration behind `at`
  double slope = st.slope_s_per_rad / m;  // of the mapped force; g'(0) = 1
  for (;;) {
    if (at.usable && std::abs(residual(at)) <= st.tolerance && used_tolerance > eps) {
      // Reached on a loose vertical solve: the same VPITCH once more to EPS decides.
      at = solve(omega, eps);
      used_tolerance = eps;
    }
    out.vpitch_rad_s = omega;
    out.residual = residual(at);
    if (at.usable && std::abs(out.residual) <= st.tolerance) {
      out.converged = true;
      return out;
    }
    if (!at.usable) {
      out.message = "a solve of the pitch-velocity iteration did not converge";
      return out;
    }
    if (out.iterations >= st.max_iterations) {
      out.message = fmt::format(
          "the pitch velocity for the prescribed FX_WS did not converge in MAXNR = {} iterations "
          "(F_x/F_z off by {:.3e}; |FX_WS| may exceed what friction can carry)",
          st.max_iterations, out.residual);
      return out;
    }
    double step = std::clamp((goal - mapped(at)) / slope, -st.max_step_rad_s, st.max_step_rad_s);
    PitchVelocitySample next;
    for (int h = 0;; ++h) {
      ++out.iterations;
      // Loose inner solves while far off (they only steer the next step).
      used_tolerance = inner_tolerance(residual(at), eps);
      next = solve(omega + step, used_tolerance);
      const bool calm = next.usable && std::abs(next.ratio - at.ratio) <= st.max_jump;
      if (calm || h >= st.max_halvings || out.iterations >= st.max_iterations) break;
      step *= 0.5;
    }
    // Secant slope, kept only with the expected sign (beyond saturation there is none) and
    // when the change is well above what the vertical errors of the two solves make of it.
    const double noise = (at.vertical_error + next.vertical_error) * std::abs(at.ratio) / 3.0;
    const double secant = (mapped(next) - mapped(at)) / step;
    if (next.usable && std::isfinite(secant) && secant * slope > 0.0 &&
        std::abs(next.ratio - at.ratio) > 4.0 * noise)
      slope = secant;
    omega += step;
    at = next;
  }
}

}  // namespace rollcontact::wheelrail
