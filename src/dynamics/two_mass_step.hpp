#pragma once
// One time step of the sprung mass on its suspension on the wheel, the wheel on the contact:
// the trapezoidal rule (Newmark, average acceleration — unconditionally stable, no numerical
// damping) with the contact force linearised about the latest evaluation and corrected by
// secant iterations until it agrees with the contact solved at the new height. Units: mm, N, s,
// masses in N·s²/mm; z downward.

#include <functional>

namespace rollcontact::dynamics {

struct TwoMassSystem {
  double sprung_mass = 10.0;  ///< M_s [N·s²/mm] (10 t)
  double wheel_mass = 0.35;   ///< m_w [N·s²/mm]
  double stiffness = 1150.0;  ///< k_p [N/mm]
  double damping = 2.5;       ///< c_p [N·s/mm]
  double gravity = 9810.0;    ///< [mm/s²]
  /// Viscous damping between wheel and rail [N·s/mm] (0: the elastic contact, undamped); it
  /// acts on the wheel's velocity relative to the rail's.
  double contact_damping = 0.0;
};

/// Positions z (down) [mm], velocities [mm/s], accelerations [mm/s²]. The spring is at its
/// static (preloaded) length when z_s = z_w: the preload carries the sprung mass's weight.
struct TwoMassState {
  double z_s = 0.0, v_s = 0.0, a_s = 0.0;
  double z_w = 0.0, v_w = 0.0, a_w = 0.0;
};

/// Accelerations of a state under contact force `fz` [N] (force on the rail, pushing the wheel
/// up) with the rail surface moving down at `v_rail` [mm/s]: M a = R(q, v).
void set_accelerations(const TwoMassSystem& sys, double fz, double v_rail, TwoMassState& s);

struct StepSettings {
  double dt = 2e-5;              ///< [s]
  double rail_velocity = 0.0;    ///< of the rail surface (down) at the step's end [mm/s]
  double force_tolerance = 1.0;  ///< [N]: |F(z) − linear prediction| that ends the iterations
  int max_iterations = 8;
};

struct StepResult {
  TwoMassState next;
  double fz = 0.0;         ///< contact force at the new state [N]
  double stiffness = 0.0;  ///< the secant dF/dz last used [N/mm] (the next step's first guess)
  int solves = 0;
  bool converged = true;
};

/// `contact(z_w, v_w)` solves the contact at wheel height z_w (velocity v_w) and returns F_z;
/// `fz` is the force at `now`, `stiffness` the first guess of dF/dz.
StepResult trapezoidal_step(const TwoMassSystem& sys, const TwoMassState& now, double fz,
                            double stiffness, const StepSettings& settings,
                            const std::function<double(double z_w, double v_w)>& contact);

}  // namespace rollcontact::dynamics
