// SDEC (B=4, IPOTCN=−6) through the patch solver: with equal lateral semi-axes it is the
// elliptic Hertz pressure (B=2), and the prescribed force is the case's FN.

#include <gtest/gtest.h>

#include "rollcontact/solve.hpp"
#include "support/hertz_problem.hpp"

namespace rollcontact {
namespace {

model::PatchProblem rolling(model::PatchProblem p) {
  p.tangential.kind = model::TangentialKind::SteadyRolling;
  p.tangential.creepage.lateral = -6.25e-4;
  p.tangential.creepage.spin_rad_per_mm = 6.25e-4;
  p.rolling.velocity_mm_per_s = 30000.0;
  p.rolling.step_mm = 0.4;
  p.solver.tolerance = 1e-9;
  return p;
}

model::PatchProblem sdec(double b_neg, double b_pos) {
  model::PatchProblem p = test::hertz_problem(8.0, 4.0, 82000.0, 82000.0, 0.28, 44, 44, 1.1);
  p.potential.ipotcn = -6;
  p.potential.values = {8.0, b_neg, b_pos, 1.1};
  p.normal.pressure = model::PressureModel::Sdec;
  return rolling(p);
}

TEST(Sdec, EqualHalvesGiveTheEllipticHertzCase) {
  model::PatchProblem elliptic = test::hertz_problem(8.0, 4.0, 82000.0, 82000.0, 0.28, 44, 44, 1.1);
  elliptic.normal.pressure = model::PressureModel::EllipticHertzian;
  const Solution e = PatchSolver().solve(rolling(elliptic));
  const Solution s = PatchSolver().solve(sdec(4.0, 4.0));
  ASSERT_TRUE(s.solver.converged) << s.solver.message;
  EXPECT_EQ(s.totals.fn, 82000.0);
  EXPECT_NEAR(s.totals.fx, e.totals.fx, 1e-8 * 0.3 * 82000.0);
  EXPECT_NEAR(s.totals.fy, e.totals.fy, 1e-8 * 0.3 * 82000.0);
  for (std::size_t i = 0; i < s.pn.size(); ++i) EXPECT_NEAR(s.pn[i], e.pn[i], 1e-9) << i;
}

TEST(Sdec, UnequalHalvesShiftTheLoadSideways) {
  // b_pos > b_neg: the longer half lies at y > 0 and carries 3/4 of the load.
  const Solution s = PatchSolver().solve(sdec(2.0, 6.0));
  ASSERT_TRUE(s.solver.converged) << s.solver.message;
  double sum = 0.0, moment_y = 0.0;
  for (int iy = 0; iy < s.grid.my; ++iy)
    for (int ix = 0; ix < s.grid.mx; ++ix) {
      const double v = s.pn[s.grid.index(ix, iy)];
      sum += v;
      moment_y += v * s.grid.y_centre(iy);
    }
  // Integrated over x each half carries a line load ∝ 1 − t², t = (y − y₀)/b_±, so its load is
  // ∝ b_± and its centroid lies 3b_±/8 from y₀ = −2 mm: the whole centroid at
  // y₀ + (3/8)(b_pos² − b_neg²)/(b_pos + b_neg) = −0.5 mm.
  const double centroid = moment_y / sum;
  EXPECT_NEAR(centroid, -0.5, 0.01);
}

}  // namespace
}  // namespace rollcontact
