// Operator assembly (elastic/operators): the steady-rolling operator C − C′ against a dense sum
// of closed-form influence coefficients, and the parts each kind of loading gets.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "elastic/material.hpp"
#include "elastic/operators/operator_sets.hpp"
#include "support/random_field.hpp"

namespace rollcontact::elastic::operators {
namespace {

Grid small_grid() {
  Grid g;
  g.mx = 9;
  g.my = 7;
  g.dx = 0.4;
  g.dy = 0.5;
  return g;
}

// With a rolling step of exactly one element, C′ is C seen from the neighbouring element
// downstream: (C − C′)(x_I − x_J) = C(x_I − x_J) − C(x_I − x_J + dx). The oracle sums the
// closed-form coefficients directly, independent of the kernel tabulation and its shift.
TEST(OperatorSets, SteadyRollingOperatorIsTheOneStepDifferenceOfC) {
  const Grid grid = small_grid();
  const CombinedMaterial m = combine_materials(0.28, 0.28, 8.0e4, 8.0e4);
  TangentialOperatorSet set;
  assemble_tangential(set, grid, m, model::TangentialKind::SteadyRolling, grid.dx, 0.0, {});
  ASSERT_TRUE(set.steady());
  EXPECT_EQ(set.prev, nullptr);  // steady rolling has no previous-time field

  const std::size_t n = grid.size();
  std::vector<double> px = test_support::random_field(n, 11),
                      py = test_support::random_field(n, 12);
  std::vector<double> ux(n), uy(n);
  const double* in[2] = {px.data(), py.data()};
  double* out[2] = {ux.data(), uy.data()};
  set.a->apply(in, out);

  double scale = 0.0, worst = 0.0;
  for (int iy = 0; iy < grid.my; ++iy)
    for (int ix = 0; ix < grid.mx; ++ix) {
      double ex = 0.0, ey = 0.0;
      for (int jy = 0; jy < grid.my; ++jy)
        for (int jx = 0; jx < grid.mx; ++jx) {
          const double ox = (ix - jx) * grid.dx, oy = (iy - jy) * grid.dy;
          auto c = [&](Component comp, double shift) {
            return (influence_coefficient(comp, ox, oy, grid.dx, grid.dy, m.nu, m.k) -
                    influence_coefficient(comp, ox + shift, oy, grid.dx, grid.dy, m.nu, m.k)) /
                   m.g;
          };
          const std::size_t j = grid.index(jx, jy);
          ex += c(Component::xx, grid.dx) * px[j] + c(Component::xy, grid.dx) * py[j];
          ey += c(Component::xy, grid.dx) * px[j] + c(Component::yy, grid.dx) * py[j];
        }
      const std::size_t i = grid.index(ix, iy);
      scale = std::max({scale, std::abs(ex), std::abs(ey)});
      worst = std::max({worst, std::abs(ux[i] - ex), std::abs(uy[i] - ey)});
    }
  // FFT round-off on O(100) terms: 1e-12 relative is two orders above what is seen.
  EXPECT_LT(worst, 1e-12 * scale) << "scale " << scale;
}

TEST(OperatorSets, ShiftUsesPlainCAndNoRollingStep) {
  const Grid grid = small_grid();
  const CombinedMaterial m = combine_materials(0.28, 0.28, 8.0e4, 8.0e4);
  TangentialOperatorSet set;
  assemble_tangential(set, grid, m, model::TangentialKind::Shift, 0.3, 0.1, {});
  EXPECT_EQ(set.shift_x, 0.0);
  EXPECT_EQ(set.shift_y, 0.0);
  EXPECT_EQ(set.prev_xx.data(), set.c_xx.data());  // previous displacement with C itself
  EXPECT_EQ(set.xx.data(), set.c_xx.data());
  EXPECT_EQ(set.tn, nullptr);  // equal materials: K = 0, no coupling
  EXPECT_EQ(set.nt, nullptr);
}

TEST(OperatorSets, TransientRollingSeesThePreviousDisplacementOneStepAway) {
  const Grid grid = small_grid();
  // Steel on a softer body: K ≠ 0, the couplings are assembled.
  const CombinedMaterial m = combine_materials(0.28, 0.4, 8.0e4, 1.0e4);
  ASSERT_TRUE(is_coupled(m));
  TangentialOperatorSet set;
  assemble_tangential(set, grid, m, model::TangentialKind::TransientRolling, grid.dx, 0.0, {});
  ASSERT_NE(set.tn, nullptr);
  ASSERT_NE(set.nt, nullptr);
  ASSERT_NE(set.prev, nullptr);
  // One element downstream: C′(dix, diy) = C(dix + 1, diy) wherever both are tabulated.
  for (int diy = -(grid.my - 1); diy < grid.my; ++diy)
    for (int dix = -(grid.mx - 1); dix < grid.mx - 1; ++dix) {
      EXPECT_NEAR(set.prev_xx.at(dix, diy), set.c_xx.at(dix + 1, diy),
                  1e-12 * std::abs(set.c_xx.at(0, 0)));
      EXPECT_NEAR(set.prev_xn.at(dix, diy), set.c_xn.at(dix + 1, diy),
                  1e-12 * std::abs(set.c_xx.at(0, 0)));
    }
}

// The tangential block of C alone (what the energy needs without couplings) is the 3×3
// product's tangential rows with p_n = 0: for steady rolling a product of its own, for the
// other kinds A itself.
TEST(OperatorSets, TangentialProductIsTheTangentialBlockOfC) {
  const Grid grid = small_grid();
  const CombinedMaterial m = combine_materials(0.28, 0.28, 8.0e4, 8.0e4);
  for (model::TangentialKind kind :
       {model::TangentialKind::SteadyRolling, model::TangentialKind::TransientRolling}) {
    TangentialOperatorSet set;
    assemble_tangential(set, grid, m, kind, grid.dx, 0.0, {});
    const std::size_t n = grid.size();
    const std::vector<double> px = test_support::random_field(n, 21),
                              py = test_support::random_field(n, 22), pn(n, 0.0);
    std::vector<double> ux(n), uy(n), fx(n), fy(n), fn(n);
    const double* in2[2] = {px.data(), py.data()};
    double* out2[2] = {ux.data(), uy.data()};
    set.tangential_product().apply(in2, out2);
    const double* in3[3] = {px.data(), py.data(), pn.data()};
    double* out3[3] = {fx.data(), fy.data(), fn.data()};
    set.full_product().apply(in3, out3);
    double scale = 0.0, worst = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      scale = std::max({scale, std::abs(fx[i]), std::abs(fy[i])});
      worst = std::max({worst, std::abs(ux[i] - fx[i]), std::abs(uy[i] - fy[i])});
    }
    EXPECT_GT(scale, 0.0);
    EXPECT_LT(worst, 1e-13 * scale) << static_cast<int>(kind);
    EXPECT_EQ(&set.tangential_product() == set.a.get(), !set.steady());
  }
}

}  // namespace
}  // namespace rollcontact::elastic::operators
