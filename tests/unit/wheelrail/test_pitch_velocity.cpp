// A prescribed longitudinal force (F=1, spec-additions §A6): the pitch-velocity iteration on
// analytic force curves, the inverse of a pitch velocity given (F=0 then F=1 with its force
// gives that pitch velocity back), and the S1002-on-UIC60 case that CONTACT solved with F1=1 for
// the Ma et al. (2018) study (spec/dynamic-rolling.md §6.2).

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <variant>

#include "format/inp/inp_reader.hpp"
#include "format/inp/to_wheelrail.hpp"
#include "rollcontact/errors.hpp"
#include "rollcontact/wheelrail.hpp"
#include "support/examples.hpp"
#include "wheelrail/pitch_velocity.hpp"

namespace rollcontact {
namespace {

using wheelrail::inverse_saturation;
using wheelrail::PitchVelocitySample;
using wheelrail::PitchVelocitySettings;
using wheelrail::solve_pitch_velocity;

TEST(PitchVelocityIteration, InverseSaturationInvertsTheCurve) {
  for (double y = -0.99; y < 0.995; y += 0.03) {
    const double u = inverse_saturation(y);
    EXPECT_NEAR(u - u * std::abs(u) / 3.0 + u * u * u / 27.0, y, 1e-12) << y;
  }
  EXPECT_DOUBLE_EQ(inverse_saturation(2.0), inverse_saturation(0.999));
}

/// A creep curve of another shape than the iteration's model: F_x/F_z = μ·tanh(k(ω − ω0)/μ).
struct TanhCurve {
  double mu = 0.5, k = 2.6, omega0 = -84.54;
  double operator()(double omega) const { return mu * std::tanh(k * (omega - omega0) / mu); }
};

PitchVelocitySettings settings_for(const TanhCurve& c, double target) {
  PitchVelocitySettings st;
  st.start_rad_s = c.omega0 - 0.01;  // not quite free rolling
  st.target = target;
  st.slope_s_per_rad = 0.8 * c.k;  // linear theory is an estimate
  st.saturation = c.mu;
  st.max_jump = c.mu;
  st.tolerance = 1e-5 * c.mu;
  st.max_step_rad_s = 0.8;
  return st;
}

TEST(PitchVelocityIteration, SaturatingForceConvergesInFewSolves) {
  const TanhCurve c;
  for (double target : {-0.45, -0.25, 0.05, 0.3, 0.47}) {
    const PitchVelocitySettings st = settings_for(c, target);
    int solves = 0;
    const auto solve = [&](double omega, double) {
      ++solves;
      return PitchVelocitySample{c(omega), true};
    };
    const wheelrail::PitchVelocityResult r =
        solve_pitch_velocity(st, solve(st.start_rad_s, 0.0), solve);
    ASSERT_TRUE(r.converged) << target << ": " << r.message;
    EXPECT_LT(std::abs(c(r.vpitch_rad_s) - target), st.tolerance) << target;
    const double exact = c.omega0 + c.mu / c.k * std::atanh(target / c.mu);
    EXPECT_NEAR(r.vpitch_rad_s, exact, st.tolerance / (c.k * 0.05)) << target;
    EXPECT_LE(solves, 9) << target;
  }
}

TEST(PitchVelocityIteration, BeyondFrictionIsReportedNotConverged) {
  const TanhCurve c;
  PitchVelocitySettings st = settings_for(c, -0.6);  // more than μ·F_z
  st.max_iterations = 12;
  const auto solve = [&](double omega, double) { return PitchVelocitySample{c(omega), true}; };
  const wheelrail::PitchVelocityResult r =
      solve_pitch_velocity(st, solve(st.start_rad_s, 0.0), solve);
  EXPECT_FALSE(r.converged);
  EXPECT_NE(r.message.find("MAXNR"), std::string::npos) << r.message;
  EXPECT_LT(std::abs(r.residual), 0.11);  // it went as far as friction allows
}

TEST(PitchVelocityIteration, ANonConvergedSolveStopsTheIteration) {
  const TanhCurve c;
  const PitchVelocitySettings st = settings_for(c, -0.25);
  const auto solve = [&](double, double) { return PitchVelocitySample{0.0, false}; };
  const wheelrail::PitchVelocityResult r =
      solve_pitch_velocity(st, PitchVelocitySample{c(st.start_rad_s), true}, solve);
  EXPECT_FALSE(r.converged);
  EXPECT_FALSE(r.message.empty());
}

// ----- the wheel/rail solver -----

/// Case 1 of mbench_a22_right.inp (S1002 on the pre-canted UIC60 file, centred wheelset) with
/// the steel, friction, load and speed of the Ma et al. study (spec/dynamic-rolling.md §2.4).
model::WheelRailProblem ma_et_al_proxy(double dx_mm, double fz_N) {
  const auto cases = format::read_input_cases(test_support::kExamples / "mbench_a22_right.inp");
  model::WheelRailProblem p =
      format::to_wheelrail_problem(std::get<format::WheelRailRecord>(cases.at(0)));
  p.patch.bodies.body1 = p.patch.bodies.body2 = {0.3, 80769.2};
  p.patch.friction = {0.5, 0.5};
  p.search.dx_mm = p.search.ds_mm = dx_mm;
  p.motion.fz_N = fz_N;
  p.motion.vs_mm_s = 38888.9;
  p.motion.vpitch_rad_s = 0.0;
  return p;
}

TEST(PrescribedLongitudinalForce, GivesBackThePitchVelocityOfItsForce) {
  REQUIRE_EXAMPLES();
  // F=0 at a pitch velocity 0.1 % above free rolling, then F=1 with the force that gave.
  model::WheelRailProblem p = ma_et_al_proxy(0.5, 100e3);
  p.motion.vpitch_rad_s = -1.001 * p.motion.vs_mm_s / 460.0;
  const WheelRailSolution given = WheelsetSolver().solve(p);
  ASSERT_TRUE(given.converged) << given.message;
  EXPECT_DOUBLE_EQ(given.vpitch_rad_s, p.motion.vpitch_rad_s);
  model::WheelRailProblem q = p;
  q.longitudinal = model::LongitudinalLoading::Force;
  q.motion.fx_ws_N = given.force_ws.x;
  q.motion.vpitch_rad_s = 0.0;
  const WheelRailSolution solved = WheelsetSolver().solve(q);
  ASSERT_TRUE(solved.converged) << solved.message;
  const double eps = p.patch.solver.tolerance, mu = 0.5;
  EXPECT_LT(std::abs(solved.force_ws.x / solved.force_tr.z - q.motion.fx_ws_N / q.motion.fz_N),
            eps * mu);
  EXPECT_NEAR(solved.force_tr.z, q.motion.fz_N, eps * q.motion.fz_N);
  // dF_x/dω ≈ 2·10⁵ N per rad/s here: EPS·μ·F_z = 0.5 N is 3e-6 rad/s; the force's own
  // solver tolerance (EPS·F_x) allows about as much again.
  EXPECT_NEAR(solved.vpitch_rad_s, p.motion.vpitch_rad_s, 2e-5);
  EXPECT_LE(solved.pitch_iterations, 8);
}

TEST(PrescribedPitchMoment, GivesBackThePitchVelocityOfItsMoment) {
  REQUIRE_EXAMPLES();
  // F=2 (MY_WS, the moment on the rail about the axle): F=0 at a pitch velocity 0.1 % above free
  // rolling gives a moment; F=2 with that moment finds the pitch velocity again. The moment is
  // the force's times the rolling radius, r·F_x(ws), within the small moments about the marker.
  model::WheelRailProblem p = ma_et_al_proxy(0.5, 100e3);
  p.motion.vpitch_rad_s = -1.001 * p.motion.vs_mm_s / 460.0;
  const WheelRailSolution given = WheelsetSolver().solve(p);
  ASSERT_TRUE(given.converged) << given.message;
  const Vector3& m = given.wheel_marker_ws.position;
  const double my = given.moment_ws.y + m.z * given.force_ws.x - m.x * given.force_ws.z;
  EXPECT_NEAR(my, 460.0 * given.force_ws.x, 0.01 * std::abs(460.0 * given.force_ws.x));
  model::WheelRailProblem q = p;
  q.longitudinal = model::LongitudinalLoading::Moment;
  q.motion.my_ws_Nmm = my;
  q.motion.vpitch_rad_s = 0.0;
  const WheelRailSolution solved = WheelsetSolver().solve(q);
  ASSERT_TRUE(solved.converged) << solved.message;
  EXPECT_NEAR(solved.vpitch_rad_s, p.motion.vpitch_rad_s, 2e-5);
  EXPECT_NEAR(solved.force_ws.x, given.force_ws.x, 0.5 + 1e-5 * std::abs(given.force_ws.x));
}

TEST(PrescribedLongitudinalForce, MatchesContactOnTheMaEtAlProxy) {
  REQUIRE_EXAMPLES();
  // CONTACT (open-source build, rev. 2707) with F1=1, FX_WS = −0.25·FZ at 100 kN, DX = DS =
  // 0.5 mm (spec/dynamic-rolling.md §6.2): pmax 994.3 N/mm², 769 elements in contact, 228
  // slipping, approach 0.07441 mm.
  model::WheelRailProblem p = ma_et_al_proxy(0.5, 100e3);
  p.longitudinal = model::LongitudinalLoading::Force;
  p.motion.fx_ws_N = -25e3;
  const WheelRailSolution s = WheelsetSolver().solve(p);
  ASSERT_TRUE(s.converged) << s.message;
  ASSERT_EQ(s.patches.size(), 1U);
  const Solution& patch = s.patches[0].solution;
  EXPECT_NEAR(s.force_tr.x, -25e3, 1.0);
  EXPECT_NEAR(patch.totals.pmax, 994.3, 0.5);
  EXPECT_NEAR(patch.totals.pen, 0.07441, 1e-5);
  EXPECT_NEAR(patch.statistics.ncon, 769, 2);
  EXPECT_NEAR(patch.statistics.nslip, 228, 4);
  // Faster than free rolling (−V/460 = −84.5411 rad/s): the wheel drives. CONTACT's 0.25 mm
  // run found −84.6715; ours differs by 1.4 % of the creepage there (docs/decisions.md).
  EXPECT_LT(s.vpitch_rad_s, -84.5411);
  EXPECT_NEAR(s.vpitch_rad_s, -84.6715, 0.01);
}

TEST(PrescribedLongitudinalForce, NeedsThePrescribedVerticalForce) {
  REQUIRE_EXAMPLES();
  model::WheelRailProblem p = ma_et_al_proxy(0.5, 100e3);
  p.longitudinal = model::LongitudinalLoading::Force;
  p.vertical = model::VerticalLoading::Position;
  EXPECT_THROW(WheelsetSolver().solve(p), ProblemError);
}

}  // namespace
}  // namespace rollcontact
