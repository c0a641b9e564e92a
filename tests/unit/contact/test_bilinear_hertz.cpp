// Hertzian normal contact with bilinear traction elements (C=3, spec-additions.md §B7): the
// approach under a given force converges to Hertz's as the grid is refined. Measured errors
// (m = 15, 31, 63, 127): bilinear 1.9e-3, 3.4e-4, 1.1e-4, 2.6e-5; constant (C=2) 6.4e-4,
// 6.0e-5, 6.0e-5, 1.0e-5 — the hats, reaching a whole element past the last loaded centre,
// represent the square-root edge of the pressure less well for the approach (up to 6x at m = 31).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "rollcontact/solve.hpp"
#include "support/hertz_problem.hpp"

namespace rollcontact {
namespace {

/// |approach / Hertz's approach − 1| on an m × m grid over 1.2 times the ellipse a = 3, b = 2 mm.
double approach_error(model::TractionElements elements, int m) {
  model::PatchProblem p = test::hertz_problem(3.0, 2.0, 10000.0, 82000.0, 0.28, m, m, 1.2);
  p.bodies.traction_elements = elements;
  PatchSolver solver;
  const Solution s = solver.solve(p);
  EXPECT_TRUE(s.solver.converged);
  EXPECT_NEAR(s.totals.fn, 10000.0, 1e-6 * 10000.0);
  return std::abs(s.totals.pen / s.hertz.pen - 1.0);
}

TEST(BilinearHertz, ApproachConvergesToHertz) {
  double previous = 5e-3;
  for (int m : {15, 31, 63, 127}) {
    const double bilinear = approach_error(model::TractionElements::bilinear, m);
    const double constant = approach_error(model::TractionElements::piecewise_constant, m);
    std::printf("m = %d: approach error bilinear %.3e, constant %.3e\n", m, bilinear, constant);
    EXPECT_LT(bilinear, 0.4 * previous) << m;  // converges, at least like h^1.3
    EXPECT_LE(bilinear, 6.5 * constant) << m;
    previous = bilinear;
  }
}

}  // namespace
}  // namespace rollcontact
