// The tangential problem on the box around the contact (contact/contact_box.hpp): the box's
// geometry, and the same solution as on a grid that holds just the contact.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "contact/contact_box.hpp"
#include "rollcontact/solve.hpp"
#include "support/hertz_problem.hpp"

namespace rollcontact {
namespace {

Grid grid_of(int mx, int my) {
  Grid g;
  g.mx = mx;
  g.my = my;
  g.xl = -10.0;
  g.yl = 5.0;
  g.dx = 0.5;
  g.dy = 0.25;
  return g;
}

std::vector<char> contact_rectangle(const Grid& g, int ix_lo, int ix_hi, int iy_lo, int iy_hi) {
  std::vector<char> c(g.size(), 0);
  for (int iy = iy_lo; iy <= iy_hi; ++iy)
    for (int ix = ix_lo; ix <= ix_hi; ++ix) c[g.index(ix, iy)] = 1;
  return c;
}

TEST(ContactBox, FreeElementAroundSidesInMultiplesOfEight) {
  const Grid g = grid_of(90, 40);
  const auto box = contact::contact_box(g, contact_rectangle(g, 30, 45, 10, 20), 0.5);
  ASSERT_TRUE(box);
  // x: 16 elements + 2 free = 18 -> 24; y: 11 + 2 = 13 -> 16.
  EXPECT_EQ(box->grid.mx, 24);
  EXPECT_EQ(box->grid.my, 16);
  EXPECT_EQ(box->ix0, 29);
  EXPECT_EQ(box->iy0, 9);
  // Element centres are those of the grid.
  EXPECT_DOUBLE_EQ(box->grid.x_centre(0), g.x_centre(29));
  EXPECT_DOUBLE_EQ(box->grid.y_centre(0), g.y_centre(9));
  EXPECT_EQ(box->grid.dx, g.dx);
  EXPECT_EQ(box->grid.dy, g.dy);
}

TEST(ContactBox, StaysInsideTheGrid) {
  const Grid g = grid_of(90, 40);
  // Contact at the far corner: no free element beyond the grid, box moved inwards.
  const auto box = contact::contact_box(g, contact_rectangle(g, 85, 89, 36, 39), 0.5);
  ASSERT_TRUE(box);
  EXPECT_EQ(box->grid.mx, 8);
  EXPECT_EQ(box->grid.my, 8);
  EXPECT_EQ(box->ix0 + box->grid.mx, 90);
  EXPECT_EQ(box->iy0 + box->grid.my, 40);
}

TEST(ContactBox, NoneWhenTooLargeOrEmpty) {
  const Grid g = grid_of(34, 33);
  EXPECT_FALSE(contact::contact_box(g, contact_rectangle(g, 3, 30, 2, 30), 0.5));
  EXPECT_FALSE(contact::contact_box(g, std::vector<char>(g.size(), 0), 0.5));
  EXPECT_TRUE(contact::contact_box(g, contact_rectangle(g, 3, 12, 2, 12), 0.5));
}

TEST(ContactBox, FieldsRoundTrip) {
  const Grid g = grid_of(20, 12);
  const auto box = contact::contact_box(g, contact_rectangle(g, 4, 8, 3, 6), 0.5);
  ASSERT_TRUE(box);
  std::vector<double> f(g.size());
  for (std::size_t i = 0; i < f.size(); ++i) f[i] = static_cast<double>(i);
  const std::vector<double> b = contact::restrict_to_box(f, g, *box);
  ASSERT_EQ(b.size(), box->grid.size());
  EXPECT_EQ(b[box->grid.index(2, 1)], f[g.index(box->ix0 + 2, box->iy0 + 1)]);
}

/// A Hertzian contact with creepages on a grid over `scale` times the ellipse: 1.1 holds the
/// contact alone (no box), 3.3 three times as wide with the same elements (solved on the box).
Solution solve_hertz(int t, int m, double scale) {
  model::PatchProblem p = test::hertz_problem(0.6, 1.0, 10.0, 82000.0, 0.28, m, m, scale);
  p.potential.values = {0.6, 0.6, scale, 0.0};
  p.tangential.kind = test::tangential_kind(t);
  p.solver.tolerance = 1e-9;
  p.rolling.velocity_mm_per_s = 10000.0;
  p.rolling.step_mm = 0.6 * 2.2 / m;
  p.tangential.creepage.longitudinal = t == 1 ? 1.0e-5 : 2.0e-5;
  p.tangential.creepage.lateral = t == 1 ? 0.0 : -1.0e-5;
  p.tangential.creepage.spin_rad_per_mm = t == 1 ? 1.0e-5 : 2.0e-5;
  return PatchSolver().solve(p);
}

class BoxSolveEqualsTightGrid : public ::testing::TestWithParam<int> {};

TEST_P(BoxSolveEqualsTightGrid, TractionsAndForces) {
  const int t = GetParam();
  const Solution tight = solve_hertz(t, 21, 1.1);
  const Solution wide = solve_hertz(t, 63, 3.3);  // elements coincide: offset 21 in x and y
  ASSERT_TRUE(tight.solver.converged) << tight.solver.message;
  ASSERT_TRUE(wide.solver.converged) << wide.solver.message;
  const double mu_fn = 0.3 * tight.totals.fn;
  EXPECT_NEAR(wide.totals.fn, tight.totals.fn, 1e-7 * tight.totals.fn);
  // Both solves stop at a relative change of 1e-9 (Newton's merit 1e-10): forces within 1e-6.
  EXPECT_NEAR(wide.totals.fx, tight.totals.fx, 1e-6 * mu_fn);
  EXPECT_NEAR(wide.totals.fy, tight.totals.fy, 1e-6 * mu_fn);
  double pmax = 0.0;
  for (double v : tight.pn) pmax = std::max(pmax, v);
  int slip = 0;
  for (int iy = 0; iy < 21; ++iy)
    for (int ix = 0; ix < 21; ++ix) {
      const std::size_t i = tight.grid.index(ix, iy), j = wide.grid.index(ix + 21, iy + 21);
      EXPECT_NEAR(wide.px[j], tight.px[i], 1e-5 * 0.3 * pmax) << ix << ", " << iy;
      EXPECT_NEAR(wide.py[j], tight.py[i], 1e-5 * 0.3 * pmax) << ix << ", " << iy;
      EXPECT_EQ(wide.state[j], tight.state[i]) << ix << ", " << iy;
      slip += tight.state[i] == ElementState::Slip;
    }
  EXPECT_GT(slip, 0);  // a partial-slip problem, not full adhesion
}

INSTANTIATE_TEST_SUITE_P(ShiftAndSteady, BoxSolveEqualsTightGrid, ::testing::Values(1, 3));

}  // namespace
}  // namespace rollcontact
