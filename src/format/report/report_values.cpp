#include "format/report/report_values.hpp"

#include <cmath>
#include <numbers>

namespace rollcontact::format {

EffectiveKinematics effective_kinematics(const CaseRecord& problem, const Solution& solution) {
  const auto& dg = problem.digits;
  const auto& kin = problem.kinematics;
  EffectiveKinematics e;
  if (dg.t <= 1) return e;  // shifts and normal problems: chi=0, dq=1 mm, V=1 mm/s, dt=1 s
  e.chi = kin.chi;
  e.dq = kin.dq;
  e.veloc = kin.veloc;
  const bool simplified = dg.m == 2 || dg.m == 3 || (dg.m >= 5 && dg.m <= 7);
  // Steady rolling: the step is one element whatever the solver (tangential/kinematics.cpp).
  if (dg.t == 3) e.dq = solution.grid.dx;
  const bool grid_bound = dg.t == 3 && (simplified || dg.g != 2 || dg.m == 4);
  if (grid_bound) {
    // Steady-state solvers march over grid columns: the rolling direction is +x or -x.
    const double pi = std::numbers::pi;
    const double tol = simplified ? 1e-12 : 0.01;
    const double c = std::remainder(e.chi, 2.0 * pi);
    const bool along_x = std::fabs(c) <= tol || std::fabs(std::fabs(c) - pi) <= tol;
    if (!along_x) e.chi = 0.0;
  }
  if (dg.m == 1 && dg.t == 3) e.chi = 0.0;
  e.dt = e.veloc > 0.0 ? e.dq / e.veloc : 1.0;
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
