#pragma once
// Temperature-dependent friction (CONTACT's L = 6, spec/physics.md §10.1, §10.3, spec-additions
// B2): the coefficient of each element follows the surface temperature of body 1, which the
// frictional heat of the tangential solution raises (§15). An outer fixed point alternates μ(T)
// (with friction memory, §10.2) and the tangential solve with that μ per element until the
// temperatures settle — the structure of the slip-velocity iteration of L = 2–4, with the
// temperature in place of the slip velocity. The tangential solvers only see g = μ·p_n.

#include <functional>
#include <string>
#include <vector>

#include "contact/slip_velocity_iteration.hpp"

namespace rollcontact::contact {

struct TemperatureIterationSettings {
  /// ω (OMGSLP): from the 2nd pass T ← T + ω·(T_new − T) in the contact; reduced by 0.8 every
  /// `reduction_period` passes while the element division still changes.
  double relaxation = 1.0;
  int max_passes = 90;        ///< max(1, MAXIN − 10)
  double tolerance = 1e-4;    ///< ‖ΔT‖ ≤ tolerance·‖T‖ (2-norms over the contact) [-]
  int reduction_period = 15;  ///< passes between reductions of ω
};

struct TemperatureIterationOutcome : FrictionIterationOutcome {
  Field temperature_C;  ///< body 1's surface temperature the last pass produced
};

/// Body 1's surface temperature per element [°C] that a tangential solution produces.
using SurfaceTemperatureOf = std::function<Field(const tangential::TangentialResult& tangential)>;

/// The fixed point started from `initial_temperature_C`: each pass takes μ_s = μ(T) of the law
/// (memory->law, a temperature-dependent law) per contact element, relaxes it with memory
/// (θ from the slip velocities of the previous pass), solves, and computes the new temperature.
TemperatureIterationOutcome solve_with_temperature(const FrictionMemoryInput& memory,
                                                   const Field& initial_temperature_C,
                                                   const TemperatureIterationSettings& settings,
                                                   const TangentialSolveWithFriction& solve,
                                                   const SurfaceTemperatureOf& temperature_of);

}  // namespace rollcontact::contact
