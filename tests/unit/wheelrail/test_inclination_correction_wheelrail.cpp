// Blanco's correction of the influence coefficients (C=4) in module 1 (wheelrail-advanced.md
// §1.7): a conformal patch (D=4) turns its coefficients by the inclinations of its curved
// reference's rows; a planar patch (D=2) has one inclination and keeps the plain half-space.

#include <gtest/gtest.h>

#include <cmath>

#include "rollcontact/wheelrail.hpp"
#include "wheelrail_problems.hpp"

namespace rollcontact {
namespace {

/// A hollow wheel (profile radius 20.5 mm) rolling on a crown of 20 mm radius at 10 kN: the
/// rows of a conformal patch turn by up to 25° around the crown. Optionally C=4, variant `v`.
model::WheelRailProblem hollow_wheel(bool conformal, int variant) {
  model::WheelRailProblem p = test_support::crowned_rail_problem(300.0);
  const double rr = 20.0, rw = 20.5;
  p.rail.points = test_support::sampled_profile(
      [rr](double y) { return rr - std::sqrt(rr * rr - y * y); }, -15.0, 15.0, 0.1, false);
  p.wheel.points = test_support::sampled_profile(
      [rw](double y) { return rw - std::sqrt(rw * rw - y * y); }, -18.0, 18.0, 0.1, true);
  p.search.conformal = conformal;
  p.patch.tangential.kind = model::TangentialKind::SteadyRolling;
  p.patch.solver.max_normal_tangential_passes = 10;
  p.motion.vpitch_rad_s *= 1.003;
  p.motion.yaw_rad = 0.002;
  p.vertical = model::VerticalLoading::Force;
  p.motion.fz_N = 10000.0;
  p.patch.bodies.inclination.variant = variant;
  return p;
}

WheelRailSolution solve(const model::WheelRailProblem& p) {
  WheelRailSolution s = WheelsetSolver().solve(p);
  EXPECT_TRUE(s.converged) << s.message;
  EXPECT_EQ(s.patches.size(), 1U);
  return s;
}

// A planar patch's rows all have the patch's angle: no turn, the answer of C=2 bit for bit.
TEST(InclinationCorrectionWheelRail, PlanarPatchKeepsThePlainHalfSpace) {
  const WheelRailSolution plain = solve(hollow_wheel(false, 0));
  const WheelRailSolution turned = solve(hollow_wheel(false, 4));
  EXPECT_EQ(turned.z_ws_mm, plain.z_ws_mm);
  EXPECT_EQ(turned.force_tr.x, plain.force_tr.x);
  EXPECT_EQ(turned.force_tr.y, plain.force_tr.y);
  EXPECT_EQ(turned.patches[0].solution.px, plain.patches[0].solution.px);
}

// Around the crown the correction turns the coefficients by up to 0.45 rad between the edge
// rows; the patch stays symmetric (FS ≈ 0 up to the yaw's share) and the vertical force is met.
// Every variant changes the tangential forces by a few per cent, and the symmetric variant 4
// lies between the one-sided variants 1 and 3 (half of each turn).
TEST(InclinationCorrectionWheelRail, ConformalPatchTurnsItsCoefficientsByItsRows) {
  const WheelRailSolution plain = solve(hollow_wheel(true, 0));
  double fx[5] = {plain.force_tr.x, 0.0, 0.0, 0.0, 0.0};
  for (int v = 1; v <= 4; ++v) {
    const WheelRailSolution s = solve(hollow_wheel(true, v));
    EXPECT_NEAR(s.force_tr.z, 10000.0, 0.1) << v;
    EXPECT_TRUE(s.patches[0].conformal.active) << v;
    fx[v] = s.force_tr.x;
    EXPECT_NE(fx[v], fx[0]) << v;
    EXPECT_NEAR(fx[v], fx[0], 0.05 * std::abs(fx[0])) << v;
  }
  EXPECT_LE(std::min(fx[1], fx[3]), fx[4]);
  EXPECT_GE(std::max(fx[1], fx[3]), fx[4]);
}

// The left wheel's patch is the right one's mirrored, correction included (a conical wheel on
// a 300 mm crown, off centre and yawed: rows turning by 1/600 rad per mm).
TEST(InclinationCorrectionWheelRail, LeftWheelMirrorsTheRightOne) {
  model::WheelRailProblem right = test_support::yawed_conical_wheel();
  right.search.conformal = true;
  right.patch.bodies.inclination.variant = 1;
  const WheelRailSolution r = solve(right);
  const WheelRailSolution l = solve(test_support::mirrored_left(right));
  EXPECT_EQ(l.force_tr.x, r.force_tr.x);
  EXPECT_EQ(l.force_tr.y, -r.force_tr.y);
  EXPECT_EQ(l.force_tr.z, r.force_tr.z);
  EXPECT_NE(r.force_tr.y, 0.0);
}

}  // namespace
}  // namespace rollcontact
