#pragma once
// The non-Hertzian wheel/rail-like benchmark patch shared by the benchmark programs.
//
// Undeformed distance IBASE=2: a tabulated lateral profile p(y) plus x²/(2·R) with R = 460 mm
// (wheel radius). The profile has different curvatures on the two sides of the contact and a
// cubic term, so the contact is not an ellipse. Grids of 71×81 … 575×647 elements of 0.1 mm:
// a patch of scale s (s = 1, 2, 4, 8) is the scale-1 patch stretched by s in x and y
// (h_s(x, y) = s²·h_1(x/s, y/s), approach s²·pen_1), so about 54 % of every grid is in contact.

#include <cmath>

#include "rollcontact/model/patch_problem.hpp"

namespace rollcontact::bench {

inline double profile_scale1(double y) {
  // [mm] → [mm]; a worn (conformal) profile pair: relative lateral radii 700 mm (y < 0) and
  // 1100 mm (y > 0) plus cubic flank terms, so that the patch is neither elliptic nor symmetric.
  return y < 0.0 ? y * y / 1400.0 - 2.0e-5 * y * y * y : y * y / 2200.0 + 4.0e-5 * y * y * y;
}

inline model::PatchProblem wheel_rail_patch(int mx, int my, double scale) {
  model::PatchProblem p;
  p.normal.kind = model::NormalLoadKind::Approach;
  p.solver.max_inner_iterations = 999;
  p.solver.tolerance = 1e-5;
  p.bodies.body1 = p.bodies.body2 = {0.28, 82000.0};
  p.normal.approach_mm = 0.017 * scale * scale;  // ≈ 3.1k of 5.75k elements in contact at s = 1
  p.potential.ipotcn = 1;
  p.potential.mx = mx;
  p.potential.my = my;
  const double dx = 0.1, dy = 0.1;
  p.potential.values = {-0.5 * mx * dx, -0.5 * my * dy, dx, dy};
  model::UndeformedDistance& g = p.gap;
  g.ibase = 2;
  g.iplan = 1;
  const int nn = 2 * my + 1;
  g.y1 = -0.5 * my * dy - 0.05;
  g.dy1 = (my * dy + 0.1) / (nn - 1);
  g.xm = 0.0;
  g.rm = 460.0;
  g.coeffs.resize(static_cast<std::size_t>(nn));
  for (int k = 0; k < nn; ++k) {
    const double y = g.y1 + k * g.dy1;
    g.coeffs[static_cast<std::size_t>(k)] = scale * scale * profile_scale1(y / scale);
  }
  return p;
}

}  // namespace rollcontact::bench
