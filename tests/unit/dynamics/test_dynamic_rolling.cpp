// Dynamic rolling with the exact contact at every step (spec/dynamic-rolling.md §6.4 T13-7): a
// wheel under a sprung mass on a crowned rail (a cylindrical wheel on a 300 mm crown, the
// contact solved by the wheel/rail solver) stays at rest in equilibrium, oscillates at
// sqrt(k_c/m_w)/2π about the static load when disturbed, and follows a long rail dip
// quasi-statically: the wheel load changes by the suspension's stretch and the wheel's inertia.

#include <gtest/gtest.h>

#include <cmath>

#include "rollcontact/dynamics.hpp"
#include "rollcontact/errors.hpp"
#include "rollcontact/model/profile.hpp"
#include "unit/wheelrail/wheelrail_problems.hpp"

namespace rollcontact::dynamics {
namespace {

model::WheelRailProblem crowned_rail_at_speed() {
  model::WheelRailProblem p = test_support::crowned_rail_problem(300.0);
  p.search.dx_mm = p.search.ds_mm = 0.5;
  p.motion.vs_mm_s = 38888.9;  // 140 km/h
  p.motion.vpitch_rad_s = -p.motion.vs_mm_s / 460.0;
  return p;
}

TEST(DynamicRolling, EquilibriumStaysAtRest) {
  DynamicRollingSettings st;
  st.distance_mm = 100.0;
  const SprungWheel vehicle;
  const DynamicRollingResult r = run_dynamic_rolling(crowned_rail_at_speed(), vehicle, st);
  ASSERT_TRUE(r.converged) << r.message;
  const double w = vehicle.static_load_N();
  for (const TimeSample& s : r.history) {
    EXPECT_NEAR(s.fz_N, w, 1e-4 * w) << s.t_s;
    EXPECT_NEAR(s.z_ws_mm, r.z_ws_static_mm, 1e-6) << s.t_s;
  }
  EXPECT_GT(r.z_ws_static_mm, r.z_ws_contact_mm);
  EXPECT_LE(r.solves, r.steps + 4);  // one contact solve per step at rest
}

TEST(DynamicRolling, DisturbedWheelOscillatesAtTheContactFrequency) {
  DynamicRollingSettings st;
  st.time_step_s = 2e-5;
  st.distance_mm = 1000 * st.time_step_s * 38888.9;  // 1000 steps, 20 ms ≈ 7 periods
  st.initial_vz_mm_per_s = 5.0;                      // amplitude ≈ 2 µm of ≈ 60 µm
  const SprungWheel vehicle;
  const DynamicRollingResult r = run_dynamic_rolling(crowned_rail_at_speed(), vehicle, st);
  ASSERT_TRUE(r.converged) << r.message;
  const SignalSummary sum = summarise_force(r.history, 0.02);
  const double w = vehicle.static_load_N();
  EXPECT_NEAR(sum.mean, w, 0.01 * w);
  // The force swings by k_c·amplitude = k_c·v0/ω about the static load.
  const double omega = 2.0 * M_PI * r.contact_frequency_Hz;
  const double swing = r.contact_stiffness_N_per_mm * 5.0 / omega;
  EXPECT_NEAR(sum.max - sum.mean, swing, 0.1 * swing);
  EXPECT_NEAR(sum.dominant_frequency_Hz, r.contact_frequency_Hz, 0.05 * r.contact_frequency_Hz);
  // with k_c of the contact at the static load and the wheel's mass alone.
  EXPECT_NEAR(
      r.contact_frequency_Hz,
      std::sqrt(r.contact_stiffness_N_per_mm / (vehicle.wheel_mass_kg * 1e-3)) / (2.0 * M_PI),
      1e-9);
}

TEST(DynamicRolling, LongDipIsFollowedQuasiStatically) {
  // A 0.5 mm dip 2 m long passes in 51 ms, 19 contact periods: the wheel follows the rail. At
  // the bottom the suspension is stretched by dz − z_sprung and the wheel decelerates with
  // z'' = −(d/2)(2πV/L)² (upwards): F_z = W − k_p·(dz − z_s) − m_w·z''. The cosine dip's
  // curvature starts with a jump, which sets the wheel ringing at the contact frequency with
  // m_w·|z''| ≈ 1.3 kN (no contact damping): the balance holds for the force averaged over one
  // contact period around the bottom.
  DynamicRollingSettings st;
  st.time_step_s = 1e-4;
  st.dip.depth_mm = 0.5;
  st.dip.start_mm = 50.0;
  st.dip.length_mm = 2000.0;
  const model::WheelRailProblem p = crowned_rail_at_speed();
  const double v = p.motion.vs_mm_s;
  const double bottom_mm = st.dip.start_mm + 0.5 * st.dip.length_mm;
  const double period_mm = v / 370.0;  // about one contact period of travel
  st.distance_mm = bottom_mm + 0.5 * period_mm;
  const SprungWheel vehicle;
  const DynamicRollingResult r = run_dynamic_rolling(p, vehicle, st);
  ASSERT_TRUE(r.converged) << r.message;
  const double period_s = 1.0 / r.contact_frequency_Hz;
  double sum = 0.0, stretch = 0.0;
  int n = 0;
  for (const TimeSample& s : r.history)
    if (s.t_s > r.history.back().t_s - period_s) {
      sum += s.fz_N;
      stretch += s.rail_dz_mm - s.z_sprung_mm;
      ++n;
    }
  ASSERT_GE(n, 20);
  const TimeSample& last = r.history.back();
  EXPECT_NEAR(last.z_ws_mm - r.z_ws_static_mm, last.rail_dz_mm, 0.01);
  const double acceleration =
      -0.5 * st.dip.depth_mm * std::pow(2.0 * M_PI * v / st.dip.length_mm, 2);
  const double expected = vehicle.static_load_N() -
                          vehicle.suspension_stiffness_N_per_mm * stretch / n -
                          vehicle.wheel_mass_kg * 1e-3 * acceleration;
  const double change = expected - vehicle.static_load_N();  // ≈ +730 N
  EXPECT_NEAR(sum / n, expected, 0.05 * std::abs(change));
}

TEST(DynamicRolling, TheWheelTurnsItsOutOfRoundnessUnderTheAxle) {
  // An out-of-round wheel (slices every 0.1 rad): its radius 0.2 mm smaller over a cosine dip
  // 1.2 m of its circumference long, whose bottom reaches the contact after 1 m of rolling. The
  // wheel turns at VPITCH, so the dip passes the contact as a rail dip of the same depth and
  // length would (LongDipIsFollowedQuasiStatically; 11 contact periods): at the bottom the
  // wheelset has sunk by the depth, within the ringing of the contact; before the dip arrives
  // (the first 40 cm) the wheel is round.
  model::WheelRailProblem p = crowned_rail_at_speed();
  const double r = p.wheelset.nominal_radius_mm, depth = 0.2, half = 600.0 / r;
  const double theta_bottom = -p.motion.pitch_rad + 1000.0 / r;
  SlicedProfile& slices = p.wheel.slices;
  slices.file = "out-of-round wheel (test)";
  slices.u_intpol = 1;
  for (int i = -31; i <= 31; ++i) {
    const double th = 0.1 * i, d = std::remainder(th - theta_bottom, 2.0 * M_PI) / half;
    Profile slice = p.wheel.points;
    const double dip = std::abs(d) < 1.0 ? depth * std::pow(std::cos(0.5 * M_PI * d), 2) : 0.0;
    for (double& z : slice.z) z -= dip;
    slices.u.push_back(th);
    slices.slices.push_back(slice);
  }
  DynamicRollingSettings st;
  st.time_step_s = 5e-4;
  st.distance_mm = 1000.0;
  const DynamicRollingResult res = run_dynamic_rolling(p, SprungWheel{}, st);
  ASSERT_TRUE(res.converged) << res.message;
  ASSERT_FALSE(res.warnings.empty());  // solved, and said to be unvalidated
  EXPECT_NE(res.warnings.front().find("not validated against CONTACT"), std::string::npos);
  const TimeSample& bottom = res.history.back();
  EXPECT_NEAR(bottom.z_ws_mm - res.z_ws_static_mm, depth, 0.1 * depth);
  for (const TimeSample& s : res.history) {
    if (s.s_mm < 350.0) {
      EXPECT_NEAR(s.z_ws_mm, res.z_ws_static_mm, 0.01 * depth) << s.s_mm;
    }
  }
}

TEST(DynamicRolling, RejectsMeaninglessSettings) {
  DynamicRollingSettings st;
  st.time_step_s = 0.0;
  EXPECT_THROW(run_dynamic_rolling(crowned_rail_at_speed(), SprungWheel{}, st), ProblemError);
  SprungWheel v;
  v.wheel_mass_kg = -1.0;
  EXPECT_THROW(run_dynamic_rolling(crowned_rail_at_speed(), v, DynamicRollingSettings{}),
               ProblemError);
}

}  // namespace
}  // namespace rollcontact::dynamics
