#pragma once
// Builders of Hertzian test problems for solve().

#include "rollcontact/problem.hpp"

namespace rollcontact::test {

/// A Hertzian case (IPOTCN = −3: semi-axes a, b given) with normal force `fn` [N], identical
/// bodies (G [N/mm²], ν), grid mx × my over `scale` times the Hertz ellipse.
inline Problem hertz_problem(double a, double b, double fn, double g, double nu, int mx, int my,
                             double scale) {
  Problem p;
  p.digits.p = 2;
  p.digits.n = 1;
  p.digits.t = 0;
  p.digits.o = 1;
  p.solver.maxgs = 999;
  p.solver.maxin = 100;
  p.solver.maxnr = 30;
  p.solver.eps = 1e-8;
  p.kinematics.fn = fn;
  p.materials.poiss1 = p.materials.poiss2 = nu;
  p.materials.gg1 = p.materials.gg2 = g;
  p.potential.ipotcn = -3;
  p.potential.mx = mx;
  p.potential.my = my;
  p.potential.values = {a, b, scale, 0.0};
  p.friction.fstat = p.friction.fkin = 0.3;
  return p;
}

}  // namespace rollcontact::test
