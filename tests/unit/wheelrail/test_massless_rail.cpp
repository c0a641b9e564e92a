// The massless rail (F=3, spec/wheelrail-advanced.md §2): the lateral iteration on analytic
// residuals, and the Manchester benchmark right wheel (mbench_a22_right.inp) on a rail that
// gives way: stiff springs give the rigid rail's answer, the balance equations hold at the answer,
// and two-patch flange contact converges.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <variant>

#include "format/inp/inp_reader.hpp"
#include "format/inp/to_wheelrail.hpp"
#include "rollcontact/errors.hpp"
#include "rollcontact/wheelrail.hpp"
#include "support/examples.hpp"
#include "wheelrail/massless_rail.hpp"
#include "wheelrail_problems.hpp"

namespace rollcontact {
namespace {

using wheelrail::LateralRailResult;
using wheelrail::LateralRailSettings;
using wheelrail::solve_lateral_rail;

TEST(LateralRailIteration, LinearResidualNeedsThreeEvaluations) {
  // r = 500 − 2e4·δy (a contact force that does not depend on δy): the spring's step is exact.
  LateralRailSettings st;
  st.stiffness_N_per_mm = 2e4;
  int calls = 0;
  const LateralRailResult r = solve_lateral_rail(st, [&](double x) {
    ++calls;
    return 500.0 - 2e4 * x;
  });
  EXPECT_TRUE(r.converged) << r.message;
  EXPECT_NEAR(r.dy_mm, 0.025, 1e-12);
  EXPECT_LE(calls, 2);
}

TEST(LateralRailIteration, NonlinearResidualIsBracketedAndSolved) {
  // A flange force that eases as the rail gives way, against a soft spring.
  LateralRailSettings st;
  st.stiffness_N_per_mm = 1e3;
  st.tolerance_N = 1e-6;
  st.tolerance_mm = 1e-9;
  auto f = [](double x) { return 9000.0 * std::exp(-2.0 * x) - 1e3 * x - 500.0; };
  const LateralRailResult r = solve_lateral_rail(st, f);
  ASSERT_TRUE(r.converged) << r.message;
  EXPECT_LT(std::abs(f(r.dy_mm)), 1e-3);
  EXPECT_LE(r.iterations, 12);
}

TEST(LateralRailIteration, WithoutSpringTheFirstStepIsDystep0) {
  // ky = 0: r = 2 − x³ rises nowhere; DYSTEP0 = 0.5 mm starts the search, secants bracket.
  LateralRailSettings st;
  st.first_step_mm = 0.5;
  st.tolerance_N = 1e-9;
  st.tolerance_mm = 1e-12;
  double second = 0.0;
  int calls = 0;
  const LateralRailResult r = solve_lateral_rail(st, [&](double x) {
    if (++calls == 2) second = x;
    return 2.0 - x * x * x;
  });
  ASSERT_TRUE(r.converged) << r.message;
  EXPECT_DOUBLE_EQ(second, 0.5);
  EXPECT_NEAR(r.dy_mm, std::cbrt(2.0), 1e-6);
}

TEST(LateralRailIteration, ASpringStepBeyondThreeMillimetresIsDystep0) {
  // A soft rail (1 kN/mm) under a contact force of 3.5 MN at δy = 0 that vanishes within a few
  // millimetres (the contact is lost as the rail gives way): the spring alone would move the
  // rail by 3.5 m, leaving a bracket that MAXNR bisections cannot close (a random case). Such a
  // step is DYSTEP0 instead (wheelrail-advanced.md §2.5: early steps at most 3 mm).
  LateralRailSettings st;
  st.stiffness_N_per_mm = 1e3;
  st.first_step_mm = 1.0;
  double second = 0.0;
  int calls = 0;
  const auto residual = [&](double x) {
    if (++calls == 2) second = x;
    const double contact = x > -2.0 ? -3.5e6 * (x + 2.0) / 2.0 : 0.0;  // eases to 0 at −2 mm
    return 9526.0 + 1e3 * (-x) + contact;                              // preload, spring, contact
  };
  const LateralRailResult r = solve_lateral_rail(st, residual);
  ASSERT_TRUE(r.converged) << r.message;
  EXPECT_DOUBLE_EQ(second, -1.0);
  EXPECT_NEAR(residual(r.dy_mm), 0.0, 1e-3 * 9526.0);
}

TEST(LateralRailIteration, AJumpInTheForceIsReportedNotHidden) {
  LateralRailSettings st;
  st.stiffness_N_per_mm = 10.0;
  st.tolerance_mm = 1e-6;
  const LateralRailResult r =
      solve_lateral_rail(st, [](double x) { return (x < 0.3 ? 1000.0 : -1000.0) - 10.0 * x; });
  EXPECT_TRUE(r.converged);
  EXPECT_NEAR(r.dy_mm, 0.3, 1e-5);
  EXPECT_NE(r.message.find("jumps"), std::string::npos) << r.message;
}

TEST(LateralRailIteration, StopsAtMaxnrWithAMessage) {
  LateralRailSettings st;
  st.max_iterations = 5;
  const LateralRailResult r = solve_lateral_rail(st, [](double) { return 1.0; });
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.iterations, 5);
  EXPECT_NE(r.message.find("MAXNR"), std::string::npos);
}

// ----- the Manchester benchmark on a massless rail -----

/// Case `k` (1-based; y_ws = 0.5·(k − 1) mm) of mbench_a22_right.inp.
model::WheelRailProblem benchmark_case(int k) {
  const auto cases = format::read_input_cases(test_support::kExamples / "mbench_a22_right.inp");
  return format::to_wheelrail_problem(
      std::get<format::WheelRailRecord>(cases.at(static_cast<std::size_t>(k - 1))));
}

model::WheelRailProblem on_massless_rail(model::WheelRailProblem p, double ky, double fy, double kz,
                                         double fz) {
  p.massless_rail = {true, ky, fy, kz, fz, 1.0};
  return p;
}

double lateral_balance(const WheelRailSolution& s) {
  const RailDeflection& d = s.rail_deflection;
  return s.force_tr.y - d.ky_N_per_mm * d.dy_mm + d.fy_N;
}

TEST(MasslessRail, StiffSpringsGiveTheRigidRail) {
  REQUIRE_EXAMPLES();
  for (int k : {7, 19}) {  // y_ws = 3 mm (tread), 9 mm (tread and flange)
    const model::WheelRailProblem rigid = benchmark_case(k);
    const WheelRailSolution a = WheelsetSolver().solve(rigid);
    const WheelRailSolution b =
        WheelsetSolver().solve(on_massless_rail(rigid, 1e12, 0.0, 1e12, 0.0));
    ASSERT_TRUE(a.converged && b.converged) << a.message << b.message;
    ASSERT_EQ(a.patches.size(), b.patches.size());
    EXPECT_LT(std::abs(b.rail_deflection.dy_mm), 1e-7);
    EXPECT_LT(std::abs(b.rail_deflection.dz_mm), 1e-7);
    // Both meet F_z within EPS·FZ (1e-5 of 10 kN) by iterations that take different paths:
    // they agree to twice that, and the other forces with them.
    const double scale = std::abs(a.force_tr.z), tolerance = 2.0 * rigid.patch.solver.tolerance;
    EXPECT_NEAR(b.force_tr.x, a.force_tr.x, tolerance * scale) << "case " << k;
    EXPECT_NEAR(b.force_tr.y, a.force_tr.y, tolerance * scale) << "case " << k;
    EXPECT_NEAR(b.force_tr.z, a.force_tr.z, tolerance * scale) << "case " << k;
    // The rail sinks by δz, the wheel with it.
    EXPECT_NEAR(b.z_ws_mm, a.z_ws_mm + b.rail_deflection.dz_mm, 1e-6);
  }
}

TEST(MasslessRail, PrescribedForceGivesDzDirectlyAndBalancesLaterally) {
  REQUIRE_EXAMPLES();
  const model::WheelRailProblem rigid = benchmark_case(7);  // y_ws = 3 mm, one patch
  const double ky = 2e4, fy = 1000.0, kz = 2e5, fz = 500.0;
  WheelsetSolver solver;
  const WheelRailSolution s = solver.solve(on_massless_rail(rigid, ky, fy, kz, fz));
  ASSERT_TRUE(s.converged) << s.message;
  const RailDeflection& d = s.rail_deflection;
  ASSERT_TRUE(d.active);
  EXPECT_DOUBLE_EQ(d.dz_mm, (rigid.motion.fz_N + fz) / kz);
  EXPECT_NEAR(s.force_tr.z, rigid.motion.fz_N, 1e-5 * rigid.motion.fz_N);
  // The tolerance on δy is EPS [mm]: the residual is within the balance's slope times EPS.
  const double eps = rigid.patch.solver.tolerance;
  EXPECT_LT(std::abs(lateral_balance(s)), std::max(eps * std::abs(fy), 2.0 * ky * eps));
  EXPECT_DOUBLE_EQ(d.residual_y_N, lateral_balance(s));
  // The rail gives way in the direction of F_y(tr) + FYRAIL.
  EXPECT_GT(d.dy_mm * (s.force_tr.y + fy), 0.0);
  // The rail moved: its marker carries the deflections.
  const WheelRailSolution r = WheelsetSolver().solve(rigid);
  EXPECT_NEAR(s.rail_marker_tr.position.y - r.rail_marker_tr.position.y, d.dy_mm, 1e-12);
  EXPECT_NEAR(s.rail_marker_tr.position.z - r.rail_marker_tr.position.z, d.dz_mm, 1e-12);
}

TEST(MasslessRail, WithoutLateralSpringTheRailLoadIsTheContactForce) {
  REQUIRE_EXAMPLES();
  // KYRAIL = 0: F_y(tr) = −FYRAIL; the wheel climbs into the flange until it carries 9 kN.
  const model::WheelRailProblem rigid = benchmark_case(19);
  const double fy = -9000.0;
  const WheelRailSolution s = WheelsetSolver().solve(on_massless_rail(rigid, 0.0, fy, 1e5, 0.0));
  ASSERT_TRUE(s.converged) << s.message;
  const double eps = rigid.patch.solver.tolerance;
  EXPECT_NEAR(s.force_tr.y, -fy, std::max(1e-6, eps * std::abs(fy)) + 1.0);
  EXPECT_LE(s.rail_deflection.iterations, rigid.patch.solver.max_newton_iterations);
}

/// Checks the balance equations of a converged massless-rail case within the iteration's
/// tolerances: |r_y| within the balance's slope (≥ ky) times EPS [mm], r_z within EPS·FZ.
void expect_balanced(const WheelRailSolution& s, const model::WheelRailProblem& p,
                     const std::string& what) {
  ASSERT_TRUE(s.converged) << what << ": " << s.message;
  const RailDeflection& d = s.rail_deflection;
  const double eps = p.patch.solver.tolerance;
  EXPECT_LE(d.iterations, p.patch.solver.max_newton_iterations) << what;
  EXPECT_LT(std::abs(d.residual_y_N), std::max(2.0 * d.ky_N_per_mm * eps, eps * std::abs(d.fy_N)))
      << what;
  EXPECT_NEAR(d.residual_y_N, lateral_balance(s), 1e-9) << what;
  EXPECT_LT(std::abs(d.residual_z_N), eps * p.motion.fz_N) << what;
}

TEST(MasslessRail, FlangeContactConvergesForStiffAndSoftRails) {
  REQUIRE_EXAMPLES();
  // y_ws = 8, 9, 10 mm: the flange alone carries the wheel (one patch, δ ≈ −0.8..−0.95 rad, as
  // in CONTACT's reference); the rail gives way by F_y/ky.
  for (int k : {17, 19, 21}) {
    const model::WheelRailProblem rigid = benchmark_case(k);
    for (double ky : {1e4, 3e4, 1e5}) {
      const std::string what = "case " + std::to_string(k) + ", ky " + std::to_string(ky);
      const WheelRailSolution s =
          WheelsetSolver().solve(on_massless_rail(rigid, ky, 0.0, 1e5, 0.0));
      expect_balanced(s, rigid, what);
      ASSERT_EQ(s.patches.size(), 1U) << what;
      EXPECT_LT(s.patches[0].contact_angle_rad, -0.7) << what;
      EXPECT_GT(s.rail_deflection.dy_mm, 0.0) << what;
      std::printf("    %s: %d iterates, dy_defl %.5f mm, FY %.1f N, r_y %.3g N\n", what.c_str(),
                  s.rail_deflection.iterations, s.rail_deflection.dy_mm, s.force_tr.y,
                  s.rail_deflection.residual_y_N);
    }
  }
}

TEST(MasslessRail, TwoPatchContactConverges) {
  REQUIRE_EXAMPLES();
  // y_ws = 5 mm, yaw 12 mrad with D_SEP = 6, D_COMB = 3 mm (as mbench_a22_varfric case 3): tread
  // and flange root are two patches.
  model::WheelRailProblem rigid = benchmark_case(11);
  rigid.search.d_sep_mm = 6.0;
  rigid.search.d_comb_mm = 3.0;
  rigid.search.d_turn_mm = 9.0;
  // The patches lie between D_SEP and D_TURN: the .inp route refuses the turned angles (not
  // CONTACT's rule yet); the balance of the rail is what this test checks.
  rigid.validated_only = false;
  for (double ky : {1e4, 3e4, 1e5}) {
    const std::string what = "ky " + std::to_string(ky);
    const WheelRailSolution s = WheelsetSolver().solve(on_massless_rail(rigid, ky, 0.0, 1e5, 0.0));
    expect_balanced(s, rigid, what);
    EXPECT_EQ(s.patches.size(), 2U) << what;
    std::printf("    %s: %zu patches, %d iterates, dy_defl %.5f mm, FY %.1f N, r_y %.3g N\n",
                what.c_str(), s.patches.size(), s.rail_deflection.iterations,
                s.rail_deflection.dy_mm, s.force_tr.y, s.rail_deflection.residual_y_N);
  }
}

TEST(MasslessRail, PrescribedPositionSolvesTheVerticalSpring) {
  REQUIRE_EXAMPLES();
  // N=0: the wheel 0.1 mm deeper than the rigid rail's answer for 10 kN; the rail sinks.
  model::WheelRailProblem rigid = benchmark_case(7);
  const WheelRailSolution r = WheelsetSolver().solve(rigid);
  ASSERT_TRUE(r.converged);
  rigid.vertical = model::VerticalLoading::Position;
  rigid.motion.z_mm = r.z_ws_mm + 0.1;
  const double kz = 1e5, fz = 300.0;
  const WheelRailSolution s = WheelsetSolver().solve(on_massless_rail(rigid, 5e4, 0.0, kz, fz));
  ASSERT_TRUE(s.converged) << s.message;
  const RailDeflection& d = s.rail_deflection;
  EXPECT_NEAR(s.z_ws_mm, rigid.motion.z_mm, 1e-12);
  EXPECT_GT(d.dz_mm, 0.0);
  EXPECT_LT(std::abs(s.force_tr.z - kz * d.dz_mm + fz), 1e-4 * std::abs(s.force_tr.z));
  EXPECT_DOUBLE_EQ(d.residual_z_N, s.force_tr.z - kz * d.dz_mm + fz);
}

TEST(MasslessRail, LeftWheelIsTheMirrorImage) {
  // Inputs and outputs are track coordinates: the mirrored left case deflects the rail by −δy.
  model::WheelRailProblem right = test_support::yawed_conical_wheel();
  right = on_massless_rail(right, 2e4, 800.0, 1e5, 200.0);
  const model::WheelRailProblem left = test_support::mirrored_left(right);
  const WheelRailSolution r = WheelsetSolver().solve(right), l = WheelsetSolver().solve(left);
  ASSERT_TRUE(r.converged && l.converged) << r.message << l.message;
  EXPECT_NE(r.rail_deflection.dy_mm, 0.0);
  EXPECT_EQ(l.rail_deflection.dy_mm, -r.rail_deflection.dy_mm);
  EXPECT_EQ(l.rail_deflection.dz_mm, r.rail_deflection.dz_mm);
  EXPECT_EQ(l.force_tr.y, -r.force_tr.y);
  EXPECT_EQ(l.rail_marker_tr.position.y, -r.rail_marker_tr.position.y);
  EXPECT_EQ(l.rail_deflection.residual_y_N, -r.rail_deflection.residual_y_N);
}

TEST(MasslessRail, InadmissibleInputsAreRefused) {
  REQUIRE_EXAMPLES();
  model::WheelRailProblem p = on_massless_rail(benchmark_case(1), 1e4, 0.0, 0.0, 0.0);
  p.vertical = model::VerticalLoading::Position;  // N=0 and KZRAIL = 0: no vertical equation
  EXPECT_THROW(WheelsetSolver().solve(p), ProblemError);
  p = on_massless_rail(benchmark_case(1), 1e4, 0.0, 1e5, 0.0);
  p.patch.tangential.kind = model::TangentialKind::None;  // T=0
  EXPECT_THROW(WheelsetSolver().solve(p), ProblemError);
}

}  // namespace
}  // namespace rollcontact
