#pragma once
// Builders of model problems shared by the solver tests and benchmarks.

#include "rollcontact/model/patch_problem.hpp"

namespace rollcontact::test {

/// A Hertzian patch (potential contact from the semi-axes a, b [mm]) with normal force `fn` [N],
/// identical bodies (G [N/mm²], ν), grid mx × my over `scale` times the Hertz ellipse, Coulomb
/// friction μ = 0.3, no tangential problem, tolerance 1e-8.
inline model::PatchProblem hertz_problem(double a, double b, double fn, double g, double nu, int mx,
                                         int my, double scale) {
  model::PatchProblem p;
  p.normal.kind = model::NormalLoadKind::Force;
  p.normal.force_N = fn;
  p.solver.tolerance = 1e-8;
  p.bodies.body1 = p.bodies.body2 = {nu, g};
  p.potential.ipotcn = -3;
  p.potential.mx = mx;
  p.potential.my = my;
  p.potential.values = {a, b, scale, 0.0};
  p.friction = {0.3, 0.3};
  return p;
}

/// The tangential problem of CONTACT's T digit: 0 none, 1 shift, 2 transient, 3 steady rolling.
inline model::TangentialKind tangential_kind(int t) {
  constexpr model::TangentialKind kinds[] = {
      model::TangentialKind::None, model::TangentialKind::Shift,
      model::TangentialKind::TransientRolling, model::TangentialKind::SteadyRolling};
  return kinds[t];
}

}  // namespace rollcontact::test
