// Flexible wheelsets (E = 4, 5; spec/wheelrail-advanced.md §5.1): the wheel's deviation from its
// place on the wheelset moves its surface, and only the deviation rates create creepage.
// Checked by equivalences with the rigid wheelset: a lateral or vertical deviation equals the
// same displacement of the wheelset, a lateral deviation rate the same wheelset velocity; a
// static yaw deviation turns the wheel about its marker (the contact stays at x = 0) without the
// lateral creepage a wheelset yaw brings; a yaw rate of the wheel adds spin; left mirrors right.

#include <gtest/gtest.h>

#include <cmath>

#include "rollcontact/wheelrail.hpp"
#include "wheelrail_problems.hpp"

namespace rollcontact {
namespace {

WheelRailSolution solve(const model::WheelRailProblem& p) {
  WheelsetSolver solver;
  WheelRailSolution s = solver.solve(p);
  EXPECT_TRUE(s.converged) << s.message;
  EXPECT_EQ(s.patches.size(), 1u);
  return s;
}

TEST(FlexibleWheelset, LateralDeviationIsALateralWheelsetShift) {
  // Unrotated wheelset: DYWHL = 1.5 mm moves the wheel exactly as Y_WS = 1.5 mm does.
  model::WheelRailProblem shifted = test_support::rolling_conical_wheel();
  shifted.motion.y_mm = 1.5;
  model::WheelRailProblem deviated = test_support::rolling_conical_wheel();
  deviated.wheel_deviation.dy_mm = 1.5;
  const WheelRailSolution a = solve(shifted), b = solve(deviated);
  ASSERT_EQ(a.patches.size(), 1u);
  ASSERT_EQ(b.patches.size(), 1u);
  EXPECT_NEAR(b.patches[0].reference_tr.y, a.patches[0].reference_tr.y, 1e-9);
  EXPECT_NEAR(b.patches[0].contact_angle_rad, a.patches[0].contact_angle_rad, 1e-12);
  EXPECT_NEAR(b.force_tr.y, a.force_tr.y, 1e-6);
  EXPECT_NEAR(b.force_tr.x, a.force_tr.x, 1e-6);
  EXPECT_NEAR(b.z_ws_mm, a.z_ws_mm, 1e-9);
  // The wheel-profile coordinates of the contact are the wheel's own: the same in both.
  EXPECT_NEAR(b.patches[0].reference_wheel.y, a.patches[0].reference_wheel.y, 1e-9);
  // The contact stays where the slopes match on the rail; the wheel touches it 1.5 mm further
  // towards its flange (the test has something to tell apart).
  const WheelRailSolution c = solve(test_support::rolling_conical_wheel());
  EXPECT_NEAR(c.patches[0].reference_wheel.y - a.patches[0].reference_wheel.y, 1.5, 1e-3);
}

TEST(FlexibleWheelset, VerticalDeviationLowersTheWheel) {
  // FZ prescribed: a wheel DZWHL = 0.02 mm lower on its wheelset lets the wheelset sit 0.02 mm
  // higher for the same contact (z_ws to the vertical iteration's tolerance, EPS·FZ over the
  // contact stiffness ≈ 1e-8 mm).
  model::WheelRailProblem deviated = test_support::rolling_conical_wheel();
  deviated.wheel_deviation.dz_mm = 0.02;
  const WheelRailSolution a = solve(test_support::rolling_conical_wheel()), b = solve(deviated);
  ASSERT_EQ(a.patches.size(), 1u);
  ASSERT_EQ(b.patches.size(), 1u);
  EXPECT_NEAR(b.z_ws_mm, a.z_ws_mm - 0.02, 1e-6);
  EXPECT_NEAR(b.patches[0].solution.totals.pen, a.patches[0].solution.totals.pen, 1e-6);
}

TEST(FlexibleWheelset, StaticYawDeviationCreatesNoCreepage) {
  // A cylindrical wheel touches the crown under its marker (profile y = 0, 750 mm from the
  // wheelset centre). Yawing the wheelset by ψ moves the contact to x = −750·sin ψ and brings
  // lateral creepage |η| = sin ψ; yawing the wheel alone about its marker keeps the contact at
  // x = 0 and, the wheel turning with the wheelset's pitch, brings none.
  const double psi = 0.005;
  model::WheelRailProblem base = test_support::crowned_rail_problem(300.0);
  base.patch.tangential.kind = model::TangentialKind::SteadyRolling;
  base.vertical = model::VerticalLoading::Force;
  base.motion.fz_N = 10000.0;
  model::WheelRailProblem yawed = base;
  yawed.motion.yaw_rad = psi;
  model::WheelRailProblem deviated = base;
  deviated.wheel_deviation.dyaw_rad = psi;
  const WheelRailSolution s0 = solve(base), a = solve(yawed), b = solve(deviated);
  ASSERT_EQ(a.patches.size(), 1u);
  ASSERT_EQ(b.patches.size(), 1u);
  EXPECT_NEAR(a.patches[0].reference_tr.x, -750.0 * std::sin(psi), 1e-3);
  EXPECT_NEAR(std::abs(a.patches[0].eta), std::sin(psi), 1e-6);
  EXPECT_NEAR(b.patches[0].reference_tr.x, 0.0, 1e-6);
  EXPECT_NEAR(b.patches[0].eta, 0.0, 1e-12);
  EXPECT_NEAR(b.patches[0].xi, s0.patches[0].xi, 1e-9);
  EXPECT_NEAR(b.force_tr.y, s0.force_tr.y, 1e-6);
  // The wheel's own yaw shows in the wheel marker's orientation.
  EXPECT_DOUBLE_EQ(b.wheel_marker_tr.yaw_rad, psi);
}

TEST(FlexibleWheelset, DeviationRatesAreWheelVelocities) {
  // VYWHL = 3 mm/s on an unrotated wheelset is VY = 3 mm/s: the same lateral creepage.
  model::WheelRailProblem moving = test_support::rolling_conical_wheel();
  moving.motion.vy_mm_s = 3.0;
  model::WheelRailProblem deviated = test_support::rolling_conical_wheel();
  deviated.wheel_deviation.vy_mm_s = 3.0;
  const WheelRailSolution a = solve(moving), b = solve(deviated);
  ASSERT_EQ(a.patches.size(), 1u);
  ASSERT_EQ(b.patches.size(), 1u);
  EXPECT_NEAR(b.patches[0].eta, a.patches[0].eta, 1e-12);
  EXPECT_NE(a.patches[0].eta, 0.0);
  EXPECT_NEAR(b.force_tr.y, a.force_tr.y, 1e-6);
  // A yaw rate of the wheel about its marker adds spin: Δφ = −VYAWW·cos δ / V (and moves the
  // contact point, off the marker, laterally).
  model::WheelRailProblem spinning = test_support::rolling_conical_wheel();
  spinning.wheel_deviation.vyaw_rad_s = 0.02;
  const WheelRailSolution base = solve(test_support::rolling_conical_wheel()), c = solve(spinning);
  ASSERT_EQ(c.patches.size(), 1u);
  const WheelRailPatch& w = c.patches[0];
  // (V itself changes by the yaw rate's x-velocity at the contact, 0.02 × 15 mm/s of 2000.)
  const WheelRailPatch& w0 = base.patches[0];
  EXPECT_NEAR(w.phi_per_mm,
              (w0.phi_per_mm * w0.veloc_mm_s - 0.02 * std::cos(w.contact_angle_rad)) / w.veloc_mm_s,
              1e-12);
  EXPECT_NE(w.veloc_mm_s, w0.veloc_mm_s);
}

TEST(FlexibleWheelset, LeftWheelIsTheMirrorImageOfTheRightOne) {
  model::WheelRailProblem right = test_support::rolling_conical_wheel();
  right.motion.y_mm = 1.0;
  right.wheel_deviation = {0.3, 0.5, 0.01, 0.001, 0.004, 0.0, 1.0, 2.0, 0.0, 0.01, 0.02, 0.0};
  const model::WheelRailProblem left = test_support::mirrored_left(right);  // deviations too
  const WheelRailSolution r = solve(right), l = solve(left);
  ASSERT_EQ(r.patches.size(), 1u);
  ASSERT_EQ(l.patches.size(), 1u);
  EXPECT_EQ(l.force_tr.x, r.force_tr.x);
  EXPECT_EQ(l.force_tr.y, -r.force_tr.y);
  EXPECT_EQ(l.force_tr.z, r.force_tr.z);
  EXPECT_EQ(l.patches[0].eta, -r.patches[0].eta);
  EXPECT_EQ(l.patches[0].phi_per_mm, -r.patches[0].phi_per_mm);
  EXPECT_EQ(l.wheel_marker_tr.position.y, -r.wheel_marker_tr.position.y);
}

}  // namespace
}  // namespace rollcontact
