// The three tangential solvers on a TangentialSystem built directly from the operators (no
// PatchSolver around them): Coulomb's law element by element, agreement between semismooth
// Newton, preconditioned Jacobi and ConvexGS, full slip at the exact force μ·FN, and the local
// element problem with an anisotropic diagonal block.

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "elastic/material.hpp"
#include "elastic/operators/operator_sets.hpp"
#include "tangential/element_problem.hpp"
#include "tangential/tangential_preconditioner.hpp"
#include "tangential/tangential_system.hpp"

namespace rollcontact::tangential {
namespace {

constexpr double kMu = 0.3;
constexpr double kP0 = 1000.0;  // peak pressure [N/mm²]

/// A circular contact of radius 1 mm with Hertzian pressure on a 21×21 grid of 0.1 mm, steel
/// on steel, and a uniform rigid slip (bx, 0) per step [mm].
struct CircularContact {
  elastic::operators::TangentialOperatorSet ops;
  std::unique_ptr<TangentialPreconditioner> preconditioner;
  TangentialSystem sys;
  std::vector<double> pressure;

  CircularContact(model::TangentialKind kind, double bx) {
    Grid grid;
    grid.mx = grid.my = 21;
    grid.dx = grid.dy = 0.1;
    grid.xl = grid.yl = -1.05;
    const CombinedMaterial m = elastic::combine_materials(0.28, 0.28, 8.0e4, 8.0e4);
    elastic::operators::assemble_tangential(ops, grid, m, kind, grid.dx, 0.0, {});
    preconditioner = std::make_unique<TangentialPreconditioner>(ops.c_xx, ops.c_xy, ops.c_yy,
                                                                FftBackendKind::Default);
    const std::size_t n = grid.size();
    sys.grid = grid;
    sys.a = {&ops.xx,       &ops.xy,     &ops.xy, &ops.yy, ops.a.get(), preconditioner.get(),
             !ops.steady(), ops.steady()};
    sys.contact.assign(n, 0);
    sys.bound.assign(n, 0.0);
    sys.bx.assign(n, 0.0);
    sys.by.assign(n, 0.0);
    pressure.assign(n, 0.0);
    for (int iy = 0; iy < grid.my; ++iy)
      for (int ix = 0; ix < grid.mx; ++ix) {
        const double x = grid.xl + (ix + 0.5) * grid.dx, y = grid.yl + (iy + 0.5) * grid.dy;
        const double r2 = x * x + y * y;
        if (r2 >= 1.0) continue;
        const std::size_t i = grid.index(ix, iy);
        pressure[i] = kP0 * std::sqrt(1.0 - r2);
        sys.contact[i] = 1;
        sys.bound[i] = kMu * pressure[i];
        sys.bx[i] = bx;
      }
  }
};

TangentialSettings tight() {
  TangentialSettings s;
  s.eps = 1e-9;
  return s;
}

/// Coulomb's law: |p| ≤ g; adhesion without slip; slip at the bound against the slip.
void expect_coulomb(const TangentialSystem& sys, const TangentialResult& r, double slip_scale) {
  for (std::size_t i = 0; i < sys.contact.size(); ++i) {
    if (!sys.contact[i]) continue;
    const double g = sys.bound[i], p = std::hypot(r.px[i], r.py[i]);
    const double s = std::hypot(r.sx[i], r.sy[i]);
    EXPECT_LE(p, g * (1.0 + 1e-9)) << "element " << i;
    if (r.state[i] == ElementState::Adhesion) {
      EXPECT_EQ(s, 0.0) << "element " << i;  // finalise reports no slip in adhesion
    } else {
      EXPECT_NEAR(p, g, 1e-9 * g) << "element " << i;
      if (s > 1e-6 * slip_scale) {
        EXPECT_LT((r.px[i] * r.sx[i] + r.py[i] * r.sy[i]) / (p * s), -0.9999) << "element " << i;
      }
    }
  }
}

using Solver = TangentialResult (*)(const TangentialSystem&, const TangentialSettings&,
                                    const std::vector<double>*, const std::vector<double>*);

struct Named {
  const char* name;
  Solver solve;
};

class EverySolver : public ::testing::TestWithParam<Named> {};

// A shift of a third of the elastic scale μp₀a/G ≈ 3.8e-3 mm: adhesion inside, slip outside.
TEST_P(EverySolver, PartialSlipObeysCoulombAndAgreesWithConvexGS) {
  const double shift = 1.2e-3;
  CircularContact c(model::TangentialKind::Shift, shift);
  const TangentialResult r = GetParam().solve(c.sys, tight(), nullptr, nullptr);
  ASSERT_TRUE(r.converged) << r.message;
  expect_coulomb(c.sys, r, shift);
  int adhesion = 0, slip = 0;
  for (ElementState s : r.state) {
    adhesion += s == ElementState::Adhesion;
    slip += s == ElementState::Slip;
  }
  EXPECT_GT(adhesion, 50);  // a stick zone inside ...
  EXPECT_GT(slip, 50);      // ... and a slip annulus

  const TangentialResult ref = solve_convex_gs(c.sys, tight(), nullptr, nullptr);
  ASSERT_TRUE(ref.converged);
  double worst = 0.0;
  for (std::size_t i = 0; i < r.px.size(); ++i)
    worst = std::max({worst, std::abs(r.px[i] - ref.px[i]), std::abs(r.py[i] - ref.py[i])});
  // Both stop at a relative change of 1e-9; 1e-6·μp₀ leaves room for the different paths.
  EXPECT_LT(worst, 1e-6 * kMu * kP0);
}

// A shift far beyond the elastic scale: everything slips, p = −g·b/|b| and F = μ·FN exactly.
TEST_P(EverySolver, LargeShiftGivesFullSlipAtMuTimesFn) {
  CircularContact c(model::TangentialKind::Shift, 1.0);
  const TangentialResult r = GetParam().solve(c.sys, tight(), nullptr, nullptr);
  ASSERT_TRUE(r.converged) << r.message;
  double fx = 0.0, fy = 0.0, fn = 0.0;
  for (std::size_t i = 0; i < r.px.size(); ++i) {
    if (!c.sys.contact[i]) continue;
    EXPECT_EQ(r.state[i], ElementState::Slip) << "element " << i;
    fx += r.px[i];
    fy += r.py[i];
    fn += c.pressure[i];
  }
  // The iterations stop at a relative change of 1e-9 and the slip test allows |p| ≥ g(1 − 1e-9):
  // 1e-8 relative covers both.
  EXPECT_NEAR(fx, -kMu * fn, 1e-8 * kMu * fn);
  EXPECT_NEAR(fy, 0.0, 1e-8 * kMu * fn);
}

INSTANTIATE_TEST_SUITE_P(Tangential, EverySolver,
                         ::testing::Values(Named{"SemismoothNewton", solve_semismooth_newton},
                                           Named{"PreconditionedJacobi",
                                                 solve_preconditioned_jacobi},
                                           Named{"ConvexGS", solve_convex_gs}),
                         [](const auto& param_info) { return std::string(param_info.param.name); });

// Steady rolling: the non-symmetric C − C′ with GMRES inside Newton, against ConvexGS.
TEST(SteadyRolling, NewtonAgreesWithConvexGSOnTheNonSymmetricOperator) {
  // Creepage 1e-3 over a step of 0.1 mm: partial slip (μp₀/G ≈ 3.8e-3).
  CircularContact c(model::TangentialKind::SteadyRolling, 1e-4);
  const TangentialResult newton = solve_semismooth_newton(c.sys, tight(), nullptr, nullptr);
  const TangentialResult gs = solve_convex_gs(c.sys, tight(), nullptr, nullptr);
  ASSERT_TRUE(newton.converged) << newton.message;
  ASSERT_TRUE(gs.converged) << gs.message;
  expect_coulomb(c.sys, newton, 1e-4);
  double worst = 0.0, fx = 0.0;
  for (std::size_t i = 0; i < newton.px.size(); ++i) {
    worst = std::max(worst, std::abs(newton.px[i] - gs.px[i]));
    fx += newton.px[i];
  }
  EXPECT_LT(worst, 1e-6 * kMu * kP0);
  EXPECT_LT(fx, 0.0);  // the traction opposes the creepage
}

// TangentialSettings::slip_of_last_iterate (rough solves): the same tractions and states, the
// slip from the iteration instead of a product — equal to it up to the solve's tolerance.
TEST(SteadyRolling, SlipOfTheLastIterateIsTheProductsUpToTheTolerance) {
  CircularContact c(model::TangentialKind::SteadyRolling, 1e-4);
  TangentialSettings rough;
  rough.eps = 1e-2;
  TangentialSettings carried = rough;
  carried.slip_of_last_iterate = true;
  const TangentialResult product = solve_semismooth_newton(c.sys, rough, nullptr, nullptr);
  const TangentialResult iterate = solve_semismooth_newton(c.sys, carried, nullptr, nullptr);
  ASSERT_TRUE(product.converged && iterate.converged);
  EXPECT_EQ(iterate.px, product.px);
  EXPECT_EQ(iterate.py, product.py);
  EXPECT_EQ(iterate.state, product.state);
  double worst = 0.0, largest = 0.0;
  int slipping = 0;
  for (std::size_t i = 0; i < product.sx.size(); ++i) {
    worst =
        std::max(worst, std::hypot(iterate.sx[i] - product.sx[i], iterate.sy[i] - product.sy[i]));
    largest = std::max(largest, std::hypot(product.sx[i], product.sy[i]));
    slipping += product.state[i] == ElementState::Slip;
  }
  EXPECT_GT(slipping, 0);
  EXPECT_GT(largest, 0.0);
  // The final projection moves p by at most the tolerance's share of it; the slip moves by that
  // through A (|A| ~ 1/G per element: 1e-2 of μp₀/G ≈ 4e-5 mm here, against slips of ~1e-4).
  EXPECT_LT(worst, 1e-2 * kMu * kP0 / 8.0e4);
  EXPECT_GT(worst, 0.0);  // not the product again
}

// S = c + D·p with an anisotropic D: adhesion solves S = 0 inside the bound; slip puts p on the
// bound, opposite to S.
TEST(ElementProblem, AdhesionSolvesForZeroSlipAndSlipOpposesIt) {
  const double d[4] = {2.0, 0.3, 0.3, 1.5};
  const ElementSolution a = solve_element(0.1, -0.05, d, 1.0);
  EXPECT_FALSE(a.slip);
  EXPECT_NEAR(0.1 + d[0] * a.px + d[1] * a.py, 0.0, 1e-15);
  EXPECT_NEAR(-0.05 + d[2] * a.px + d[3] * a.py, 0.0, 1e-15);

  const double g = 0.2;
  const ElementSolution s = solve_element(1.0, 0.7, d, g);
  ASSERT_TRUE(s.slip);
  EXPECT_NEAR(std::hypot(s.px, s.py), g, 1e-14);
  EXPECT_NEAR(s.sx, 1.0 + d[0] * s.px + d[1] * s.py, 1e-14);
  EXPECT_NEAR(s.sy, 0.7 + d[2] * s.px + d[3] * s.py, 1e-14);
  EXPECT_NEAR(s.px * s.sy - s.py * s.sx, 0.0, 1e-12);  // parallel ...
  EXPECT_LT(s.px * s.sx + s.py * s.sy, 0.0);           // ... and opposite

  const ElementSolution none = solve_element(1.0, 0.7, d, 0.0);  // no bound: free slip
  EXPECT_TRUE(none.slip);
  EXPECT_EQ(none.px, 0.0);
  EXPECT_EQ(none.sx, 1.0);
}

}  // namespace
}  // namespace rollcontact::tangential
