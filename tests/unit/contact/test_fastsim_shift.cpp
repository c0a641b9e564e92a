// Shifts (T=1) with Kalker's simplified theory (M=2, 3): no particle moves, so each element
// starts from its own previous displacement, u = u_prev − W, p = u/L, and slips where |p| would
// exceed μ·p_n (Cattaneo's problem in the simplified theory). Checked element by element from
// rest, and over a sequence: zero increments keep the tractions, a second shift adds to them.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "rollcontact/solve.hpp"
#include "support/hertz_problem.hpp"

namespace rollcontact {
namespace {

model::PatchProblem fastsim_shift(double shift_x_mm) {
  model::PatchProblem p = test::hertz_problem(6.0, 4.0, 50000.0, 82000.0, 0.28, 40, 28, 1.1);
  p.bodies.compliance = model::TangentialCompliance::FastsimThreeFlexibilities;
  p.tangential.kind = model::TangentialKind::Shift;
  p.tangential.creepage = {shift_x_mm, 0.0, 0.0};
  return p;
}

TEST(FastsimShift, FromRestEachElementTakesTheShiftOverItsFlexibility) {
  PatchSolver solver;
  model::PatchProblem p = fastsim_shift(0.004);
  p.sequence.continue_previous = false;
  const Solution s = solver.solve(p);
  ASSERT_TRUE(s.solver.converged) << s.solver.message;
  ASSERT_TRUE(s.simplified.present);
  const double l = s.simplified.flx1 / s.simplified.k_eff;  // L/k in x [mm³/N]
  double fx = 0.0;
  int slipping = 0, sticking = 0;
  for (std::size_t i = 0; i < s.grid.size(); ++i) {
    if (!(s.pn[i] > 0.0)) continue;
    const double bound = 0.3 * s.pn[i], trial = 0.004 / l;
    fx -= std::min(trial, bound) * s.grid.element_area();
    (trial > bound ? slipping : sticking) += 1;
  }
  EXPECT_NEAR(s.totals.fx, fx, 1e-9 * s.totals.fn);
  EXPECT_GT(slipping, 10);  // partial slip at the edge, stick inside: a test of both
  EXPECT_GT(sticking, 10);
  EXPECT_LT(std::abs(s.totals.fx), 0.3 * s.totals.fn);
}

TEST(FastsimShift, ZeroIncrementsKeepTheTractionsFurtherShiftsAdd) {
  PatchSolver solver;
  model::PatchProblem p = fastsim_shift(0.004);
  p.sequence.continue_previous = false;
  const Solution first = solver.solve(p);
  p.sequence.continue_previous = true;
  p.tangential.creepage = {0.0, 0.0, 0.0};
  const Solution kept = solver.solve(p);
  // (the normal problem is solved again each case: slipping elements follow p_n to its 1e-8)
  EXPECT_NEAR(kept.totals.fx, first.totals.fx, 1e-9 * first.totals.fn);
  p.tangential.creepage = {0.004, 0.0, 0.0};
  const Solution more = solver.solve(p);
  // Twice the shift from rest, element by element: the same as one shift of 0.008 mm.
  PatchSolver fresh;
  model::PatchProblem twice = fastsim_shift(0.008);
  twice.sequence.continue_previous = false;
  const Solution once = fresh.solve(twice);
  EXPECT_NEAR(more.totals.fx, once.totals.fx, 1e-9 * once.totals.fn);
  EXPECT_LT(more.totals.fx, 1.5 * first.totals.fx);  // more (negative) force than one shift
  // Shifting back by the same amount unloads elastically only where it stuck: hysteresis.
  p.tangential.creepage = {-0.008, 0.0, 0.0};
  const Solution back = solver.solve(p);
  EXPECT_GT(back.totals.fx, 0.0);
}

}  // namespace
}  // namespace rollcontact
