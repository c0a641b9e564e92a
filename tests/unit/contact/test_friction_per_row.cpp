// Variable friction V=3 (module 3, experimental in CONTACT): one Coulomb coefficient per grid
// row. Checked: equal rows are V=0 exactly; with two coefficients every element keeps to its
// row's bound and the slipping ones sit on it, and the creep force lies between the two
// uniform cases.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "rollcontact/errors.hpp"
#include "rollcontact/solve.hpp"
#include "support/hertz_problem.hpp"

namespace rollcontact {
namespace {

model::PatchProblem rolling(double mu) {
  model::PatchProblem p = test::hertz_problem(6.0, 4.0, 50000.0, 82000.0, 0.28, 30, 24, 1.1);
  p.friction = {mu, mu};
  p.tangential.kind = model::TangentialKind::SteadyRolling;
  p.tangential.creepage = {-0.002, 0.0, 0.0};
  p.rolling.velocity_mm_per_s = 1000.0;
  p.rolling.step_mm = 6.0 * 2.2 / 30.0;
  return p;
}

TEST(FrictionPerRow, EqualRowsAreOneCoefficient) {
  model::PatchProblem p = rolling(0.3);
  const Solution plain = PatchSolver().solve(p);
  p.friction.row_coefficients.assign(24, 0.3);
  const Solution rows = PatchSolver().solve(p);
  ASSERT_TRUE(plain.solver.converged && rows.solver.converged);
  EXPECT_EQ(rows.totals.fx, plain.totals.fx);
  EXPECT_EQ(rows.totals.fy, plain.totals.fy);
}

TEST(FrictionPerRow, EachRowKeepsToItsOwnBound) {
  model::PatchProblem p = rolling(0.3);
  p.friction.row_coefficients.assign(24, 0.3);
  for (int iy = 0; iy < 12; ++iy) p.friction.row_coefficients[iy] = 0.15;  // one side wet
  const Solution s = PatchSolver().solve(p);
  ASSERT_TRUE(s.solver.converged) << s.solver.message;
  int slipping_low = 0;
  for (int iy = 0; iy < s.grid.my; ++iy)
    for (int ix = 0; ix < s.grid.mx; ++ix) {
      const std::size_t i = s.grid.index(ix, iy);
      if (!(s.pn[i] > 0.0)) continue;
      const double bound = p.friction.row_coefficients[iy] * s.pn[i];
      const double t = std::hypot(s.px[i], s.py[i]);
      EXPECT_LE(t, bound * (1.0 + 1e-8) + 1e-9) << ix << ", " << iy;
      if (s.state[i] == ElementState::Slip) {
        EXPECT_NEAR(t, bound, 1e-6 * bound + 1e-9);
        slipping_low += iy < 12 ? 1 : 0;
      }
    }
  EXPECT_GT(slipping_low, 10);
  const Solution low = PatchSolver().solve(rolling(0.15)), high = PatchSolver().solve(rolling(0.3));
  EXPECT_GT(std::abs(s.totals.fx), std::abs(low.totals.fx));
  EXPECT_LT(std::abs(s.totals.fx), std::abs(high.totals.fx));
}

TEST(FrictionPerRow, RowsMustMatchTheGrid) {
  model::PatchProblem p = rolling(0.3);
  p.friction.row_coefficients.assign(10, 0.3);
  EXPECT_THROW((void)PatchSolver().solve(p), ProblemError);
}

}  // namespace
}  // namespace rollcontact
