// The interfacial layer of M=4 (physics.md §12, spec-additions B4) on a single element loaded by
// shifts, where everything is a scalar: the layer's compliance h/G₃ in series with the
// half-space's, the yield limit τ_c0 capping the traction, and hardening k_τ making the
// traction rise with the accumulated plastic slip.

#include <gtest/gtest.h>

#include <cmath>

#include "rollcontact/solve.hpp"
#include "support/hertz_problem.hpp"

namespace rollcontact {
namespace {

constexpr double kG3 = 176.63, kThickness = 0.02;  // plastic_3bl's magnetite: G₃/h ≈ 8832 N/mm³

/// One 1 × 1 mm element under 900 N (plastic_3bl), μ = 0.7, shifted by `shift_mm` per case.
model::PatchProblem single_element(double shift_mm, bool layer, double tau_c0, double k_tau) {
  model::PatchProblem p = test::hertz_problem(0.5, 0.5, 900.0, 82000.0, 0.28, 1, 1, 1.0);
  p.tangential.kind = model::TangentialKind::Shift;
  p.tangential.creepage.longitudinal = -shift_mm;
  p.friction = {0.7, 0.7};
  p.solver.tolerance = 1e-10;
  p.bodies.has_layer = layer;
  p.bodies.layer = {kG3, kThickness, tau_c0, k_tau};
  return p;
}

TEST(InterfacialLayer, ComplianceAddsInSeriesWithTheHalfSpace) {
  const double w = 1e-3;  // mm: adhesion
  PatchSolver a, b;
  const Solution bare = a.solve(single_element(w, false, 0.0, 0.0));
  const Solution layered = b.solve(single_element(w, true, 0.0, 0.0));
  ASSERT_TRUE(bare.solver.converged && layered.solver.converged);
  ASSERT_EQ(layered.statistics.nadh, 1);
  // w = F·(c_el + h/G₃) per mm² of element: 1/F grows by (h/G₃)/w.
  const double area = bare.grid.element_area();
  EXPECT_NEAR(area / layered.totals.fx - area / bare.totals.fx, kThickness / kG3 / w, 1e-9);
  EXPECT_LT(layered.totals.fx, 0.12 * bare.totals.fx);  // the layer dominates: 85 vs ~ 900 N
}

TEST(InterfacialLayer, YieldLimitCapsTheTractionAndTheLayerFlows) {
  // τ_c0 = 560 N/mm² below μ·p = 630: shifts of 0.035 mm load the element elastically to
  // about 280 and 560 N/mm² (G/h of the whole ≈ 8000 N/mm³), then it flows; the flow is
  // plastic, not sliding, and takes what the elastic compliances do not.
  PatchSolver bare_solver;
  const Solution bare = bare_solver.solve(single_element(1e-3, false, 0.0, 0.0));
  const double compliance = 1e-3 / bare.totals.fx + kThickness / kG3;  // mm per N/mm²
  const double expected_flow = 3 * 0.035 - 560.0 * compliance;
  ASSERT_GT(expected_flow, 0.03);
  PatchSolver s;
  double total_flow = 0.0;
  for (int step = 1; step <= 3; ++step) {
    model::PatchProblem p = single_element(0.035, true, 560.0, 0.0);
    p.sequence.continue_previous = step > 1;
    const Solution sol = s.solve(p);
    ASSERT_TRUE(sol.solver.converged) << sol.solver.message;
    if (step < 3) {
      EXPECT_EQ(sol.statistics.nplast, 0);
      continue;
    }
    EXPECT_NEAR(sol.totals.fx, 560.0, 1e-6);
    EXPECT_EQ(sol.statistics.nplast, 1);
    EXPECT_EQ(sol.statistics.nslip, 0);
    EXPECT_EQ(sol.sx[0], 0.0);  // no sliding
    ASSERT_EQ(sol.plastic_x.size(), 1u);
    total_flow = sol.plastic_x[0];
    EXPECT_NEAR(sol.plastic_accumulated[0], expected_flow, 1e-9);
    // The work of the flow: 560 N over the flow (J).
    EXPECT_NEAR(std::abs(sol.totals.frictional_power), 560.0 * expected_flow * 1e-3, 1e-9);
  }
  EXPECT_NEAR(std::abs(total_flow), expected_flow, 1e-9);
}

TEST(InterfacialLayer, HardeningRaisesTheLimitWithTheAccumulatedFlow) {
  // Once flowing, every further shift Δw raises the traction by Δw/(c_el + h/G₃ + 1/k_τ):
  // the elastic compliances in series with the hardening one (spec-additions B4's k_u).
  const double tau0 = 200.0, k_tau = 435.0, dw = 0.01;
  PatchSolver bare_solver;
  const Solution bare = bare_solver.solve(single_element(1e-3, false, 0.0, 0.0));
  const double c_el = 1e-3 / bare.totals.fx;  // mm per N/mm² on the 1 mm² element
  PatchSolver s;
  std::vector<double> fx;
  for (int step = 1; step <= 6; ++step) {
    model::PatchProblem p = single_element(step == 1 ? 0.04 : dw, true, tau0, k_tau);
    p.sequence.continue_previous = step > 1;
    const Solution sol = s.solve(p);
    ASSERT_TRUE(sol.solver.converged) << sol.solver.message;
    EXPECT_EQ(sol.statistics.nplast, 1) << step;
    EXPECT_NEAR(sol.totals.fx, tau0 + k_tau * sol.plastic_accumulated[0], 1e-6);
    fx.push_back(sol.totals.fx);
  }
  const double slope = dw / (c_el + kThickness / kG3 + 1.0 / k_tau);
  for (std::size_t k = 2; k < fx.size(); ++k) EXPECT_NEAR(fx[k] - fx[k - 1], slope, 1e-6);
}

TEST(InterfacialLayer, WithoutComplianceOrYieldLimitItIsNoLayer) {
  // LAYTHK = 0 and TAU_C0 = 0 (no plasticity): M=4 must equal M=0 bit for bit, in steady rolling
  // with partial slip on a Hertzian contact.
  model::PatchProblem p = test::hertz_problem(0.6, 1.0, 1000.0, 82000.0, 0.28, 24, 30, 1.1);
  p.tangential.kind = model::TangentialKind::SteadyRolling;
  p.rolling.velocity_mm_per_s = 1000.0;
  p.rolling.step_mm = 2.0 * 1.1 * 0.6 / 24;
  p.tangential.creepage = {4e-4, -2e-4, 1e-4};
  PatchSolver a, b;
  const Solution bare = a.solve(p);
  p.bodies.has_layer = true;
  p.bodies.layer = {kG3, 0.0, 0.0, 0.0};
  const Solution layered = b.solve(p);
  ASSERT_TRUE(bare.solver.converged && layered.solver.converged);
  EXPECT_GT(bare.statistics.nslip, 0);
  EXPECT_EQ(layered.totals.fx, bare.totals.fx);
  EXPECT_EQ(layered.totals.fy, bare.totals.fy);
  EXPECT_EQ(layered.px, bare.px);
  EXPECT_EQ(layered.statistics.nplast, 0);
}

}  // namespace
}  // namespace rollcontact

