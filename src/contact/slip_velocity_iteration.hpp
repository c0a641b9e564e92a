#pragma once
// Velocity-dependent friction (spec/physics.md §10.2–10.3): the coefficient of each element
// depends on its slip velocity s_a = |S|/δt, which the tangential solution determines. An outer
// fixed point alternates μ(s_a) (with friction memory) and the tangential solve with that μ per
// element, until the slip velocities settle. The tangential solvers themselves only ever see
// the traction bound g = μ·p_n.

#include <functional>
#include <string>
#include <vector>

#include "physics/friction_law.hpp"
#include "rollcontact/grid.hpp"
#include "rollcontact/model/friction.hpp"
#include "rollcontact/solution.hpp"
#include "tangential/tangential_system.hpp"

namespace rollcontact::contact {

using Field = std::vector<double>;

/// Friction memory of physics.md §10.2 for one field of slip velocities.
struct FrictionMemoryInput {
  const Grid* grid = nullptr;
  const std::vector<char>* contact = nullptr;  ///< 1 for elements in contact
  const physics::FrictionLaw* law = nullptr;
  double memory_distance_mm = 0.0;       ///< d_c (MEMDST); ≤ 1e-9: no memory
  double memory_floor_speed_mm_s = 0.0;  ///< s₀ (MEM_S0)
  double dt_s = 1.0;                     ///< time step δt [s]
  bool steady = false;                   ///< steady rolling: μ′ is the upstream neighbour's μ
  double chi_rad = 0.0;                  ///< rolling direction (steady rolling)
  /// Shifts and transient rolling: μ of the previous time per element (empty, or negative
  /// entries: μ_static).
  const Field* previous_mu = nullptr;
  /// μ_s per element that memory relaxes towards (temperature-dependent friction: μ(T) of each
  /// element); nullptr: the law's μ(s_a) at the element's slip velocity.
  const Field* target_mu = nullptr;
};

/// μ per element (μ_static outside the contact) and μ′, the value it relaxed from.
struct FrictionField {
  Field mu, mu_prime;
};

/// μ_I = θ·μ′_I + (1 − θ)·μ(s_a,I) with θ = d_c/(d_c + δt·max(s_a, s₀)). In steady rolling μ′ is
/// μ of the upstream neighbour (μ_static at the leading edge), found by sweeping against the
/// rolling direction; otherwise the previous-time field.
FrictionField friction_with_memory(const FrictionMemoryInput& in, const Field& slip_speed_mm_s);

struct SlipVelocitySettings {
  double relaxation = 1.0;  ///< ω_slp (OMGSLP)
  int max_passes = 90;      ///< max(1, MAXIN − 10)
};

/// What a fixed point of solution-dependent friction (slip velocity here, temperature in
/// temperature_iteration.hpp) gives: its last tangential solution and how it got there.
struct FrictionIterationOutcome {
  tangential::TangentialResult tangential;  ///< the last pass's solution
  Field mu;                                 ///< μ per element used in it
  int passes = 0;
  bool converged = false;
  std::string message;             ///< why not converged
  std::vector<std::string> trace;  ///< one line per pass, as CONTACT's "Vel-dep" lines
};

using SlipVelocityOutcome = FrictionIterationOutcome;

/// Keeps pass `pass` (its μ and tangential solution) as the outcome's last; false when that
/// tangential solve did not converge, whose message then becomes the outcome's.
bool record_pass(FrictionIterationOutcome& out, int pass, Field mu,
                 tangential::TangentialResult tangential);

/// Solves the tangential problem for the friction field `mu` (bound μ_I·p_n,I).
using TangentialSolveWithFriction = std::function<tangential::TangentialResult(const Field& mu)>;

/// The fixed point of physics.md §10.3, started from `initial_speed_mm_s`: each pass evaluates
/// μ with memory, solves, takes s_a = |S|/δt in contact, over-relaxes it by ω_slp in slipping
/// elements whose μ exceeds μ′ (from the 2nd pass), and stops when ‖Δs_a‖ ≤ 0.001·‖s_a‖ or
/// nothing slips. ω_slp is reduced by 0.8 every 20 passes while the division still changes.
SlipVelocityOutcome solve_with_slip_velocity(const FrictionMemoryInput& memory,
                                             const Field& initial_speed_mm_s,
                                             const SlipVelocitySettings& settings,
                                             const TangentialSolveWithFriction& solve);

}  // namespace rollcontact::contact
