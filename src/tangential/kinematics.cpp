#include "tangential/kinematics.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

namespace rollcontact::tangential {

TangentialSolverKind select_solver(const ControlDigits& d) {
  if (d.t == 0) return TangentialSolverKind::None;
  if (d.t == 3) return d.g == 2 ? TangentialSolverKind::ConvexGS : TangentialSolverKind::SteadyGS;
  return d.g == 2 ? TangentialSolverKind::ConvexGS : TangentialSolverKind::TangCG;
}

EffectiveKinematics effective_kinematics(const Problem& problem, const Grid& grid,
                                         std::vector<std::string>* warnings) {
  const ControlDigits& d = problem.digits;
  const Kinematics& k = problem.kinematics;
  EffectiveKinematics e;
  if (d.t <= 1) return e;  // χ = 0, δq = 1 mm, V = 1 mm/s, δt = 1 s
  e.chi = k.chi;
  e.dq = k.dq;
  e.veloc = k.veloc;
  const bool steady_grid_solver =
      d.t == 3 && (select_solver(d) == TangentialSolverKind::SteadyGS || d.m == 4 || d.m == 2 ||
                   d.m == 3 || (d.m >= 5 && d.m <= 7));
  if (steady_grid_solver || (d.t == 3 && d.m == 1)) {
    // Steady rolling on a contact-fixed grid needs χ = 0 or π and δq = δx: the previous-time
    // field is then the current one shifted by one element.
    const bool near_zero = std::abs(std::remainder(e.chi, 2.0 * std::numbers::pi)) < 0.01;
    const bool near_pi =
        std::abs(std::remainder(e.chi - std::numbers::pi, 2.0 * std::numbers::pi)) < 0.01;
    if (!near_zero && !near_pi) e.chi = 0.0;
    if (d.m != 1) {
      if (warnings && std::abs(e.dq - grid.dx) > 0.01 * grid.dx)
        warnings->push_back(fmt::format("Using DQ = DX = {:.4g} instead of {:.4g}", grid.dx, e.dq));
      e.dq = grid.dx;
    }
  }
  e.dt = e.dq / e.veloc;
  return e;
}

RigidShift rigid_shift(const Grid& grid, const Problem& problem, const EffectiveKinematics& kin,
                       double cksi, double ceta, double cphi) {
  const Kinematics& k = problem.kinematics;
  const int t = problem.digits.t;
  RigidShift w;
  w.wx.assign(grid.size(), 0.0);
  w.wy.assign(grid.size(), 0.0);
  // For rolling the spin term is evaluated half-way (f_φ = FACPHI) along the step.
  const double off_x = t >= 2 ? std::cos(kin.chi) * kin.dq * k.facphi : 0.0;
  const double off_y = t >= 2 ? std::sin(kin.chi) * kin.dq * k.facphi : 0.0;
  const double step = t >= 2 ? kin.dq : 1.0;  // T=1: the inputs are shifts already
  const bool spin_in_x = problem.digits.e != 3, spin_in_y = problem.digits.e != 2;
  const bool extra = problem.digits.e == 9 && k.extra_slip.size() >= 2 * grid.size();
  for (int iy = 0; iy < grid.my; ++iy) {
    const double y = grid.y_centre(iy) - k.spinyo + off_y;
    for (int ix = 0; ix < grid.mx; ++ix) {
      const double x = grid.x_centre(ix) - k.spinxo + off_x;
      const std::size_t i = grid.index(ix, iy);
      double wx = cksi - (spin_in_x ? cphi * y : 0.0);
      double wy = ceta + (spin_in_y ? cphi * x : 0.0);
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
