// Starts of a patch's iterations along a sequence (model::SequenceLink) as the wheel/rail
// solver uses them: the normal iteration from the last solve's pressure, and a normal problem
// posed again unchanged (the full solve at the height of the vertical-force iteration's last
// normal estimate) answered without iterating.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "rollcontact/solve.hpp"
#include "support/hertz_problem.hpp"

namespace rollcontact {
namespace {

model::PatchProblem rolling_case() {
  model::PatchProblem p = test::hertz_problem(0.6, 1.0, 10.0, 82000.0, 0.28, 31, 41, 1.1);
  p.tangential.kind = test::tangential_kind(3);
  p.solver.tolerance = 1e-7;
  p.rolling.velocity_mm_per_s = 10000.0;
  p.rolling.step_mm = 0.6 * 2.2 / 31;
  p.tangential.creepage.longitudinal = 1.0e-5;
  p.tangential.creepage.spin_rad_per_mm = 1.0e-5;
  p.sequence.continue_previous = true;
  p.sequence.normal_from_previous = true;
  return p;
}

TEST(SequenceStarts, TheSameNormalProblemIsAnsweredWithoutIterating) {
  model::PatchProblem estimate = rolling_case();
  estimate.tangential.kind = model::TangentialKind::None;  // a normal-only estimate
  estimate.sequence.becomes_previous = false;
  PatchSolver solver;
  const Solution first = solver.solve(estimate);
  ASSERT_TRUE(first.solver.converged);
  EXPECT_GT(first.solver.normal_products, 0);
  const Solution full = solver.solve(rolling_case());
  ASSERT_TRUE(full.solver.converged) << full.solver.message;
  EXPECT_EQ(full.solver.normal_products, 0);
  EXPECT_EQ(full.pn, first.pn);
  EXPECT_EQ(full.totals.fn, first.totals.fn);
  EXPECT_GT(full.statistics.nslip, 0);  // and the tangential problem was solved on it

  // A different load is solved, from the last pressure: fewer products than from scratch.
  model::PatchProblem deeper = rolling_case();
  deeper.normal.force_N *= 1.05;
  const Solution warm = solver.solve(deeper);
  PatchSolver fresh;
  const Solution cold = fresh.solve(deeper);
  ASSERT_TRUE(warm.solver.converged && cold.solver.converged);
  EXPECT_GT(warm.solver.normal_products, 0);
  EXPECT_LT(warm.solver.normal_products, cold.solver.normal_products);
  EXPECT_NEAR(warm.totals.fn, cold.totals.fn, 1e-9 * cold.totals.fn);
  EXPECT_NEAR(warm.totals.pen, cold.totals.pen, 1e-5 * cold.totals.pen);
}

TEST(SequenceStarts, ARoughSolveLeavesOutWhatOnlyTheAnswerNeeds) {
  // SolverOptions::rough_tolerance: an iterate that only informs the next step (the
  // vertical-force iteration's first full solve) gets its forces to the rough tolerance, but no
  // tangential displacements and no elastic energy (a product with the full 3×3 operator).
  PatchSolver tight_solver, rough_solver;
  const Solution tight = tight_solver.solve(rolling_case());
  model::PatchProblem p = rolling_case();
  p.solver.rough_tolerance = 1e-2;
  const Solution rough = rough_solver.solve(p);
  ASSERT_TRUE(tight.solver.converged && rough.solver.converged);
  EXPECT_NEAR(rough.totals.fx, tight.totals.fx, 1e-2 * std::abs(tight.totals.fx));
  EXPECT_NEAR(rough.totals.fn, tight.totals.fn, 1e-9 * tight.totals.fn);  // FN prescribed
  EXPECT_GT(tight.totals.elastic_energy, 0.0);
  EXPECT_EQ(rough.totals.elastic_energy, 0.0);
  double tight_ux = 0.0, rough_ux = 0.0, rough_un = 0.0;
  for (std::size_t i = 0; i < tight.ux.size(); ++i) {
    tight_ux = std::max(tight_ux, std::abs(tight.ux[i]));
    rough_ux = std::max(rough_ux, std::abs(rough.ux[i]));
    rough_un = std::max(rough_un, std::abs(rough.un[i]));
  }
  EXPECT_GT(tight_ux, 0.0);
  EXPECT_EQ(rough_ux, 0.0);
  EXPECT_GT(rough_un, 0.0);  // the normal solve's own product is kept
}

}  // namespace
}  // namespace rollcontact
