#include "format/report/report_values.hpp"

#include <cmath>

namespace rollcontact::format {

EffectiveKinematics effective_kinematics(const Solution& solution) {
  const rollcontact::EffectiveKinematics& k = solution.kinematics;
  EffectiveKinematics e;
  e.chi = k.chi;
  e.dq = k.dq;
  e.veloc = k.veloc;
  e.dt = k.dt;
  return e;
}

double static_friction(const Friction& friction) {
  switch (friction.law) {
    case 2:
    case 3:
    case 4:
      return friction.fkin + friction.params[0] + friction.params[2];
    case 6:
      return friction.fkin;
    default:
      return friction.fstat;
  }
}

EffectiveCreepages effective_creepages(const CaseRecord& problem, const Solution& solution) {
  const auto& dg = problem.digits;
  const auto& kin = problem.kinematics;
  EffectiveCreepages c{kin.cksi, kin.ceta, kin.cphi};
  if (dg.t == 0) return {};
  const bool rolling = dg.t >= 2;
  if (dg.f >= 1) c.x = rolling ? solution.totals.creep_x : solution.totals.shift_x;
  if (dg.f >= 2) c.y = rolling ? solution.totals.creep_y : solution.totals.shift_y;
  return c;
}

EffectiveCreepages printed_creepages(const CaseRecord& problem, const Solution& solution) {
  EffectiveCreepages c = effective_creepages(problem, solution);
  const double eps = problem.solver.eps;
  const EffectiveCreepages raw = c;
  if (problem.digits.f >= 1 && std::fabs(raw.x) < std::fabs(raw.y * eps)) c.x = 0.0;
  if (problem.digits.f >= 2 && std::fabs(raw.y) < std::fabs(raw.x * eps)) c.y = 0.0;
  return c;
}

double effective_approach(const CaseRecord& problem, const Solution& solution) {
  return problem.digits.n == 0 ? problem.kinematics.pen : solution.totals.pen;
}

bool uses_plasticity(const CaseRecord& problem) {
  const double tau_c0 = problem.materials.model_params[2];
  return problem.digits.m == 4 && tau_c0 > 1e-10 && tau_c0 <= 1e10;
}

}  // namespace rollcontact::format
