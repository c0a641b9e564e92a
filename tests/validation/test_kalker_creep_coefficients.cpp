// Kalker's linear theory from the exact steady-rolling solver: at vanishing creepage
// FX = −G c² C11 ξ, FY = −G c² C22 η − G c³ C23 φ with c = √(ab). The discrete values approach
// Kalker's table from above as the grid is refined (for a/b = 1: C11 = 4.318, 4.197, 4.192, 4.155,
// 4.144 at 10, 20, 40, 60, 80 elements per axis against 4.12); the acceptance is 2 % at 60.
// A few seconds per solve: label "reference", not run under the sanitizers.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "rollcontact/solve.hpp"

namespace rollcontact {
namespace {

struct CreepCase {
  double aob, c11, c22, c23;  // Kalker's table, ν = 0.25 (spec/physics.md §11.1)
};

class KalkerCoefficients : public ::testing::TestWithParam<CreepCase> {};

TEST_P(KalkerCoefficients, FromSmallCreepageOnARefinedGrid) {
  const CreepCase cc = GetParam();
  const double g = 82000.0, nu = 0.25, fn = 10000.0, c = 5.0;
  const int n = 60;  // elements over each axis of the contact ellipse
  model::PatchProblem base;
  base.tangential.kind = model::TangentialKind::SteadyRolling;
  base.normal.kind = model::NormalLoadKind::Force;
  base.solver.tolerance = 1e-6;
  base.normal.force_N = fn;
  base.rolling.velocity_mm_per_s = 1000.0;
  base.bodies.body1 = base.bodies.body2 = {nu, g};
  base.potential.ipotcn = -3;
  base.potential.mx = base.potential.my = n + 4;
  base.potential.values = {c * std::sqrt(cc.aob), c / std::sqrt(cc.aob), (n + 4.0) / n, 0.0};
  base.friction = {1e4, 1e4};  // full adhesion: the linear limit
  const double creep = 1e-6;
  PatchSolver solver;
  model::PatchProblem px = base, py = base, pphi = base;
  px.tangential.creepage.longitudinal = creep;
  py.tangential.creepage.lateral = creep;
  pphi.tangential.creepage.spin_rad_per_mm = creep / c;
  const Solution sx = solver.solve(px), sy = solver.solve(py), sphi = solver.solve(pphi);
  ASSERT_TRUE(sx.solver.converged && sy.solver.converged && sphi.solver.converged);
  const double c11 = -sx.totals.fx / (g * c * c * creep);
  const double c22 = -sy.totals.fy / (g * c * c * creep);
  const double c23 = -sphi.totals.fy / (g * c * c * c * (creep / c));
  RecordProperty("c11", std::to_string(c11));
  std::printf("a/b %.2f: C11 %.4f (%.2f) C22 %.4f (%.2f) C23 %.4f (%.3f)\n", cc.aob, c11, cc.c11,
              c22, cc.c22, c23, cc.c23);
  EXPECT_NEAR(c11, cc.c11, 0.02 * cc.c11);
  EXPECT_NEAR(c22, cc.c22, 0.02 * cc.c22);
  EXPECT_NEAR(c23, cc.c23, 0.02 * cc.c23);
}

INSTANTIATE_TEST_SUITE_P(Table, KalkerCoefficients,
                         ::testing::Values(CreepCase{0.5, 3.62, 3.01, 0.929},
                                           CreepCase{1.0, 4.12, 3.67, 1.47},
                                           CreepCase{2.0, 5.10, 4.90, 2.62}));

}  // namespace
}  // namespace rollcontact
