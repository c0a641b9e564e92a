// PatchSolver with the temperature calculation (H ≥ 1, spec/physics.md §15): the bulk
// temperatures without a tangential problem, one surface temperature for both bodies in
// contact, the heat equal to the frictional power, and the hottest point in the rear half.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "post/surface_temperature.hpp"
#include "rollcontact/solve.hpp"
#include "support/hertz_problem.hpp"

namespace rollcontact {
namespace {

/// A circular Hertzian contact (a = b = 3 mm, FN = 10 kN) between steel bodies at 20 °C and
/// 150 °C, rolling towards +x at 20 m/s.
model::PatchProblem heated_problem(int t, double creepage) {
  model::PatchProblem p = test::hertz_problem(3.0, 3.0, 1e4, 82000.0, 0.28, 40, 40, 1.1);
  p.tangential.kind = test::tangential_kind(t);
  p.tangential.creepage.longitudinal = creepage;
  p.rolling = {0.0, 2.0 * 3.0 * 1.1 / 40, 20000.0, 1.0 / 6.0};
  p.heat.enabled = true;
  p.heat.body1 = {20.0, 450.0, 50e-3, 7.85e-6};
  p.heat.body2 = {150.0, 450.0, 50e-3, 7.85e-6};
  return p;
}

TEST(SurfaceTemperatureSolve, WithoutTangentialProblemTheBulkTemperaturesAreTheResult) {
  PatchSolver solver;
  const Solution s = solver.solve(heated_problem(0, 0.0));
  ASSERT_TRUE(s.solver.converged) << s.solver.message;
  ASSERT_EQ(s.temp1.size(), s.grid.size());
  EXPECT_TRUE(std::all_of(s.temp1.begin(), s.temp1.end(), [](double v) { return v == 20.0; }));
  EXPECT_TRUE(std::all_of(s.temp2.begin(), s.temp2.end(), [](double v) { return v == 150.0; }));
  EXPECT_DOUBLE_EQ(s.totals.max_temp1, 20.0);
  EXPECT_DOUBLE_EQ(s.totals.max_temp2, 150.0);
}

TEST(SurfaceTemperatureSolve, NoHeatWithoutTheCalculation) {
  model::PatchProblem p = heated_problem(3, 0.01);
  p.heat.enabled = false;
  PatchSolver solver;
  const Solution s = solver.solve(p);
  EXPECT_TRUE(s.temp1.empty());
  EXPECT_DOUBLE_EQ(s.totals.max_temp1, 0.0);
}

TEST(SurfaceTemperatureSolve, FullSlidingHeatsBothSurfacesAlikeDownstream) {
  PatchSolver solver;
  const Solution s = solver.solve(heated_problem(3, 0.05));
  ASSERT_TRUE(s.solver.converged) << s.solver.message;
  ASSERT_EQ(s.statistics.nadh, 0);  // full sliding
  const Grid& g = s.grid;
  // The heat generated equals the frictional power: Σ q·δxδy [mW] = −1000·FRIC.POWER [W].
  const std::vector<double> q = post::frictional_heat_flux(s, 0.0, {});
  double heat = 0.0;
  for (const double v : q) heat += v * g.element_area();
  EXPECT_NEAR(heat, -1000.0 * s.totals.frictional_power, 1e-9 * heat);
  // Identical bodies in contact share one surface temperature, above the contact temperature
  // (20 + 150)/2.
  double hottest = 0.0;
  int hottest_ix = -1, hottest_iy = -1;
  for (int iy = 0; iy < g.my; ++iy) {
    for (int ix = 0; ix < g.mx; ++ix) {
      const std::size_t i = g.index(ix, iy);
      if (s.pn[i] <= 0.0) continue;
      EXPECT_DOUBLE_EQ(s.temp1[i], s.temp2[i]);
      EXPECT_GT(s.temp1[i], 85.0);
      if (s.temp1[i] > hottest) {
        hottest = s.temp1[i];
        hottest_ix = ix;
        hottest_iy = iy;
      }
    }
  }
  EXPECT_DOUBLE_EQ(std::max(s.totals.max_temp1, s.totals.max_temp2), hottest);
  // Heat is carried downstream: with the Hertzian flux (falling to 0 at the edges) the maximum
  // lies in the rear half of the contact (x < 0), on the centre row, and each row warms up
  // from its leading edge.
  EXPECT_LT(g.x_centre(hottest_ix), -0.3 * 3.0);
  EXPECT_NEAR(g.y_centre(hottest_iy), 0.0, g.dy);
  for (int ix = g.mx - 1; ix > hottest_ix; --ix) {
    const std::size_t i = g.index(ix, hottest_iy), next = g.index(ix - 1, hottest_iy);
    if (s.pn[i] > 0.0) {
      EXPECT_LT(s.temp1[i], s.temp1[next]) << ix;
    }
  }
}

}  // namespace
}  // namespace rollcontact
