// Blanco's correction of the influence coefficients for a varying surface inclination (C=4,
// spec-additions.md §B8, wheelrail-advanced.md §1.7): the four variants against the spec's
// component formulas, the identities between them, and the kernels of a curved surface.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "elastic/inclination_correction.hpp"
#include "elastic/influence.hpp"
#include "elastic/material.hpp"
#include "rollcontact/errors.hpp"

namespace rollcontact::elastic {
namespace {

/// A 3×3 of half-space shape (x, s, n): A_sx = A_xs, A_nx = −A_xn, A_ns = −A_sn.
void half_space_like(double (&a)[3][3]) {
  const double xx = 0.71, xs = -0.13, xn = 0.042, ss = 0.83, sn = -0.057, nn = 0.91;
  const double m[3][3] = {{xx, xs, xn}, {xs, ss, sn}, {-xn, -sn, nn}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) a[i][j] = m[i][j];
}

TEST(TurnCoefficients, NoTurnLeavesEveryVariantThePlainCoefficients) {
  double a[3][3], b[3][3];
  half_space_like(a);
  for (int variant = 1; variant <= 4; ++variant) {
    turn_coefficients(variant, 0.0, a, b);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) EXPECT_EQ(b[i][j], a[i][j]) << variant << " " << i << j;
  }
}

// spec-additions.md §B8, written out component by component, with c, s of the turn θ and
// c½, s½ of θ/2 (components x = 0, s = 1, n = 2).
TEST(TurnCoefficients, VariantsAreTheSpecsComponentFormulas) {
  double a[3][3], b[3][3];
  half_space_like(a);
  const double theta = 0.37, c = std::cos(theta), s = std::sin(theta);
  const double ch = std::cos(0.5 * theta), sh = std::sin(0.5 * theta);
  constexpr double tol = 1e-15;
  // Variant 1: columns x unchanged; B_·s = c A_·s + s A_·n; B_·n = c A_·n − s A_·s.
  turn_coefficients(1, theta, a, b);
  for (int r = 0; r < 3; ++r) {
    EXPECT_NEAR(b[r][0], a[r][0], tol);
    EXPECT_NEAR(b[r][1], c * a[r][1] + s * a[r][2], tol);
    EXPECT_NEAR(b[r][2], c * a[r][2] - s * a[r][1], tol);
  }
  // Variant 2: as 1 but B_xn = A_xn.
  double b1[3][3];
  turn_coefficients(1, theta, a, b1);
  turn_coefficients(2, theta, a, b);
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 3; ++k) EXPECT_EQ(b[r][k], r == 0 && k == 2 ? a[0][2] : b1[r][k]) << r << k;
  // Variant 3: row x unchanged; B_s· = c A_s· − s A_n·; B_n· = s A_s· + c A_n·.
  turn_coefficients(3, theta, a, b);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(b[0][k], a[0][k], tol);
    EXPECT_NEAR(b[1][k], c * a[1][k] - s * a[2][k], tol);
    EXPECT_NEAR(b[2][k], s * a[1][k] + c * a[2][k], tol);
  }
  // Variant 4, with a⁺ = (A_ss + A_nn)/2, a⁻ = (A_ss − A_nn)/2.
  turn_coefficients(4, theta, a, b);
  const double ap = 0.5 * (a[1][1] + a[2][2]), am = 0.5 * (a[1][1] - a[2][2]);
  EXPECT_NEAR(b[0][0], a[0][0], tol);
  EXPECT_NEAR(b[0][1], ch * a[0][1] + sh * a[0][2], tol);
  EXPECT_NEAR(b[0][2], ch * a[0][2] - sh * a[0][1], tol);
  EXPECT_NEAR(b[1][0], ch * a[0][1] + sh * a[0][2], tol);
  EXPECT_NEAR(b[2][0], sh * a[0][1] - ch * a[0][2], tol);
  EXPECT_NEAR(b[1][1], am + ap * c + a[1][2] * s, tol);
  EXPECT_NEAR(b[1][2], a[1][2] * c - ap * s, tol);
  EXPECT_NEAR(b[2][1], ap * s - a[1][2] * c, tol);
  EXPECT_NEAR(b[2][2], -am + ap * c + a[1][2] * s, tol);
}

TEST(TurnCoefficients, UnknownVariantIsRefused) {
  double a[3][3], b[3][3];
  half_space_like(a);
  EXPECT_THROW(turn_coefficients(5, 0.1, a, b), ProblemError);
}

TEST(InclinationCurvature, IsTheLeastSquaresSlopeOfTheTable) {
  model::InclinationCorrection c;
  c.variant = 4;
  c.y_mm = {-6.0, -2.0, 1.0, 7.0};
  for (double y : c.y_mm) c.alpha_rad.push_back(0.3 - 0.025 * y);
  EXPECT_NEAR(inclination_curvature(c), -0.025, 1e-16);
  // Scattered about a line: the fit's slope Σ(y − ȳ)α / Σ(y − ȳ)² (ȳ = 0 here), not a secant.
  c.alpha_rad = {0.0, 0.1, 0.1, 0.3};
  EXPECT_NEAR(inclination_curvature(c), (-2.0 * 0.1 + 1.0 * 0.1 + 7.0 * 0.3) / (36.0 + 4 + 1 + 49),
              1e-15);
  c.y_mm = {3.0};
  c.alpha_rad = {0.2};
  EXPECT_EQ(inclination_curvature(c), 0.0);  // one inclination: a plane
  c.alpha_rad.clear();
  EXPECT_THROW(inclination_curvature(c), ProblemError);
}

