// Velocity-dependent friction (physics.md §10.2-10.3): the memory relaxation along a row, the
// fixed point on slip velocities reducing to Coulomb's law for a flat law, full sliding at the
// friction of the rigid slip velocity, and a fixed point cut short reported as not converged.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "contact/slip_velocity_iteration.hpp"
#include "physics/friction_law.hpp"
#include "rollcontact/solve.hpp"
#include "support/hertz_problem.hpp"

namespace rollcontact {
namespace {

model::Friction exponential(double fkin, double f1, double s1_mm_s) {
  model::Friction f;
  f.law = model::FrictionLawKind::ExponentialFalling;
  f.kinetic_coefficient = fkin;
  f.terms = {model::FallingTerm{f1, s1_mm_s}, model::FallingTerm{0.0, 1e-4}};
  f.static_coefficient = fkin + f1;
  return f;
}

TEST(FrictionMemory, RelaxesGeometricallyFromTheLeadingEdge) {
  // Constant slip velocity along a row: μ′ of the leading element is μ_static, each next one
  // relaxes from its upstream neighbour, so μ_k − μ(s) = θ^(k+1)·(μ_static − μ(s)).
  const Grid grid{5, 1, -2.5, -0.5, 1.0, 1.0};
  const std::vector<char> contact(5, 1);
  const model::Friction f = exponential(0.18, 0.12, 100.0);
  const auto law = physics::make_friction_law(f);
  contact::FrictionMemoryInput in;
  in.grid = &grid;
  in.contact = &contact;
  in.law = law.get();
  in.memory_distance_mm = 0.003;
  in.memory_floor_speed_mm_s = 1.0;
  in.dt_s = 1e-4;
  in.steady = true;
  const double s = 50.0;
  const contact::FrictionField field = contact::friction_with_memory(in, std::vector(5, s));
  const double theta = 0.003 / (0.003 + 1e-4 * s), mu_s = law->coefficient_at(s);
  for (int k = 0; k < 5; ++k) {  // χ = 0: the leading edge is at the highest ix
    const double expected = mu_s + std::pow(theta, k + 1) * (0.30 - mu_s);
    EXPECT_NEAR(field.mu[static_cast<std::size_t>(4 - k)], expected, 1e-15) << k;
  }
  // Without memory μ is the law's value everywhere.
  in.memory_distance_mm = 0.0;
  for (double mu : contact::friction_with_memory(in, std::vector(5, s)).mu)
    EXPECT_NEAR(mu, mu_s, 1e-15);
}

model::PatchProblem steady_case(const model::Friction& f, double cksi) {
  model::PatchProblem p = test::hertz_problem(0.6, 1.0, 1000.0, 82000.0, 0.28, 24, 30, 1.1);
  p.tangential.kind = model::TangentialKind::SteadyRolling;
  p.rolling.velocity_mm_per_s = 1000.0;
  p.rolling.step_mm = 2.0 * 1.1 * 0.6 / 24;
  p.tangential.creepage.longitudinal = cksi;
  p.friction = f;
  p.solver.tolerance = 1e-9;
  return p;
}

TEST(VelocityDependentFriction, FlatLawIsCoulombsLaw) {
  // Zero slopes (F1 = F2 = 0): μ(s_a) = FKIN everywhere for L = 2, 3 and 4 alike, so the fixed
  // point must give Coulomb's solution.
  const double cksi = 4e-4;  // partial slip
  PatchSolver a;
  const Solution coulomb = a.solve(steady_case(model::Friction{0.3, 0.3}, cksi));
  ASSERT_TRUE(coulomb.solver.converged);
  EXPECT_GT(coulomb.statistics.nslip, 0);
  EXPECT_GT(coulomb.statistics.nadh, 0);
  for (const auto kind :
       {model::FrictionLawKind::LinearFalling, model::FrictionLawKind::RationalFalling,
        model::FrictionLawKind::ExponentialFalling}) {
    model::Friction f = exponential(0.3, 0.0, 100.0);
    f.law = kind;
    PatchSolver b;
    const Solution flat = b.solve(steady_case(f, cksi));
    ASSERT_TRUE(flat.solver.converged) << flat.solver.message;
    EXPECT_NEAR(flat.totals.fx, coulomb.totals.fx, 1e-7 * coulomb.totals.fn);
    EXPECT_LE(flat.solver.slip_velocity_passes, 3);
  }
}

TEST(VelocityDependentFriction, CreepCurvePeaksWhereTheLawSays) {
  // One element under shifts (s_a = |S| per 1 s step): F = K·w while it sticks, so the creep
  // curve peaks at w* = μ_static·FN/K with F = μ_static·FN, and beyond it the element slides with
  // F = μ(w − F/K)·FN, a scalar equation checked here by bisection.
  const model::Friction f = exponential(0.18, 0.12, 0.01);  // falls over 0.01 mm/s
  const auto law = physics::make_friction_law(f);
  auto solve_shift = [&](double w) {
    model::PatchProblem p = test::hertz_problem(0.5, 0.5, 900.0, 82000.0, 0.28, 1, 1, 1.0);
    p.tangential.kind = model::TangentialKind::Shift;
    p.tangential.creepage.longitudinal = w;
    p.friction = f;
    p.solver.tolerance = 1e-12;
    p.solver.initial_slip_velocity = model::InitialSlipVelocity::Zero;
    PatchSolver s;
    return s.solve(p);
  };
  const Solution elastic = solve_shift(1e-6);
  const double fn = elastic.totals.fn, k = std::abs(elastic.totals.fx) / 1e-6;  // N/mm
  const double w_peak = 0.30 * fn / k;
  double best_w = 0.0, best_f = 0.0;
  for (double w = 0.2 * w_peak; w <= 3.0 * w_peak; w += 0.05 * w_peak) {
    const Solution sol = solve_shift(w);
    ASSERT_TRUE(sol.solver.converged) << sol.solver.message;
    const double force = std::abs(sol.totals.fx);
    if (force > best_f) best_f = force, best_w = w;
    if (w > 1.01 * w_peak) {  // sliding: F = μ(w − F/K)·FN
      double lo = 0.18 * fn, hi = 0.30 * fn;
      for (int it = 0; it < 200; ++it) {
        const double mid = 0.5 * (lo + hi);
        (mid - law->coefficient_at(w - mid / k) * fn > 0.0 ? hi : lo) = mid;
      }
      // The fixed point stops at ‖Δs_a‖ ≤ 0.001·‖s_a‖, which leaves μ·FN within a few 1e-5·FN
      // of the exact root here (measured 8.8e-6·FN at most).
      EXPECT_NEAR(force, 0.5 * (lo + hi), 2e-5 * fn) << w / w_peak;
    }
  }
  EXPECT_NEAR(best_w, w_peak, 0.05 * w_peak);
  EXPECT_NEAR(best_f, 0.30 * fn, 0.01 * fn);
}

TEST(VelocityDependentFriction, FullSlidingTakesTheFrictionOfTheRigidSlipVelocity) {
  // ξ = 0.2 at V = 1000 mm/s: everything slides at s_a ≈ ξV = 200 mm/s (the elastic part of the
  // slip is about μ p₀/G ≈ 0.5 % of ξ), so FX ≈ −μ(ξV)·FN = −(0.18 + 0.12/4)·FN, well below the
  // static 0.30 and the kinetic 0.18 bounds of the law.
  const model::Friction f = exponential(0.18, 0.12, 100.0);
  PatchSolver s;
  const Solution sol = s.solve(steady_case(f, 0.2));
  ASSERT_TRUE(sol.solver.converged) << sol.solver.message;
  EXPECT_EQ(sol.statistics.nadh, 0);
  EXPECT_NEAR(-sol.totals.fx / sol.totals.fn, 0.21, 0.21 * 5e-3);
  ASSERT_EQ(sol.mu.size(), sol.grid.size());
  for (std::size_t i = 0; i < sol.mu.size(); ++i) {
    if (sol.pn[i] > 0.0) {
      EXPECT_NEAR(sol.mu[i], 0.21, 0.21 * 1e-2);
    }
  }
  // A falling creep curve: more creepage, less force.
  PatchSolver s2;
  const Solution faster = s2.solve(steady_case(f, 0.4));
  ASSERT_TRUE(faster.solver.converged);
  EXPECT_LT(-faster.totals.fx, -sol.totals.fx);
}

TEST(VelocityDependentFriction, FixedPointCutShortIsNotConverged) {
  // Partial slip from zero slip velocity needs several passes; one pass must not be reported
  // as a solution.
  model::PatchProblem p = steady_case(exponential(0.18, 0.12, 100.0), 1e-3);
  p.solver.max_slip_velocity_passes = 1;
  PatchSolver s;
  const Solution sol = s.solve(p);
  EXPECT_FALSE(sol.solver.converged);
  EXPECT_NE(sol.solver.message.find("slip-velocity iteration"), std::string::npos);
  p.solver.max_slip_velocity_passes = 90;
  PatchSolver s2;
  const Solution full = s2.solve(p);
  EXPECT_TRUE(full.solver.converged) << full.solver.message;
  EXPECT_GT(full.solver.slip_velocity_passes, 1);
}

model::PatchProblem fastsim_case(const model::Friction& f, double cksi) {
  model::PatchProblem p = steady_case(f, cksi);
  p.bodies.compliance = model::TangentialCompliance::FastsimThreeFlexibilities;
  return p;
}

TEST(VelocityDependentFastsim, FlatLawIsCoulombsLaw) {
  for (const double cksi : {2e-4, 1e-3, 0.05}) {
    PatchSolver a, b;
    const Solution coulomb = a.solve(fastsim_case(model::Friction{0.3, 0.3}, cksi));
    const Solution flat = b.solve(fastsim_case(exponential(0.3, 0.0, 100.0), cksi));
    ASSERT_TRUE(coulomb.solver.converged && flat.solver.converged);
    EXPECT_NEAR(flat.totals.fx, coulomb.totals.fx, 1e-12 * coulomb.totals.fn) << cksi;
  }
}

TEST(VelocityDependentFastsim, EveryElementTakesTheLawAtItsRigidSlipVelocity) {
  // CONTACT's Fastsim (docs/decisions.md): μ_I = θ·μ′_I + (1 − θ)·μ_s(V·|w|) with the rigid slip
  // velocity V·|w| = V·ξ here (no spin), θ = d_c/(d_c + δt·max(Vξ, s₀)), μ′ the upstream
  // element's μ and μ_static for the first element of a row; the bound μ_I·p_n holds in
  // adhesion and in slip. Without memory (d_c = 0) μ = μ_s(Vξ) everywhere and full sliding gives
  // FX = −μ_s(Vξ)·FN exactly; with memory μ falls from μ_static at the leading edge to μ_s(Vξ)
  // by the factor θ per element.
  model::Friction f = exponential(0.18, 0.12, 100.0);
  const auto law = physics::make_friction_law(f);
  for (const double cksi : {1e-3, 0.2}) {
    PatchSolver s;
    const Solution sol = s.solve(fastsim_case(f, cksi));
    ASSERT_TRUE(sol.solver.converged);
    ASSERT_EQ(sol.mu.size(), sol.grid.size());
    const double mu_rigid = law->coefficient_at(cksi * sol.kinematics.veloc);
    int slipping = 0;
    for (std::size_t i = 0; i < sol.mu.size(); ++i) {
      if (sol.pn[i] <= 0.0) continue;
      EXPECT_NEAR(sol.mu[i], mu_rigid, 1e-12);
      if (sol.state[i] == ElementState::Slip) {
        ++slipping;
        EXPECT_NEAR(std::hypot(sol.px[i], sol.py[i]), sol.mu[i] * sol.pn[i], 1e-9 * sol.pn[i]);
      }
    }
    EXPECT_GT(slipping, 0);
    if (cksi == 0.2) {
      EXPECT_EQ(sol.statistics.nadh, 0);
      EXPECT_NEAR(-sol.totals.fx / sol.totals.fn, mu_rigid, 1e-9);
    }
  }
  // With memory the first element of a row enters with μ_s at its own rigid slip velocity (the
  // memory starts in the steady state, as CONTACT's tractcurv cases show), so under a uniform
  // rigid slip μ = μ_s(Vξ) everywhere; with spin the rigid slip varies across the patch and
  // along each row μ_I = θ_I·μ_{I−1} + (1 − θ_I)·μ_s(s_I), s_I = V·|w_I|.
  f.memory_distance_mm = 0.003;
  f.memory_floor_speed_mm_s = 1.0;
  PatchSolver m;
  const Solution mem = m.solve(fastsim_case(f, 0.05));
  ASSERT_TRUE(mem.solver.converged);
  const double mu_uniform = law->coefficient_at(0.05 * mem.kinematics.veloc);
  for (std::size_t i = 0; i < mem.mu.size(); ++i) {
    if (mem.pn[i] > 0.0) {
      EXPECT_NEAR(mem.mu[i], mu_uniform, 1e-12);
    }
  }
  model::PatchProblem spin = fastsim_case(f, 0.002);
  spin.tangential.creepage.spin_rad_per_mm = 2e-4;
  PatchSolver sp;
  const Solution ss = sp.solve(spin);
  ASSERT_TRUE(ss.solver.converged);
  const double v = ss.kinematics.veloc, dt = ss.kinematics.dt, dq = ss.kinematics.dq;
  int checked = 0;
  for (int iy = 0; iy < ss.grid.my; ++iy) {
    double prev = -1.0;
    for (int ix = ss.grid.mx - 1; ix >= 0; --ix) {
      const std::size_t i = ss.grid.index(ix, iy);
      if (ss.pn[i] <= 0.0) {
        prev = -1.0;
        continue;
      }
      // Rigid slip w = (ξ − φ·y, φ·(x + δq/6)) (FACPHI offset along χ = 0).
      const double x = ss.grid.x_centre(ix) + dq / 6.0, y = ss.grid.y_centre(iy);
      const double s_i = v * std::hypot(0.002 - 2e-4 * y, 2e-4 * x);
      const double theta = 0.003 / (0.003 + dt * std::max(s_i, 1.0));
      const double mu_s = law->coefficient_at(s_i);
      const double expected = prev < 0.0 ? mu_s : theta * prev + (1.0 - theta) * mu_s;
      EXPECT_NEAR(ss.mu[i], expected, 1e-9) << ix << ", " << iy;
      prev = ss.mu[i];
      ++checked;
    }
  }
  EXPECT_GT(checked, 100);
}

// Transient rolling (T=2) and shifts (T=1) with Fastsim and a falling law carry each particle's
// friction memory along with it (its μ one step upstream) and start a particle entering the
// contact with μ_s at its own rigid slip velocity, as steady rolling starts a row: rolling at
// constant creepage with δq = δx for more steps than the patch is long ends exactly in the
// steady state, element by element.
TEST(VelocityDependentFastsim, TransientRollingEndsInTheSteadyState) {
  model::Friction f = exponential(0.18, 0.12, 100.0);
  f.memory_distance_mm = 0.003;
  f.memory_floor_speed_mm_s = 1.0;
  model::PatchProblem steady = fastsim_case(f, 0.002);
  steady.tangential.creepage.spin_rad_per_mm = 2e-4;  // μ varies across the patch
  PatchSolver a;
  const Solution target = a.solve(steady);
  ASSERT_TRUE(target.solver.converged);
  model::PatchProblem step = steady;
  step.tangential.kind = model::TangentialKind::TransientRolling;
  PatchSolver b;
  Solution s;
  for (int k = 0; k < target.grid.mx + 2; ++k) {
    step.sequence.continue_previous = k > 0;
    s = b.solve(step);
    ASSERT_TRUE(s.solver.converged) << k;
  }
  ASSERT_EQ(s.mu.size(), target.mu.size());
  double largest = 0.0, worst = 0.0, worst_mu = 0.0;
  for (std::size_t i = 0; i < s.px.size(); ++i) {
    largest = std::max(largest, std::hypot(target.px[i], target.py[i]));
    worst = std::max(worst, std::hypot(s.px[i] - target.px[i], s.py[i] - target.py[i]));
    if (target.pn[i] > 0.0) worst_mu = std::max(worst_mu, std::abs(s.mu[i] - target.mu[i]));
  }
  EXPECT_LT(worst, 1e-12 * largest);
  EXPECT_LT(worst_mu, 1e-14);
  EXPECT_NEAR(s.totals.fx, target.totals.fx, 1e-12 * std::abs(target.totals.fx));
  // A shift keeps each particle's memory where it is: shifting on with the same increment
  // from a state reached by shifting, the elements keep their μ unless they slid.
  model::PatchProblem shift = steady;
  shift.tangential.kind = model::TangentialKind::Shift;
  shift.tangential.creepage = {1e-4, 0.0, 0.0};
  PatchSolver c;
  const Solution first = c.solve(shift);
  shift.sequence.continue_previous = true;
  const Solution second = c.solve(shift);
  ASSERT_TRUE(first.solver.converged && second.solver.converged);
  EXPECT_GT(std::abs(second.totals.fx), std::abs(first.totals.fx));
}

}  // namespace
}  // namespace rollcontact
