// The trapezoidal step of the sprung mass and the wheel on a contact spring, against closed-form
// motion: a wheel on a linear spring oscillates about its equilibrium with sqrt(k/m), the
// trapezoidal rule keeps the amplitude (no numerical damping) and lags by (ω·dt)²/12 per radian.

#include <gtest/gtest.h>

#include <cmath>

#include "dynamics/two_mass_step.hpp"

namespace rollcontact::dynamics {
namespace {

/// A wheel alone (no suspension) on a linear contact spring k_c from z = 0, carrying the
/// weight of both masses: equilibrium W/k_c.
struct LinearContact {
  double k_c = 1.8e6;  // N/mm
  double operator()(double z, double) const { return z > 0.0 ? k_c * z : 0.0; }
};

TwoMassSystem decoupled() {
  TwoMassSystem s;
  s.stiffness = 0.0;
  s.damping = 0.0;
  return s;
}

TEST(TrapezoidalStep, WheelOnALinearSpringOscillatesWithItsNaturalFrequency) {
  const TwoMassSystem sys = decoupled();
  const LinearContact contact;
  const double weight = (sys.sprung_mass + sys.wheel_mass) * sys.gravity;
  const double z_eq = weight / contact.k_c, omega = std::sqrt(contact.k_c / sys.wheel_mass);
  // Start at the equilibrium with a velocity: z(t) = z_eq + (v0/ω)·sin ωt, contact never opens.
  TwoMassState s;
  s.z_w = s.z_s = z_eq;
  s.v_w = 5.0;  // mm/s, amplitude 2 µm against z_eq ≈ 55 µm
  double f = contact(s.z_w, 0.0);
  set_accelerations(sys, f, 0.0, s);
  StepSettings st;
  st.dt = 2e-5;
  st.force_tolerance = 1e-6;
  const int steps = 1000;  // ≈ 7 periods
  for (int n = 0; n < steps; ++n) {
    const StepResult r = trapezoidal_step(sys, s, f, contact.k_c, st, contact);
    ASSERT_TRUE(r.converged);
    EXPECT_EQ(r.solves, 1);  // the linear model is exact
    s = r.next;
    f = r.fz;
  }
  // The trapezoidal rule's discrete frequency: tan(ω_h·dt/2) = ω·dt/2.
  const double omega_h = 2.0 / st.dt * std::atan(omega * st.dt / 2.0);
  const double t = steps * st.dt;
  EXPECT_NEAR(s.z_w, z_eq + 5.0 / omega * std::sin(omega_h * t), 1e-9);
  EXPECT_NEAR(s.v_w, 5.0 * std::cos(omega_h * t), 1e-5);
  // and against the exact motion, within the phase lag (ω·dt)²/12 per radian.
  const double lag = std::pow(omega * st.dt, 2) / 12.0 * omega * t;
  EXPECT_NEAR(s.z_w, z_eq + 5.0 / omega * std::sin(omega * t), 1.1 * 5.0 / omega * lag);
}

TEST(TrapezoidalStep, NonlinearContactIsIteratedToItsTolerance) {
  // Hertz F = C·δ^1.5 with a poor first guess of the stiffness (0): the secant iterations
  // bring the force to the linear model's prediction within the tolerance.
  const TwoMassSystem sys = decoupled();
  const double c = 1e5 / std::pow(0.075, 1.5);
  auto hertz = [c](double z, double) { return z > 0.0 ? c * std::pow(z, 1.5) : 0.0; };
  TwoMassState s;  // dropped onto the rail from first contact, at rest
  double f = 0.0;
  set_accelerations(sys, f, 0.0, s);
  StepSettings st;
  st.dt = 2e-5;
  st.force_tolerance = 1.0;
  double energy0 = 0.0, max_f = 0.0;
  const double weight = (sys.sprung_mass + sys.wheel_mass) * sys.gravity;
  auto energy = [&](const TwoMassState& x) {
    // kinetic + contact potential (2/5)·C·δ^2.5 − work of the weight
    const double d = std::max(x.z_w, 0.0);
    return 0.5 * sys.wheel_mass * x.v_w * x.v_w + 0.4 * c * std::pow(d, 2.5) - weight * x.z_w;
  };
  energy0 = energy(s);
  double stiffness = 0.0;
  for (int n = 0; n < 400; ++n) {
    const StepResult r = trapezoidal_step(sys, s, f, stiffness, st, hertz);
    ASSERT_TRUE(r.converged) << n;
    ASSERT_LE(r.solves, 4) << n;
    s = r.next;
    f = r.fz;
    stiffness = r.stiffness;
    max_f = std::max(max_f, f);
  }
  // Energy is conserved to the step's force tolerance times the travel (no numerical damping,
  // no growth); the peak force of a Hertzian drop from rest is 2^1.5 = 2.83 × the static load
  // only for a linear spring: for δ^1.5, δ_max solves (2/5)·C·δ^2.5 = W·δ.
  EXPECT_NEAR(energy(s), energy0, 1e-3 * weight * 0.1);
  const double delta_max = std::pow(2.5 * weight / c, 1.0 / 1.5);
  EXPECT_NEAR(max_f, c * std::pow(delta_max, 1.5), 0.01 * weight);
}

TEST(TrapezoidalStep, SuspensionCarriesTheSprungMassAtRest) {
  // Both masses at rest with the spring at its static length and the contact carrying the
  // total weight: nothing moves.
  TwoMassSystem sys;
  const double weight = (sys.sprung_mass + sys.wheel_mass) * sys.gravity;
  const double k_c = 1.8e6, z0 = weight / k_c;
  auto contact = [k_c](double z, double) { return k_c * z; };
  TwoMassState s;
  s.z_s = s.z_w = z0;
  double f = weight;
  set_accelerations(sys, f, 0.0, s);
  EXPECT_DOUBLE_EQ(s.a_s, 0.0);
  EXPECT_NEAR(s.a_w, 0.0, 1e-9);
  StepSettings st;
  for (int n = 0; n < 100; ++n) {
    const StepResult r = trapezoidal_step(sys, s, f, k_c, st, contact);
    s = r.next;
    f = r.fz;
  }
  EXPECT_NEAR(s.z_w, z0, 1e-12);
  EXPECT_NEAR(s.z_s, z0, 1e-12);
}

TEST(TrapezoidalStep, ContactDamperDecaysTheOscillationAtItsRate) {
  // Wheel on a linear spring with a damper of ratio ζ: the amplitude falls as e^(−ζωt).
  TwoMassSystem sys = decoupled();
  const LinearContact contact;
  const double omega = std::sqrt(contact.k_c / sys.wheel_mass), zeta = 0.05;
  sys.contact_damping = 2.0 * zeta * std::sqrt(contact.k_c * sys.wheel_mass);
  const double weight = (sys.sprung_mass + sys.wheel_mass) * sys.gravity;
  const double z_eq = weight / contact.k_c;
  TwoMassState s;
  s.z_w = s.z_s = z_eq;
  s.v_w = 5.0;
  double f = contact(s.z_w, 0.0);
  set_accelerations(sys, f, 0.0, s);
  StepSettings st;
  st.dt = 1e-5;
  st.force_tolerance = 1e-6;
  // Peaks of z − z_eq over the last of 10 periods against the damped envelope.
  const double period = 2.0 * M_PI / omega;
  const int steps = static_cast<int>(10.0 * period / st.dt);
  double peak = 0.0;
  for (int n = 1; n <= steps; ++n) {
    const StepResult r = trapezoidal_step(sys, s, f, contact.k_c, st, contact);
    s = r.next;
    f = r.fz;
    if (n * st.dt > 9.0 * period) peak = std::max(peak, s.z_w - z_eq);
  }
  const double omega_d = omega * std::sqrt(1.0 - zeta * zeta);
  const double expected = 5.0 / omega_d * std::exp(-zeta * omega * 9.25 * period);
  EXPECT_NEAR(peak, expected, 0.02 * expected);
}

}  // namespace
}  // namespace rollcontact::dynamics
