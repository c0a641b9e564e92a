// Conformal contact (CONTACT's D=4; spec/wheelrail-advanced.md §1): the least-squares average
// creepages, a tread contact where the curved reference is nearly the tangent plane (D=4 must
// give D=2's answer), a hollow wheel conforming to a crown (the gap along the local normals
// carries more load than the planar one), and the Manchester benchmark's flange-root cases of
// mbench_a22_varfric (c5, c7) through the .inp route against CONTACT's printed numbers.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <variant>
#include <vector>

#include "format/inp/inp_reader.hpp"
#include "format/inp/to_wheelrail.hpp"
#include "rollcontact/wheelrail.hpp"
#include "support/examples.hpp"
#include "wheelrail/conformal_patch.hpp"
#include "wheelrail_problems.hpp"

namespace rollcontact {
namespace {

TEST(ConformalContact, AverageCreepagesOfARigidFieldAreItsCreepagesExactly) {
  // w = (ξ − φ·y, η + φ·x) on an off-centre, irregular set of elements.
  const double xi = 3.1e-3, eta = -1.7e-3, phi = 4.2e-4;
  std::vector<wheelrail::SlipSample> samples;
  for (int i = 0; i < 9; ++i)
    for (int j = 0; j < 5 + (i % 3); ++j) {
      const double x = -2.0 + 0.4 * i + 0.05, y = 1.3 + 0.3 * j;
      samples.push_back({x, y, xi - phi * y, eta + phi * x});
    }
  const wheelrail::PatchKinematics k = wheelrail::fit_average_creepages(samples);
  EXPECT_NEAR(k.xi, xi, 1e-15);
  EXPECT_NEAR(k.eta, eta, 1e-15);
  EXPECT_NEAR(k.phi_per_mm, phi, 1e-15);
  // One point: no spin can be fitted; nothing at all: zero.
  EXPECT_EQ(wheelrail::fit_average_creepages({samples.front()}).phi_per_mm, 0.0);
  EXPECT_EQ(wheelrail::fit_average_creepages({}).xi, 0.0);
}

/// The crowned rail of the geometry tests under a cylinder, rolling with creepage: VPITCH 0.4 %
/// below free rolling (ξ ≈ −4e-3), a yaw of 2 mrad (η), μ = 0.3.
model::WheelRailProblem rolling_tread(bool conformal) {
  model::WheelRailProblem p = test_support::crowned_rail_problem(300.0);
  p.patch.tangential.kind = model::TangentialKind::SteadyRolling;
  p.motion.vpitch_rad_s *= 1.004;
  p.motion.yaw_rad = 0.002;
  p.vertical = model::VerticalLoading::Force;
  p.motion.fz_N = 50000.0;
  p.search.conformal = conformal;
  return p;
}

TEST(ConformalContact, TreadContactOnALargeCrownEqualsThePlanarAnswer) {
  WheelsetSolver planar_solver, conformal_solver;
  const WheelRailSolution planar = planar_solver.solve(rolling_tread(false));
  const WheelRailSolution conformal = conformal_solver.solve(rolling_tread(true));
  ASSERT_TRUE(planar.converged) << planar.message;
  ASSERT_TRUE(conformal.converged) << conformal.message;
  ASSERT_EQ(planar.patches.size(), 1U);
  ASSERT_EQ(conformal.patches.size(), 1U);
  const WheelRailPatch& a = planar.patches[0];
  const WheelRailPatch& b = conformal.patches[0];
  ASSERT_TRUE(b.conformal.active);
  EXPECT_FALSE(a.conformal.active);
  // The curved reference: one row per DS sample, midway between the crown (turning 1/300 rad
  // per mm) and the cylinder (not turning), so its normal turns by 1/600 rad per mm.
  const ConformalPatch& c = b.conformal;
  ASSERT_EQ(c.row_alpha_rad.size(), static_cast<std::size_t>(b.solution.grid.my));
  for (std::size_t i = 0; i < c.row_alpha_rad.size(); ++i) {
    const double s = c.row0_s_mm + c.ds_mm * static_cast<double>(i);
    EXPECT_NEAR(c.row_alpha_rad[i] - b.contact_angle_rad, s / 600.0, 2e-5) << "row " << i;
  }
  // Over a contact 2×6 mm wide the rows turn by at most ±0.01 rad: bar and tilde agree to
  // 1 − cos 0.01 = 5e-5.
  EXPECT_NEAR(c.bar_fn, c.tilde_fn, 5e-5 * c.tilde_fn);
  // The average creepages are the planar creepages (rigid slip of the same motion) within what
  // the curvature of the crown and the wheel's rotation within the patch add. D=4 divides by
  // V = VS, D=2 by the mean of VS and the rolling speed (0.2 % more here): compare the slip
  // velocities.
  EXPECT_NEAR(b.veloc_mm_s, 2000.0, 1e-9);
  EXPECT_NEAR(b.xi * b.veloc_mm_s, a.xi * a.veloc_mm_s, 2e-3);  // mm/s, of 8 mm/s
  EXPECT_NEAR(b.eta * b.veloc_mm_s, a.eta * a.veloc_mm_s, 2e-3);
  EXPECT_NEAR(b.phi_per_mm * b.veloc_mm_s, a.phi_per_mm * a.veloc_mm_s, 2e-3);
  // Forces: the same wheelset height and forces within 0.2 %.
  EXPECT_NEAR(conformal.z_ws_mm, planar.z_ws_mm, 2e-4);
  EXPECT_NEAR(conformal.force_tr.x, planar.force_tr.x, 2e-3 * std::abs(planar.force_tr.x));
  EXPECT_NEAR(conformal.force_tr.y, planar.force_tr.y, 2e-3 * std::abs(planar.force_tr.y) + 2.0);
  EXPECT_NEAR(conformal.force_tr.z, 50000.0, 50.0);
}

TEST(ConformalContact, HollowWheelOnACrownCarriesLessThanThePlanarGapSays) {
  // Crown of 20 mm radius in a hollow wheel of 20.5 mm profile radius, pushed 0.05 mm into it:
  // at the angle θ around the crown the surfaces are (to first order) −0.05·cos θ +
  // 0.5·(1 − cos θ) apart along their common normal, and that divided by cos θ measured
  // vertically, as the planar approach does. Both vanish at the same θ (25°), but the planar
  // interpenetration is deeper by 1/cos θ (up to 10 %): the conformal contact carries less at
  // the same position. The curved reference follows the crown's normal (α = asin(y/20.25) at
  // the mid radius) and, the problem being symmetric, FS is zero.
  auto problem = [](bool conformal) {
    model::WheelRailProblem p = test_support::crowned_rail_problem(300.0);
    const double rr = 20.0, rw = 20.5;
    p.rail.points = test_support::sampled_profile(
        [rr](double y) { return rr - std::sqrt(rr * rr - y * y); }, -15.0, 15.0, 0.1, false);
    p.wheel.points = test_support::sampled_profile(
        [rw](double y) { return rw - std::sqrt(rw * rw - y * y); }, -18.0, 18.0, 0.1, true);
    p.motion.z_mm = 0.05;
    p.search.conformal = conformal;
    return p;
  };
  const WheelRailSolution planar = WheelsetSolver().solve(problem(false));
  const WheelRailSolution conformal = WheelsetSolver().solve(problem(true));
  ASSERT_EQ(planar.patches.size(), 1U);
  ASSERT_EQ(conformal.patches.size(), 1U);
  const ConformalPatch& c = conformal.patches[0].conformal;
  ASSERT_TRUE(c.active);
  EXPECT_LT(conformal.force_tr.z, 0.99 * planar.force_tr.z);  // measured 0.934
  EXPECT_GT(conformal.force_tr.z, 0.90 * planar.force_tr.z);
  EXPECT_NEAR(c.bar_fs, 0.0, 1e-6 * c.tilde_fn);
  EXPECT_LT(c.bar_fn, c.tilde_fn);  // the rows' normals fan out around the crown
  for (std::size_t i = 0; i < c.row_y_mm.size(); ++i)
    EXPECT_NEAR(c.row_alpha_rad[i], std::asin((c.row_y_mm[i] - 750.0) / 20.25), 2e-3)
        << "row " << i;
}

TEST(ConformalContact, FlangeRootCasesOfTheBenchmarkGiveContactsNumbers) {
  // mbench_a22_varfric case 5 (V=1: friction per row by its inclination) and case 7 (V=2) at
  // y = 5.5 mm, yaw 13.2 mrad: CONTACT's printed curved reference, average creepages and
  // bar/tilde forces.
  REQUIRE_EXAMPLES();
  const std::filesystem::path dir{ROLLCONTACT_EXAMPLES_DIR};
  const auto cases = format::read_input_cases(dir / "mbench_a22_varfric.inp");
  WheelsetSolver solver;
  for (std::size_t k = 0; k < 4; ++k) {  // the cases before set the sequence's state
    auto record = std::get<format::WheelRailRecord>(cases.at(k));
    record.subsurface = {};
    model::WheelRailProblem p = format::to_wheelrail_problem(record);
    p.validated_only = false;
    (void)solver.solve(p);
  }
  const WheelRailSolution s =
      solver.solve(format::to_wheelrail_problem(std::get<format::WheelRailRecord>(cases.at(4))));
  ASSERT_TRUE(s.converged) << s.message;
  ASSERT_EQ(s.patches.size(), 1U);
  const WheelRailPatch& w = s.patches[0];
  const ConformalPatch& c = w.conformal;
  ASSERT_TRUE(c.active);
  ASSERT_EQ(c.row_y_mm.size(), 17U);  // CONTACT: 17 points, rows 6-12 in contact
  EXPECT_EQ(c.contact_row_first, 5);
  EXPECT_EQ(c.contact_row_last, 11);
  // CONTACT's table: row 1 (724.6342, 3.9166, -0.4357), row 17 (727.6474, 2.8524, -0.2663).
  EXPECT_NEAR(c.row_y_mm.front(), 724.6342, 2e-4);
  EXPECT_NEAR(c.row_z_mm.front(), 3.9166, 2e-4);
  EXPECT_NEAR(c.row_alpha_rad.front(), -0.4357, 1e-4);
  EXPECT_NEAR(c.row_y_mm.back(), 727.6474, 2e-4);
  EXPECT_NEAR(c.row_alpha_rad.back(), -0.2663, 1e-4);
  ASSERT_EQ(c.row_friction.size(), 17U);
  EXPECT_NEAR(c.row_friction.front(), 0.2000, 1e-4);
  EXPECT_NEAR(c.row_friction.back(), 0.2474, 1e-4);
  // CKSI 4.409E-03, CETA 1.403E-02, CPHI 7.151E-04; VELOC = VS.
  EXPECT_NEAR(w.xi, 4.409e-3, 1e-6);
  EXPECT_NEAR(w.eta, 1.403e-2, 1e-5);
  EXPECT_NEAR(w.phi_per_mm, 7.151e-4, 1e-6);
  EXPECT_NEAR(w.veloc_mm_s, 2000.0, 1e-9);
  // BAR_FN 9897, BAR_FX −613.9, BAR_FS −1991, TILDE_FN 9903 within the module-1 tolerance
  // (5e-3 relative + 2e-4·FZ).
  auto tol = [](double f) { return 5e-3 * std::abs(f) + 2.0; };
  EXPECT_NEAR(c.bar_fn, 9897.0, tol(9897.0));
  EXPECT_NEAR(c.bar_fx, -613.9, tol(613.9));
  EXPECT_NEAR(c.bar_fs, -1991.0, tol(1991.0));
  EXPECT_NEAR(c.tilde_fn, 9903.0, tol(9903.0));
  EXPECT_NEAR(s.force_tr.y, 1387.0, tol(1387.0));
}

TEST(ConformalContact, LeftWheelMirrorsTheRightOne) {
  // The mirror image of a right-wheel case on a left wheel (inputs in track coordinates) gives
  // the right wheel's conformal patch mirrored: lateral positions, angles, FS and the lateral
  // forces change sign, everything else is bit for bit the same.
  model::WheelRailProblem right = test_support::yawed_conical_wheel();
  right.motion.vy_mm_s = 3.0;
  right.search.conformal = true;
  const model::WheelRailProblem left = test_support::mirrored_left(right);
  const WheelRailSolution r = WheelsetSolver().solve(right);
  const WheelRailSolution l = WheelsetSolver().solve(left);
  ASSERT_EQ(r.patches.size(), 1U);
  ASSERT_EQ(l.patches.size(), 1U);
  EXPECT_EQ(l.force_tr.x, r.force_tr.x);
  EXPECT_EQ(l.force_tr.y, -r.force_tr.y);
  EXPECT_EQ(l.force_tr.z, r.force_tr.z);
  const ConformalPatch &a = r.patches[0].conformal, &b = l.patches[0].conformal;
  ASSERT_TRUE(b.active);
  EXPECT_EQ(b.bar_fn, a.bar_fn);
  EXPECT_EQ(b.bar_fs, -a.bar_fs);
  EXPECT_EQ(b.moment_planar.z, -a.moment_planar.z);
  ASSERT_EQ(b.row_y_mm.size(), a.row_y_mm.size());
  for (std::size_t i = 0; i < a.row_y_mm.size(); ++i) {
    EXPECT_EQ(b.row_y_mm[i], -a.row_y_mm[i]);
    EXPECT_EQ(b.row_alpha_rad[i], -a.row_alpha_rad[i]);
  }
  EXPECT_EQ(l.patches[0].eta, -r.patches[0].eta);
  EXPECT_NE(r.patches[0].eta, 0.0);
}

TEST(ConformalContact, OnARollerOfHugeRadiusItIsTheTrack) {
  // The rolling tread of above on a roller of NOMRADR = 1e8 mm turning at VS/NOMRADR: the
  // curved reference, the average creepages and the forces of the track (the roller's material
  // passes the contact at RPITCH·NOMRADR = VS, its surface within 1e-8 mm of the track's).
  const model::WheelRailProblem track = rolling_tread(true);
  model::WheelRailProblem roller = track;
  roller.roller = {true, 1e8, track.motion.vs_mm_s / 1e8};
  roller.motion.vs_mm_s = 0.0;
  const WheelRailSolution t = WheelsetSolver().solve(track);
  const WheelRailSolution r = WheelsetSolver().solve(roller);
  ASSERT_TRUE(t.converged) << t.message;
  ASSERT_TRUE(r.converged) << r.message;
  ASSERT_EQ(r.patches.size(), 1U);
  const WheelRailPatch &a = t.patches[0], &b = r.patches[0];
  ASSERT_TRUE(b.conformal.active);
  // V: VS on the track, the mean material speed on a roller (wheelrail-advanced.md §1.6: 2004
  // mm/s here, the wheel's material 0.4 % faster): the slip velocities agree.
  EXPECT_NEAR(b.veloc_mm_s, 2004.0, 0.01);
  EXPECT_EQ(b.chi_rad, 0.0);
  EXPECT_NEAR(b.xi * b.veloc_mm_s, a.xi * a.veloc_mm_s, 1e-4);  // mm/s, of 8 mm/s
  EXPECT_NEAR(b.eta * b.veloc_mm_s, a.eta * a.veloc_mm_s, 1e-4);
  EXPECT_NEAR(b.phi_per_mm * b.veloc_mm_s, a.phi_per_mm * a.veloc_mm_s, 1e-4);
  ASSERT_EQ(b.conformal.row_alpha_rad.size(), a.conformal.row_alpha_rad.size());
  for (std::size_t i = 0; i < a.conformal.row_alpha_rad.size(); ++i)
    EXPECT_NEAR(b.conformal.row_alpha_rad[i], a.conformal.row_alpha_rad[i], 1e-9);
  EXPECT_NEAR(r.force_tr.x, t.force_tr.x, 1e-3 * std::abs(t.force_tr.x));
  EXPECT_NEAR(r.force_tr.y, t.force_tr.y, 1e-3 * std::abs(t.force_tr.y) + 0.1);
  EXPECT_NEAR(r.z_ws_mm, t.z_ws_mm, 1e-6);
}

TEST(ConformalContact, InternalRollerConformsAlongXAndRollsForward) {
  // A cylinder inside a ring of 1000 mm (NOMRADR < 0) at a prescribed approach: with D=4 as with
  // D=2 the ring's circle lengthens the contact (the same force as the planar patch within 1 %:
  // the curved reference is that of a crowned rail under a cylinder, nearly planar), and the
  // material passes at the ring's surface speed.
  model::WheelRailProblem p = test_support::crowned_rail_problem(300.0);
  p.roller = {true, -1000.0, -2.0};  // the ring's surface at −2000 mm/s: the wheel rolls forward
  p.motion.vs_mm_s = 0.0;
  p.motion.vpitch_rad_s = -2000.0 / 460.0;
  p.patch.tangential.kind = model::TangentialKind::SteadyRolling;
  p.motion.z_mm = 0.02;
  model::WheelRailProblem planar = p;
  p.search.conformal = true;
  const WheelRailSolution c = WheelsetSolver().solve(p);
  const WheelRailSolution d = WheelsetSolver().solve(planar);
  ASSERT_EQ(c.patches.size(), 1U);
  ASSERT_EQ(d.patches.size(), 1U);
  const WheelRailPatch& w = c.patches[0];
  ASSERT_TRUE(w.conformal.active);
  EXPECT_NEAR(w.veloc_mm_s, 2000.0, 1.0);
  EXPECT_EQ(w.chi_rad, d.patches[0].chi_rad);
  // Free rolling at the nominal radii: D=2 takes the creepage at the reference point, where
  // ring and wheel pass at 2000 mm/s both (ξ = 0). The ring's profile is the crown, so off the
  // centre line its radius is 1000 + y²/600 mm and its material faster: D=4's average over
  // the contact (semi-width about 2.5 mm, mean y² about 2.5 mm²) is ξ ≈ −2.5/600/1000 = −4e-6.
  EXPECT_EQ(d.patches[0].xi, 0.0);
  EXPECT_LT(w.xi, -2e-6);  // measured −5.1e-6
  EXPECT_GT(w.xi, -1e-5);
  EXPECT_NEAR(w.conformal.tilde_fn, d.patches[0].solution.totals.fn,
              0.01 * d.patches[0].solution.totals.fn);
}

}  // namespace
}  // namespace rollcontact
