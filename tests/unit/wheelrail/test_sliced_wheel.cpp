// A wheel whose profile varies around its circumference (physics.md §13.9) through the
// wheelset solver: identical slices are the plain wheel; the result is periodic in the wheel's
// rotation; a dip in the radius under the contact lowers the force at a prescribed position and
// lets the wheelset sink at a prescribed force.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "rollcontact/wheelrail.hpp"
#include "wheelrail_problems.hpp"

namespace rollcontact {
namespace {

constexpr double kPi = std::numbers::pi;

/// The problem's wheel profile as slices every `step` rad around the wheel, the radius reduced
/// by `dip(θ)` [mm] (approximating spline, TH_INTPOL = 2, as the shared example).
model::WheelRailProblem sliced(model::WheelRailProblem p, double step,
                               const std::function<double(double)>& dip) {
  SlicedProfile& s = p.wheel.slices;
  s.file = "slices (test)";
  s.u_intpol = 2;
  const int n = static_cast<int>(std::floor(kPi / step));
  for (int i = -n; i <= n; ++i) {
    const double th = step * i;
    Profile slice = p.wheel.points;
    for (double& z : slice.z) z -= dip(th);
    s.u.push_back(th);
    s.slices.push_back(slice);
  }
  return p;
}

/// A smooth dip of depth `depth` [mm] and half-width `half` [rad] at θ0.
std::function<double(double)> dip_at(double th0, double depth, double half) {
  return [=](double th) {
    const double d = (th - th0) / half;
    return std::abs(d) < 1.0 ? depth * std::pow(std::cos(0.5 * kPi * d), 2) : 0.0;
  };
}

TEST(SlicedWheel, IdenticalSlicesGiveThePlainWheel) {
  model::WheelRailProblem p = test_support::crowned_rail_problem(300.0, 0.05);
  p.motion.z_mm = 0.05;
  p.motion.pitch_rad = -0.4;
  const WheelRailSolution plain = WheelsetSolver().solve(p);
  const WheelRailSolution s = WheelsetSolver().solve(sliced(p, 0.1, [](double) { return 0.0; }));
  ASSERT_TRUE(plain.converged && s.converged) << s.message;
  ASSERT_EQ(s.patches.size(), 1u);
  EXPECT_NEAR(s.force_tr.z, plain.force_tr.z, 1e-4 * plain.force_tr.z);
  EXPECT_NEAR(s.force_tr.x, plain.force_tr.x, 1e-4 * plain.force_tr.z);
  EXPECT_NEAR(s.patches[0].reference_tr.x, 0.0, 1e-6);
  // The sliced wheel's weights integrate its actual circle along x (radius r0 + z(y)), the
  // plain wheel's closed form the parabola of NOMRADW (physics.md §13.3 step 4): 1.7 µm apart
  // in y on this crowned profile.
  EXPECT_NEAR(s.patches[0].reference_tr.y, plain.patches[0].reference_tr.y, 2.5e-3);
}

TEST(SlicedWheel, YawedSteepFlankOfIdenticalSlicesIsThePlainWheels) {
  // A 30 mrad yawed cone of slope 0.5 on a 40 mm crown: the locus lies 15 mm off the axle, where
  // the surface is deepest along a line of constant track y — not the lowest point of the
  // wheel's circle, which the circle crosses the track beside it (R·(s·ψ)²/2 = 0.05 mm higher
  // here). A flange 20 mrad yawed on a wheel flat's slices missed its contact by 0.19 mm.
  model::WheelRailProblem p = test_support::crowned_rail_problem(40.0, 0.5);
  p.motion.yaw_rad = 0.03;
  p.motion.z_mm = 0.1;
  const WheelRailSolution plain = WheelsetSolver().solve(p);
  const WheelRailSolution s = WheelsetSolver().solve(sliced(p, 0.1, [](double) { return 0.0; }));
  ASSERT_TRUE(plain.converged && s.converged) << s.message;
  ASSERT_EQ(plain.patches.size(), 1u);
  ASSERT_EQ(s.patches.size(), 1u);
  EXPECT_GT(std::abs(plain.patches[0].reference_tr.x), 3.0);  // off the axle
  EXPECT_NEAR(s.force_tr.z, plain.force_tr.z, 2e-3 * plain.force_tr.z);
  EXPECT_NEAR(s.patches[0].solution.totals.pen, plain.patches[0].solution.totals.pen, 2e-4);
  EXPECT_NEAR(s.patches[0].reference_tr.x, plain.patches[0].reference_tr.x, 0.05);
}

TEST(SlicedWheel, ConformalPatchOfIdenticalSlicesIsThePlainWheels) {
  // D=4 through the C++ API (the .inp route refuses wheel slices): the curved reference takes
  // the wheel's cross-section under the axle, the gap and the rigid slip the 2-D surface.
  model::WheelRailProblem p = test_support::crowned_rail_problem(300.0, 0.05);
  p.motion.z_mm = 0.05;
  p.motion.pitch_rad = -0.4;
  p.patch.tangential.kind = model::TangentialKind::SteadyRolling;
  p.motion.vpitch_rad_s *= 1.002;
  p.search.conformal = true;
  const WheelRailSolution plain = WheelsetSolver().solve(p);
  const WheelRailSolution s = WheelsetSolver().solve(sliced(p, 0.1, [](double) { return 0.0; }));
  ASSERT_TRUE(plain.converged && s.converged) << s.message;
  ASSERT_EQ(s.patches.size(), 1u);
  ASSERT_TRUE(s.patches[0].conformal.active);
  EXPECT_NEAR(s.force_tr.z, plain.force_tr.z, 1e-4 * plain.force_tr.z);
  EXPECT_NEAR(s.force_tr.x, plain.force_tr.x, 1e-4 * plain.force_tr.z);
  // ξ at reference points 1.7 µm apart (see IdenticalSlicesGiveThePlainWheel): 5e-5 relative.
  EXPECT_NEAR(s.patches[0].xi, plain.patches[0].xi, 1e-4 * std::abs(plain.patches[0].xi));
}

TEST(SlicedWheel, ResultIsPeriodicInTheRotation) {
  model::WheelRailProblem p =
      sliced(test_support::crowned_rail_problem(300.0), 0.01, dip_at(0.3, 0.03, 0.08));
  p.motion.z_mm = 0.05;
  p.motion.pitch_rad = -0.32;  // the dip's centre 9 mm behind the contact
  const WheelRailSolution a = WheelsetSolver().solve(p);
  p.motion.pitch_rad += 2.0 * kPi;
  const WheelRailSolution b = WheelsetSolver().solve(p);
  ASSERT_TRUE(a.converged && b.converged);
  ASSERT_EQ(a.patches.size(), 1u);
  EXPECT_NEAR(b.force_tr.z, a.force_tr.z, 1e-9 * a.force_tr.z);
  EXPECT_NEAR(b.patches[0].reference_tr.x, a.patches[0].reference_tr.x, 1e-9);
  // The radius grows ahead of the contact (x > 0: larger θ, away from the dip): the deepest
  // point of the wheel, and the contact, move forward.
  EXPECT_GT(a.patches[0].reference_tr.x, 0.1);
}

TEST(SlicedWheel, ABumpBeyondTheDeepestPointMovesTheReferenceTowardsIt) {
  // A 5 µm bump 8 mm ahead of the contact's centre (where the round wheel has risen 70 µm) is
  // never the deepest point, but it deepens the interpenetration near the leading edge: the
  // weighted centre (∫ g² x dx over the actual surface) moves forward — wheelflat case 3, where
  // the flat's first slices lie just ahead of the contact. Mirrored behind, the centre moves
  // back by the same amount.
  const model::WheelRailProblem round = test_support::crowned_rail_problem(300.0);
  const double th0 = 0.3, ahead = 8.0 / 460.0;
  const auto reference_x = [&](double th_bump) {
    model::WheelRailProblem p = sliced(round, 0.002, dip_at(th_bump, -0.005, 0.004));
    p.motion.pitch_rad = -th0;
    p.motion.z_mm = 0.1;
    const WheelRailSolution s = WheelsetSolver().solve(p);
    EXPECT_TRUE(s.converged);
    EXPECT_EQ(s.patches.size(), 1u);
    return s.patches.empty() ? 0.0 : s.patches[0].reference_tr.x;
  };
  const double forward = reference_x(th0 + ahead), back = reference_x(th0 - ahead);
  EXPECT_GT(forward, 0.005);
  EXPECT_LT(forward, 0.2);
  EXPECT_NEAR(back, -forward, 1e-3 * forward);
}

TEST(SlicedWheel, ADipUnderTheContact) {
  const model::WheelRailProblem round = test_support::crowned_rail_problem(300.0);
  model::WheelRailProblem p = sliced(round, 0.01, dip_at(0.3, 0.02, 0.1));
  p.motion.pitch_rad = -0.3;
  // Prescribed position: 0.02 mm less interpenetration at the bottom of the dip, less force.
  model::WheelRailProblem r = round;
  r.motion.z_mm = p.motion.z_mm = 0.05;
  const WheelRailSolution fr = WheelsetSolver().solve(r);
  const WheelRailSolution fp = WheelsetSolver().solve(p);
  ASSERT_TRUE(fr.converged && fp.converged);
  EXPECT_LT(fp.force_tr.z, 0.8 * fr.force_tr.z);
  EXPECT_NEAR(fp.patches[0].reference_tr.x, 0.0, 1e-3);  // symmetric dip: centred
  // Prescribed force: the wheelset sinks by about the dip's depth (a little less: the dip is
  // flatter along x than the round wheel, so the same force needs less approach).
  r.vertical = p.vertical = model::VerticalLoading::Force;
  r.motion.fz_N = p.motion.fz_N = fr.force_tr.z;
  const WheelRailSolution zr = WheelsetSolver().solve(r);
  const WheelRailSolution zp = WheelsetSolver().solve(p);
  ASSERT_TRUE(zr.converged && zp.converged);
  EXPECT_NEAR(zr.z_ws_mm, 0.05, 1e-3);
  EXPECT_GT(zp.z_ws_mm - zr.z_ws_mm, 0.015);
  EXPECT_LT(zp.z_ws_mm - zr.z_ws_mm, 0.02 + 1e-4);
}

}  // namespace
}  // namespace rollcontact