namespace rollcontact {
namespace {

TEST(InterfacialLayer, SteadyRollingHardensAlongTheRows) {
  // Steady rolling through a hardening layer: a particle accumulates the flow of every element
  // it has passed, so in the plastic elements |p_t| = τ_c0 + k_τ·u*, with u* growing from the
  // leading edge (χ = 0: high ix) towards the trailing edge; softening (k_τ < 0) lowers FX.
  model::PatchProblem p = test::hertz_problem(0.6, 1.0, 1000.0, 82000.0, 0.28, 24, 30, 1.1);
  p.tangential.kind = model::TangentialKind::SteadyRolling;
  p.rolling.velocity_mm_per_s = 1000.0;
  p.rolling.step_mm = 2.0 * 1.1 * 0.6 / 24;
  p.tangential.creepage.longitudinal = 5e-3;
  p.friction = {0.7, 0.7};
  p.bodies.has_layer = true;
  p.bodies.layer = {kG3, kThickness, 30.0, 2000.0};
  PatchSolver s;
  const Solution sol = s.solve(p);
  ASSERT_TRUE(sol.solver.converged) << sol.solver.message;
  ASSERT_GT(sol.statistics.nplast, 0);
  const Grid& g = sol.grid;
  for (int iy = 0; iy < g.my; ++iy) {
    double previous = 0.0;
    for (int ix = g.mx - 1; ix >= 0; --ix) {  // from the leading edge
      const std::size_t i = g.index(ix, iy);
      EXPECT_GE(sol.plastic_accumulated[i], previous - 1e-15);
      previous = sol.plastic_accumulated[i];
      if (sol.state[i] != ElementState::Plastic) continue;
      EXPECT_NEAR(std::hypot(sol.px[i], sol.py[i]), 30.0 + 2000.0 * sol.plastic_accumulated[i],
                  1e-6 * 30.0);
    }
  }
  p.bodies.layer.hardening_N_mm3 = 0.0;
  PatchSolver s0;
  const Solution perfect = s0.solve(p);
  p.bodies.layer.hardening_N_mm3 = -500.0;
  PatchSolver s1;
  const Solution soft = s1.solve(p);
  ASSERT_TRUE(perfect.solver.converged && soft.solver.converged);
  EXPECT_GT(std::abs(sol.totals.fx), std::abs(perfect.totals.fx));
  EXPECT_LT(std::abs(soft.totals.fx), std::abs(perfect.totals.fx));
}

}  // namespace
}  // namespace rollcontact

namespace rollcontact {
namespace {

TEST(CompressibleLayer, AddsItsNormalComplianceInSeries) {
  // B=1: u_n += FLXZ·p_n. Under a prescribed force the approach grows by FLXZ·p_n on a single
  // element, and on a Hertzian grid a softer interface spreads the pressure (lower PMAX, larger
  // area) at the same force.
  const double flxz = 2e-5;  // mm³/N
  PatchSolver a, b;
  model::PatchProblem p = test::hertz_problem(0.5, 0.5, 900.0, 82000.0, 0.28, 1, 1, 1.0);
  const Solution bare = a.solve(p);
  p.bodies.normal_layer_flexibility_mm3_N = flxz;
  const Solution soft = b.solve(p);
  ASSERT_TRUE(bare.solver.converged && soft.solver.converged);
  const double pn = 900.0 / bare.grid.element_area();
  EXPECT_NEAR(soft.totals.pen - bare.totals.pen, flxz * pn, 1e-12);
  model::PatchProblem h = test::hertz_problem(3.0, 2.0, 10000.0, 82000.0, 0.28, 31, 31, 1.3);
  PatchSolver c, d;
  const Solution hertz = c.solve(h);
  h.bodies.normal_layer_flexibility_mm3_N = flxz;
  const Solution layered = d.solve(h);
  ASSERT_TRUE(hertz.solver.converged && layered.solver.converged);
  EXPECT_NEAR(layered.totals.fn, hertz.totals.fn, 1e-6 * hertz.totals.fn);
  EXPECT_LT(layered.totals.pmax, 0.99 * hertz.totals.pmax);
  EXPECT_GT(layered.statistics.ncon, hertz.statistics.ncon);
}

}  // namespace
}  // namespace rollcontact
