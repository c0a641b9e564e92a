#pragma once
// Values that reports and JSON derive from a CaseRecord and its Solution in the same way as
// CONTACT: effective kinematics after the silent adjustments (spec/physics.md §14), the friction
// coefficient used to scale forces, and the creepages/shifts with solved unknowns filled in.

#include "format/inp/case_record.hpp"
#include "rollcontact/solution.hpp"

namespace rollcontact::format {

/// Rolling direction, step, velocity and time step as the solver uses them.
struct EffectiveKinematics {
  double chi = 0.0;    ///< [rad]
  double dq = 1.0;     ///< [mm]
  double veloc = 1.0;  ///< [mm/s]
  double dt = 1.0;     ///< [s]
};

/// χ, δq, V and δt as the solver used them (physics.md §14 applied once, in
/// tangential/kinematics.cpp, and carried in Solution::kinematics).
EffectiveKinematics effective_kinematics(const Solution& solution);

/// Static friction coefficient mu_s that scales relative forces (FX/FSTAT/FN): FSTAT for
/// Coulomb, the zero-slip value FKIN + P1 + P3 for the falling laws L=2..4, FREF for L=6.
double static_friction(const Friction& friction);

/// Creepages (T=2,3) or shifts (T=1) with solved unknowns (F=1: x, F=2: x and y) taken from the
/// solution and prescribed ones from the problem.
struct EffectiveCreepages {
  double x = 0.0, y = 0.0, phi = 0.0;
};
EffectiveCreepages effective_creepages(const CaseRecord& problem, const Solution& solution);

/// As effective_creepages, with solved components that are negligible against the other one
/// (|x| < |y| EPS and vice versa) set to 0 as CONTACT prints them.
EffectiveCreepages printed_creepages(const CaseRecord& problem, const Solution& solution);

/// Approach [mm]: prescribed (N=0) or solved (N=1).
double effective_approach(const CaseRecord& problem, const Solution& solution);

/// True when the M=4 interfacial layer has an active plasticity limit (0 < TAU_C0 <= 1e10).
bool uses_plasticity(const CaseRecord& problem);

}  // namespace rollcontact::format
