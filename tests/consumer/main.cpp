// Solves one Hertzian contact through the installed public API and checks it against Hertz:
// steel sphere on steel, contact radius a = 3 mm, FN = 10 kN. Exit status 0 when the approach and
// the peak pressure agree with Hertz to 2 % (the 41×41 grid resolves both to about 1 %).

#include <cmath>
#include <cstdio>
#include <numbers>

#include "rollcontact/solve.hpp"

int main() {
  using namespace rollcontact;
  const double a = 3.0, fn = 1.0e4, g = 82000.0, nu = 0.28;

  model::PatchProblem p;
  p.normal.kind = model::NormalLoadKind::Force;
  p.normal.force_N = fn;
  p.bodies.body1 = p.bodies.body2 = {nu, g};
  p.potential.ipotcn = -3;  // Hertzian potential contact from the semi-axes [mm]
  p.potential.mx = p.potential.my = 41;
  p.potential.values = {a, a, 1.1, 0.0};

  PatchSolver solver;
  const Solution s = solver.solve(p);
  if (!s.solver.converged) {
    std::printf("not converged: %s\n", s.solver.message.c_str());
    return 1;
  }
  // Hertz (Johnson §4.2): E* = E/(2(1 − ν²)) for two equal bodies, δ = 3FN/(4E*a),
  // p0 = 3FN/(2πa²).
  const double e_star = 2.0 * g * (1.0 + nu) / (2.0 * (1.0 - nu * nu));
  const double pen = 3.0 * fn / (4.0 * e_star * a);
  const double p0 = 3.0 * fn / (2.0 * std::numbers::pi * a * a);
  const double pen_err = std::abs(s.totals.pen / pen - 1.0);
  const double p0_err = std::abs(s.totals.pmax / p0 - 1.0);
  std::printf("approach %.5e mm (Hertz %.5e, %.2f %%), pmax %.2f N/mm2 (Hertz %.2f, %.2f %%)\n",
              s.totals.pen, pen, 100.0 * pen_err, s.totals.pmax, p0, 100.0 * p0_err);
  return pen_err < 0.02 && p0_err < 0.02 ? 0 : 1;
}
