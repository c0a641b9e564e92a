// The normal problem with a prescribed approach solved on a box of the grid (PatchSolver, see
// CaseSolver::normal_box): around the interpenetration, or around the starting pressure and
// checked on the whole grid afterwards. Either way the answer is the whole grid's.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "contact/contact_box.hpp"
#include "rollcontact/solve.hpp"
#include "support/hertz_problem.hpp"

namespace rollcontact {
namespace {

TEST(InterpenetrationBox, HoldsWhereTheBodiesOverlapWithAFreeElementAround) {
  Grid g;
  g.mx = 40;
  g.my = 30;
  g.dx = g.dy = 0.5;
  // A paraboloid gap with its minimum at element (10, 20): h < pen for |Δix|, |Δiy| ≤ 3.
  std::vector<double> h(g.size());
  for (int iy = 0; iy < g.my; ++iy)
    for (int ix = 0; ix < g.mx; ++ix)
      h[g.index(ix, iy)] = 0.01 * ((ix - 10) * (ix - 10) + (iy - 20) * (iy - 20));
  const auto box = contact::interpenetration_box(g, h, 0.095, 0.5);
  ASSERT_TRUE(box);
  // Elements 7..13 overlap (0.09 < 0.095), a free one each side: 6..14, 9 -> 16 elements.
  EXPECT_EQ(box->ix0, 6);
  EXPECT_EQ(box->iy0, 14);  // 17..23 plus 16 and 24, 16 rows moved inside the grid (30)
  EXPECT_EQ(box->grid.mx, 16);
  EXPECT_EQ(box->grid.my, 16);
  EXPECT_FALSE(contact::interpenetration_box(g, h, -1.0, 0.5));  // no overlap
  EXPECT_FALSE(contact::interpenetration_box(g, h, 10.0, 0.5));  // all of the grid
  std::vector<double> f(g.size(), 0.0);
  f[g.index(10, 20)] = 1.0;
  EXPECT_TRUE(contact::zero_outside(f, g, *box));
  f[g.index(30, 2)] = 1.0;
  EXPECT_FALSE(contact::zero_outside(f, g, *box));
}

/// A sphere of radius 100 mm on a plane (h = (x² + y²)/200) with the approach prescribed, on
/// m × m elements of 0.06 mm centred on the contact: a Hertzian contact of radius √(R·PEN)
/// (0.5 mm at 2.5 µm) inside an interpenetration √2 times as wide.
model::PatchProblem sphere_problem(int m, double pen_mm) {
  model::PatchProblem p = test::hertz_problem(0.5, 0.5, 10.0, 82000.0, 0.28, m, m, 1.0);
  constexpr double dx = 0.06;
  p.potential.ipotcn = 1;
  p.potential.values = {-0.5 * m * dx, -0.5 * m * dx, dx, dx};
  p.gap.ibase = 1;
  p.gap.coeffs = {1.0 / 200.0, 0.0, 1.0 / 200.0, 0.0, 0.0, 0.0};  // b1 x² + b2 xy + b3 y²
  p.normal.kind = model::NormalLoadKind::Approach;
  p.normal.approach_mm = pen_mm;
  p.solver.tolerance = 1e-10;
  return p;
}

double max_of(const std::vector<double>& v) {
  return *std::max_element(v.begin(), v.end());
}

void expect_same_pressures(const Solution& tight, const Solution& wide, int offset) {
  const double pmax = max_of(tight.pn);
  for (int iy = 0; iy < tight.grid.my; ++iy)
    for (int ix = 0; ix < tight.grid.mx; ++ix) {
      const std::size_t i = tight.grid.index(ix, iy);
      const std::size_t j = wide.grid.index(ix + offset, iy + offset);
      // Both NormCG solves stop at a relative change of 1e-10: pressures within 1e-7·pmax.
      EXPECT_NEAR(wide.pn[j], tight.pn[i], 1e-7 * pmax) << ix << ", " << iy;
      // Displacements within rounding of the products (the wide one's on its whole grid).
      EXPECT_NEAR(wide.un[j], tight.un[i], 1e-9 * tight.totals.pen) << ix << ", " << iy;
    }
}

TEST(NormalBox, ApproachGivenOnAWideGridEqualsTheTightGrid) {
  // 21 elements hold the contact (1.0 mm of 1.26) but not the interpenetration (1.41 mm): the
  // whole grid; 63 with the same elements: the box around the interpenetration.
  const Solution tight = PatchSolver().solve(sphere_problem(21, 2.5e-3));
  const Solution wide = PatchSolver().solve(sphere_problem(63, 2.5e-3));
  ASSERT_TRUE(tight.solver.converged) << tight.solver.message;
  ASSERT_TRUE(wide.solver.converged) << wide.solver.message;
  // Hertz: FN = (4/3)·E*·√R·PEN^1.5 with E* = G/(1 − ν); 2 % for the 17 elements across.
  const double hertz = 4.0 / 3.0 * 82000.0 / 0.72 * 10.0 * std::pow(2.5e-3, 1.5);
  EXPECT_NEAR(tight.totals.fn, hertz, 0.02 * hertz);
  EXPECT_NEAR(wide.totals.fn, tight.totals.fn, 1e-7 * tight.totals.fn);
  expect_same_pressures(tight, wide, 21);
  // Outside the box the displacement is the whole grid's too: positive, decaying (a product
  // on the box alone would leave zeros there).
  EXPECT_GT(wide.un[wide.grid.index(0, 0)], 0.0);
  EXPECT_LT(wide.un[wide.grid.index(0, 0)], wide.un[wide.grid.index(10, 10)]);
}

TEST(NormalBox, AContactBeyondTheStartingPressureIsSolvedOnTheWholeGrid) {
  // A sequence (the vertical-force iteration's way) from a small contact to one three times as
  // deep: the start's box is too small, the check on the whole grid finds the overlap outside
  // it, and the solve goes on over the whole grid from there: the cold solve's answer.
  model::PatchProblem shallow = sphere_problem(63, 0.9e-3);  // contact radius 0.3 mm
  shallow.tangential.kind = test::tangential_kind(3);
  shallow.rolling.velocity_mm_per_s = 10000.0;
  shallow.rolling.step_mm = 0.06;
  shallow.tangential.creepage.longitudinal = 1.0e-5;
  shallow.sequence.continue_previous = true;
  shallow.sequence.normal_from_previous = true;
  PatchSolver sequence;
  const Solution first = sequence.solve(shallow);
  ASSERT_TRUE(first.solver.converged) << first.solver.message;

  model::PatchProblem deep = shallow;
  deep.normal.approach_mm = 3.0 * shallow.normal.approach_mm;  // radius 0.52 mm
  const Solution warm = sequence.solve(deep);
  model::PatchProblem cold_problem = deep;
  cold_problem.sequence = {};
  const Solution cold = PatchSolver().solve(cold_problem);
  ASSERT_TRUE(warm.solver.converged) << warm.solver.message;
  ASSERT_TRUE(cold.solver.converged) << cold.solver.message;
  EXPECT_GT(warm.statistics.ncon, 2 * first.statistics.ncon);  // it grew beyond the start
  EXPECT_EQ(warm.statistics.ncon, cold.statistics.ncon);
  EXPECT_NEAR(warm.totals.fn, cold.totals.fn, 1e-7 * cold.totals.fn);
  const double pmax = max_of(cold.pn);
  for (std::size_t i = 0; i < cold.pn.size(); ++i) {
    EXPECT_NEAR(warm.pn[i], cold.pn[i], 1e-7 * pmax) << i;
    EXPECT_NEAR(warm.un[i], cold.un[i], 1e-7 * cold.totals.pen) << i;
  }
}

}  // namespace
}  // namespace rollcontact
