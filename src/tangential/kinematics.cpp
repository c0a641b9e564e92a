#include "tangential/kinematics.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

namespace rollcontact::tangential {

TangentialSolverKind select_solver(const model::PatchProblem& problem) {
  using model::TangentialKind;
  const bool convex = problem.solver.tangential_method == model::TangentialMethod::ConvexGS;
  switch (problem.tangential.kind) {
    case TangentialKind::None:
      return TangentialSolverKind::None;
    case TangentialKind::SteadyRolling:
      return convex ? TangentialSolverKind::ConvexGS : TangentialSolverKind::SteadyGS;
    default:
      return convex ? TangentialSolverKind::ConvexGS : TangentialSolverKind::TangCG;
  }
}

EffectiveKinematics effective_kinematics(const model::PatchProblem& problem, const Grid& grid,
                                         std::vector<std::string>* warnings) {
  const model::Rolling& k = problem.rolling;
  const model::TangentialKind kind = problem.tangential.kind;
  EffectiveKinematics e;
  if (kind == model::TangentialKind::None || kind == model::TangentialKind::Shift)
    return e;  // χ = 0, δq = 1 mm, V = 1 mm/s, δt = 1 s
  e.chi = k.direction_rad;
  e.dq = k.step_mm;
  e.veloc = k.velocity_mm_per_s;
  const bool simplified = problem.bodies.compliance != model::TangentialCompliance::ExactHalfSpace;
  if (kind == model::TangentialKind::SteadyRolling) {
    // Steady rolling is discretised with the step of one element whatever the solver: the
    // time derivative of u is a difference over δq, and δq = δx is the finest the grid
    // resolves (CONTACT does the same, also for ConvexGS: issue 18 item 5, decisions.md).
    if (warnings && std::abs(e.dq - grid.dx) > 0.01 * grid.dx)
      warnings->push_back(fmt::format("Using DQ = DX = {:.4g} instead of {:.4g}", grid.dx, e.dq));
    e.dq = grid.dx;
  }
  if (kind == model::TangentialKind::SteadyRolling &&
      (select_solver(problem) == TangentialSolverKind::SteadyGS || simplified)) {
    // The grid-marching solvers need χ = 0 or π: the previous-time field is then the current
    // one shifted by one element along a row.
    const bool near_zero = std::abs(std::remainder(e.chi, 2.0 * std::numbers::pi)) < 0.01;
    const bool near_pi =
        std::abs(std::remainder(e.chi - std::numbers::pi, 2.0 * std::numbers::pi)) < 0.01;
    if (!near_zero && !near_pi) e.chi = 0.0;
  }
  // Viscoelastic bodies relax along +x (spec-additions §B5): model::validate refuses χ ≠ 0.
  if (kind == model::TangentialKind::SteadyRolling && problem.bodies.viscoelastic) e.chi = 0.0;
  e.dt = e.dq / e.veloc;
  return e;
}

RigidShift rigid_shift(const Grid& grid, const model::PatchProblem& problem,
                       const EffectiveKinematics& kin, double cksi, double ceta, double cphi) {
  const model::TangentialLoading& k = problem.tangential;
  const bool rolling = k.kind == model::TangentialKind::TransientRolling ||
                       k.kind == model::TangentialKind::SteadyRolling;
  const double facphi = problem.rolling.spin_offset_factor;
  RigidShift w;
  w.wx.assign(grid.size(), 0.0);
  w.wy.assign(grid.size(), 0.0);
  // For rolling the spin term is evaluated half-way (f_φ = FACPHI) along the step.
  const double off_x = rolling ? std::cos(kin.chi) * kin.dq * facphi : 0.0;
  const double off_y = rolling ? std::sin(kin.chi) * kin.dq * facphi : 0.0;
  const double step = rolling ? kin.dq : 1.0;  // shifts: the inputs are shifts already
  const bool extra = !k.extra_slip.empty() && k.extra_slip.size() >= 2 * grid.size();
  for (int iy = 0; iy < grid.my; ++iy) {
    const double y = grid.y_centre(iy) - k.spin_centre_y_mm + off_y;
    for (int ix = 0; ix < grid.mx; ++ix) {
      const double x = grid.x_centre(ix) - k.spin_centre_x_mm + off_x;
      const std::size_t i = grid.index(ix, iy);
      double wx = k.spin_terms == model::SpinInRigidSlip::LateralOnly ? cksi : cksi - cphi * y;
      double wy = k.spin_terms == model::SpinInRigidSlip::LongitudinalOnly ? ceta : ceta + cphi * x;
      if (extra) {
        wx += k.extra_slip[2 * i];
        wy += k.extra_slip[2 * i + 1];
      }
      w.wx[i] = step * wx;
      w.wy[i] = step * wy;
    }
  }
  return w;
}

}  // namespace rollcontact::tangential
