// The penalty oscillator of spec dynamic-rolling.md §5.5: one contact node on its penalty spring
// and damper, integrated with the central differences of eq 2, against the analytic stability
// of the scheme.

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "fe_advice/value_checks.hpp"
#include "rollcontact/fe_advice.hpp"

namespace rollcontact::fe_advice {

namespace {

// The envelope is measured over this many windows; the first half is the start-up transient
// (the faster of the two modes dies out), the second half gives the growth.
constexpr int kWindows = 10;
// A neutral mode (ξ = 0 below the limit) beats with the period 2π/(π − θ) steps; each window
// must hold several beats for its maximum to be the amplitude.
constexpr double kPeriodsPerWindow = 4.0;
constexpr int kMaxSteps = 20'000'000;
// Relative growth per step still counted as bounded: the window maxima of a neutral mode scatter
// by ~1e-3 over ≥ 5·10³ steps, i.e. ≤ 1e-6 per step.
constexpr double kBoundedTolerance = 1e-6;

/// Steps the run needs so that every window covers kPeriodsPerWindow oscillations of the slowest
/// envelope (the undamped period 2π/Ω, or the beat near the limit Ω ≈ 2).
int steps_needed(int requested, double omega_dt) {
  const double theta = std::acos(std::clamp(1.0 - 0.5 * omega_dt * omega_dt, -1.0, 1.0));
  const double slowest =
      2.0 * std::numbers::pi / std::max(std::min(theta, std::numbers::pi - theta), 1e-9);
  const double needed = kWindows * kPeriodsPerWindow * slowest;
  return static_cast<int>(std::clamp(std::max(static_cast<double>(requested), needed), 100.0,
                                     static_cast<double>(kMaxSteps)));
}

/// The state of the linear scheme divided by e^log_scale, so that neither a growing nor a
/// decaying response leaves the range of doubles.
struct ScaledState {
  double x = 0.0, v_half = 0.0;
  double log_scale = 0.0;

  [[nodiscard]] double log_abs_x() const { return log_scale + std::log(std::abs(x)); }
  void rescale() {
    constexpr double kBig = 1e100;
    const double ax = std::abs(x) + std::abs(v_half);  // v may be large while x passes 0
    if (ax > kBig || (ax < 1.0 / kBig && ax > 0.0)) {
      const double f = 1.0 / ax;
      x *= f;
      v_half *= f;
      log_scale -= std::log(f);
    }
  }
};

}  // namespace

double central_difference_spectral_radius(double omega_dt, double damping_ratio) {
  detail::require_non_negative("omega_dt", omega_dt);
  detail::require_non_negative("damping_ratio", damping_ratio);
  // x_{n+1} − 2x_n + x_{n−1} = −Ω²x_n − 2ξΩ(x_n − x_{n−1}): eq 2 with c·v_{n−½}.
  const double b = omega_dt * omega_dt + 2.0 * damping_ratio * omega_dt - 2.0;
  const double c = 1.0 - 2.0 * damping_ratio * omega_dt;
  const double disc = b * b - 4.0 * c;
  if (disc < 0.0) return std::sqrt(c);  // complex pair, |z|² = product of the roots
  const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
  if (q == 0.0) return 0.0;
  return std::max(std::abs(q), std::abs(c / q));
}

OscillatorRun run_penalty_oscillator(const PenaltyOscillator& oscillator, double time_step_s,
                                     int steps, double initial_penetration_mm) {
  detail::require_positive("oscillator.mass_t", oscillator.mass_t);
  detail::require_positive("oscillator.stiffness_N_mm", oscillator.stiffness_N_mm);
  detail::require_non_negative("oscillator.damping_ratio", oscillator.damping_ratio);
  detail::require_positive("time_step_s", time_step_s);
  detail::require_positive("initial_penetration_mm", initial_penetration_mm);
  const double m = oscillator.mass_t, k = oscillator.stiffness_N_mm;
  const double c = 2.0 * oscillator.damping_ratio * std::sqrt(k * m);
  const double omega_dt = std::sqrt(k / m) * time_step_s;

  OscillatorRun run;
  run.steps = steps_needed(steps, omega_dt);
  run.spectral_radius = central_difference_spectral_radius(omega_dt, oscillator.damping_ratio);
  const int window = run.steps / kWindows;
  ScaledState s{initial_penetration_mm, 0.0};  // x_0 and v_{−½}: at rest
  double log_mid = 0.0, log_last = 0.0;
  for (int w = 0; w < kWindows; ++w) {
    double log_amplitude = -std::numeric_limits<double>::infinity();
    for (int i = 0; i < window; ++i) {
      // Eq 2: a_n from x_n and the lagging half-step velocity; v_{n+½}; x_{n+1}.
      const double a = (-k * s.x - c * s.v_half) / m;
      s.v_half += a * time_step_s;
      s.x += s.v_half * time_step_s;
      log_amplitude = std::max(log_amplitude, s.log_abs_x());
      s.rescale();
    }
    if (w == kWindows / 2 - 1) log_mid = log_amplitude;
    if (w == kWindows - 1) log_last = log_amplitude;
  }
  const double log_growth = (log_last - log_mid) / (static_cast<double>(window) * (kWindows / 2));
  if (std::isnan(log_growth)) {  // the response became exactly 0: x = 0 = v, nothing can grow
    run.bounded = true;
    return run;
  }
  run.growth_per_step = std::exp(log_growth);
  const double steps_per_period = 2.0 * std::numbers::pi / omega_dt;
  run.growth_per_period = std::exp(std::min(log_growth * steps_per_period, 700.0));
  run.bounded = log_growth <= kBoundedTolerance;
  return run;
}

}  // namespace rollcontact::fe_advice