CombinedMaterial turned(int variant, double curvature) {
  CombinedMaterial m = combine_materials(0.28, 0.28, 82000.0, 82000.0);
  m.inclination_variant = variant;
  m.inclination_curvature_per_mm = curvature;
  return m;
}

const std::vector<Component> kAll{Component::xx, Component::xy, Component::xn,
                                  Component::yx, Component::yy, Component::yn,
                                  Component::nx, Component::ny, Component::nn};
// The transposed component: displacement j due to traction i.
Component transposed(Component c) {
  switch (c) {
    case Component::xy:
      return Component::yx;
    case Component::yx:
      return Component::xy;
    case Component::xn:
      return Component::nx;
    case Component::nx:
      return Component::xn;
    case Component::yn:
      return Component::ny;
    case Component::ny:
      return Component::yn;
    default:
      return c;
  }
}

double largest(const std::vector<Kernel>& ks) {
  double m = 0.0;
  for (const Kernel& k : ks)
    for (double v : k.data()) m = std::max(m, std::abs(v));
  return m;
}

/// b (kernels of kAll on a 7 × 9 grid) is bt transposed as an operator: b_ij(Δ) = bt_ji(−Δ).
void expect_transposed(const std::vector<Kernel>& b, const std::vector<Kernel>& bt, double tol) {
  for (std::size_t q = 0; q < kAll.size(); ++q) {
    const std::size_t t = static_cast<std::size_t>(
        std::find(kAll.begin(), kAll.end(), transposed(kAll[q])) - kAll.begin());
    for (int diy = -8; diy <= 8; ++diy)
      for (int dix = -6; dix <= 6; ++dix)
        ASSERT_NEAR(b[q].at(dix, diy), bt[t].at(-dix, -diy), tol) << q << " " << dix << diy;
  }
}

// B of variant 3 (the displacement turned) is that of variant 1 (the load turned) transposed as
// an operator: B3_ij(Δ) = B1_ji(−Δ).
TEST(InclinationKernels, TurningTheDisplacementIsTurningTheLoadTransposed) {
  const Grid grid{7, 9, 0.0, 0.0, 0.5, 0.4};
  const std::vector<Kernel> b1 = make_kernels(kAll, grid, turned(1, 0.04));
  const std::vector<Kernel> b3 = make_kernels(kAll, grid, turned(3, 0.04));
  ASSERT_NO_FATAL_FAILURE(expect_transposed(b3, b1, 1e-14 * largest(b1)));
}

// Variant 4 turns load and displacement halfway: the operator stays symmetric, as the
// half-space's is (PCG applies to shifts).
TEST(InclinationKernels, HalfwayTurnsKeepTheOperatorSymmetric) {
  const Grid grid{7, 9, 0.0, 0.0, 0.5, 0.4};
  const std::vector<Kernel> b = make_kernels(kAll, grid, turned(4, -0.06));
  ASSERT_NO_FATAL_FAILURE(expect_transposed(b, b, 1e-14 * largest(b)));
  // Variant 1 is not: the normal load turned into the lateral direction has no counterpart.
  const std::vector<Kernel> b1 =
      make_kernels({Component::yn, Component::ny}, grid, turned(1, -0.06));
  EXPECT_GT(std::abs(b1[0].at(0, 3) - b1[1].at(0, -3)), 1e-3 * std::abs(b1[0].at(0, 3)));
}

// Rows at the same inclination (one offset row) and a zero curvature are the plain half-space;
// the turn grows with the lateral offset as θ = −c₁·Δy.
TEST(InclinationKernels, TurnFollowsTheLateralOffset) {
  const Grid grid{5, 6, 0.0, 0.0, 0.5, 0.4};
  const CombinedMaterial plain = combine_materials(0.28, 0.28, 82000.0, 82000.0);
  const std::vector<Kernel> a = make_kernels({Component::yy, Component::nn}, grid, plain);
  const std::vector<Kernel> b =
      make_kernels({Component::yy, Component::nn, Component::ny}, grid, turned(1, 0.05));
  for (int dix = -4; dix <= 4; ++dix) {
    EXPECT_EQ(b[0].at(dix, 0), a[0].at(dix, 0));
    EXPECT_EQ(b[1].at(dix, 0), a[1].at(dix, 0));
  }
  // Variant 1 with K = 0: B_ss = cos θ·A_ss, B_nn = cos θ·A_nn, B_ns = sin θ·A_nn.
  for (int diy = -5; diy <= 5; ++diy) {
    const double theta = -0.05 * diy * grid.dy;
    EXPECT_NEAR(b[0].at(2, diy), std::cos(theta) * a[0].at(2, diy), 1e-15);
    EXPECT_NEAR(b[1].at(2, diy), std::cos(theta) * a[1].at(2, diy), 1e-15);
    EXPECT_NEAR(b[2].at(2, diy), std::sin(theta) * a[1].at(2, diy), 1e-15);
  }
  const std::vector<Kernel> none =
      make_kernels({Component::yy, Component::nn}, grid, turned(1, 0.0));
  EXPECT_EQ(none[0].data(), a[0].data());
  EXPECT_EQ(none[1].data(), a[1].data());
}

TEST(InclinationKernels, TheCorrectionCouplesQuasiIdenticalBodies) {
  EXPECT_FALSE(is_coupled(turned(2, 0.0)));
  EXPECT_TRUE(is_coupled(turned(2, 1e-3)));
}

}  // namespace
}  // namespace rollcontact::elastic
