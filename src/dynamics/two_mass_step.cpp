#include "dynamics/two_mass_step.hpp"

#include <cmath>

namespace rollcontact::dynamics {

void set_accelerations(const TwoMassSystem& sys, double fz, double v_rail, TwoMassState& s) {
  const double spring = sys.stiffness * (s.z_s - s.z_w) + sys.damping * (s.v_s - s.v_w);
  const double weight = (sys.sprung_mass + sys.wheel_mass) * sys.gravity;
  const double contact_damper = fz > 0.0 ? sys.contact_damping * (s.v_w - v_rail) : 0.0;
  s.a_s = -spring / sys.sprung_mass;
  s.a_w = (weight + spring - fz - contact_damper) / sys.wheel_mass;
}

namespace {

/// Newmark increments Δ_s, Δ_w of the step with the contact force taken as A + k·Δ_w and the
/// contact damper c_c (0 while out of contact) on the wheel's velocity relative to the rail's.
std::pair<double, double> increments(const TwoMassSystem& sys, const TwoMassState& s, double dt,
                                     double a_force, double k, double c_c, double v_rail) {
  const double beta = sys.stiffness + 2.0 * sys.damping / dt;  // suspension, stiffness + damping
  const double d0 = s.z_s - s.z_w, u0 = s.v_s - s.v_w;
  const double weight = (sys.sprung_mass + sys.wheel_mass) * sys.gravity;
  const double m11 = 4.0 * sys.sprung_mass / (dt * dt) + beta;
  const double m22 = 4.0 * sys.wheel_mass / (dt * dt) + beta + k + 2.0 * c_c / dt;
  const double r1 =
      sys.sprung_mass * (4.0 * s.v_s / dt + s.a_s) - sys.stiffness * d0 + sys.damping * u0;
  const double r2 = sys.wheel_mass * (4.0 * s.v_w / dt + s.a_w) + weight + sys.stiffness * d0 -
                    sys.damping * u0 - a_force + c_c * (s.v_w + v_rail);
  const double det = m11 * m22 - beta * beta;
  return {(r1 * m22 + beta * r2) / det, (m11 * r2 + beta * r1) / det};
}

TwoMassState advanced(const TwoMassState& s, double dt, double ds, double dw) {
  TwoMassState n;
  n.z_s = s.z_s + ds;
  n.z_w = s.z_w + dw;
  n.v_s = 2.0 * ds / dt - s.v_s;
  n.v_w = 2.0 * dw / dt - s.v_w;
  n.a_s = 4.0 * (ds - dt * s.v_s) / (dt * dt) - s.a_s;
  n.a_w = 4.0 * (dw - dt * s.v_w) / (dt * dt) - s.a_w;
  return n;
}

}  // namespace

StepResult trapezoidal_step(const TwoMassSystem& sys, const TwoMassState& now, double fz,
                            double stiffness, const StepSettings& st,
                            const std::function<double(double, double)>& contact) {
  StepResult out;
  const double dt = st.dt;
  // The force model F ≈ f_ref + k·(z_w − z_ref) through the latest evaluation.
  double z_ref = now.z_w, f_ref = fz, k = std::max(stiffness, 0.0);
  for (int it = 0;; ++it) {
    const double a_force = f_ref - k * (z_ref - now.z_w);  // the model at Δ_w = 0
    // The damper acts while the wheel is in contact (judged at the start of the step).
    const double c_c = fz > 0.0 ? sys.contact_damping : 0.0;
    const auto [ds, dw] = increments(sys, now, dt, a_force, k, c_c, st.rail_velocity);
    TwoMassState next = advanced(now, dt, ds, dw);
    const double f = contact(next.z_w, next.v_w);
    ++out.solves;
    const double predicted = a_force + k * dw;
    out.next = next;
    out.fz = f;
    out.stiffness = k;
    if (std::abs(f - predicted) <= st.force_tolerance) {
      // The Newmark accelerations met the linear model; with the model within tolerance of the
      // solved force the state stands as it is.
      return out;
    }
    if (it + 1 >= st.max_iterations) {
      out.converged = false;
      set_accelerations(sys, f, st.rail_velocity, out.next);  // balanced with the solved force
      return out;
    }
    // Secant through the last two evaluations (a contact that opens gives k → 0).
    const double dz = next.z_w - z_ref;
    if (std::abs(dz) > 1e-12) k = std::max((f - f_ref) / dz, 0.0);
    z_ref = next.z_w;
    f_ref = f;
  }
}

}  // namespace rollcontact::dynamics
