// Rails whose profile varies along the track (`.slcs` slices: switches and crossings; spec
// physics.md §13.9): the rail is a surface in (u = S_WS + x, y). Checked with answers known
// without it: identical slices are the plain rail; a rail that sinks linearly along the track
// carries the wheel lower by its depth at S_WS, and the contact moves to where the wheel's
// circle is parallel to the inclined rail, x = −R·dz/du; a slices file reaches the solver
// through the .inp route; the gauge-point placement is refused.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <variant>
#include <vector>

#include "format/inp/inp_reader.hpp"
#include "format/inp/to_wheelrail.hpp"
#include "rollcontact/errors.hpp"
#include "rollcontact/wheelrail.hpp"
#include "support/files.hpp"
#include "wheelrail_problems.hpp"

namespace rollcontact {
namespace {

/// The crowned rail of the track tests as slices at u = 0 and 1000 mm, the second lowered by
/// `drop_mm`; interpolated linearly between them (two slices, U_INTPOL = 1).
model::WheelRailProblem sliced_crown(double drop_mm, double s_ws_mm) {
  model::WheelRailProblem p = test_support::crowned_rail_problem(300.0);
  p.patch.tangential.kind = model::TangentialKind::SteadyRolling;
  p.vertical = model::VerticalLoading::Force;
  p.motion.fz_N = 10000.0;
  p.motion.s_mm = s_ws_mm;
  SlicedProfile& sp = p.rail.slices;
  sp.file = "crown.slcs (test)";
  sp.u_intpol = 1;
  sp.u = {0.0, 1000.0};
  Profile lowered = p.rail.points;
  for (double& z : lowered.z) z += drop_mm;
  sp.slices = {p.rail.points, lowered};
  return p;
}

WheelRailSolution solve(const model::WheelRailProblem& p) {
  WheelsetSolver solver;
  WheelRailSolution s = solver.solve(p);
  EXPECT_TRUE(s.converged) << s.message;
  EXPECT_EQ(s.patches.size(), 1u);
  return s;
}

TEST(SlicedRail, IdenticalSlicesAreThePlainRail) {
  // The slices are resampled every 0.25 mm and splined again: the same surface to ~1e-7 mm.
  model::WheelRailProblem plain = sliced_crown(0.0, 300.0);
  plain.rail.slices = {};
  const WheelRailSolution a = solve(plain), b = solve(sliced_crown(0.0, 300.0));
  ASSERT_EQ(a.patches.size(), 1u);
  ASSERT_EQ(b.patches.size(), 1u);
  EXPECT_NEAR(b.z_ws_mm, a.z_ws_mm, 1e-6);
  EXPECT_NEAR(b.patches[0].reference_tr.x, a.patches[0].reference_tr.x, 1e-6);
  EXPECT_NEAR(b.patches[0].reference_tr.y, a.patches[0].reference_tr.y, 1e-5);
  EXPECT_NEAR(b.force_tr.x, a.force_tr.x, 1e-5 * 1e4);
  EXPECT_NEAR(b.force_tr.y, a.force_tr.y, 1e-5 * 1e4);
}

TEST(SlicedRail, SinkingRailCarriesTheWheelLowerAndMovesTheContactBack) {
  // 1 mm over 1000 mm: at S_WS = 500 the rail lies 0.5 mm lower. Along x the gap is
  // s·x + x²/(2R) with s = 1e-3 and R the wheel's 460 mm: smallest at x = −s·R = −0.46 mm, where
  // it is −s²R/2 = −2.3e-4 mm, so the wheelset sits 0.5 − 2.3e-4 mm lower than on the plain rail.
  model::WheelRailProblem plain = sliced_crown(0.0, 500.0);
  plain.rail.slices = {};
  const WheelRailSolution a = solve(plain), b = solve(sliced_crown(1.0, 500.0));
  ASSERT_EQ(a.patches.size(), 1u);
  ASSERT_EQ(b.patches.size(), 1u);
  const double s = 1e-3, r = 460.0;
  EXPECT_NEAR(b.z_ws_mm - a.z_ws_mm, 0.5 - 0.5 * s * s * r, 2e-5);
  EXPECT_NEAR(b.patches[0].reference_tr.x, -s * r, 5e-3);
  EXPECT_NEAR(b.patches[0].solution.totals.fn, a.patches[0].solution.totals.fn, 1e-3 * 1e4);
  // Further along, the wheel sits lower by the rail's depth there.
  const WheelRailSolution c = solve(sliced_crown(1.0, 800.0));
  EXPECT_NEAR(c.z_ws_mm - b.z_ws_mm, 0.3, 2e-5);
}

TEST(SlicedRail, ConformalPatchOnASinkingRail) {
  // D=4 on the sinking rail: identical slices give the plain rail's conformal patch, and the
  // rail sinking 1 mm/m carries the wheelset lower by its depth as with D=2 (the curved
  // reference's rail samples lie on the 3-D surface at x_ref).
  model::WheelRailProblem plain = sliced_crown(0.0, 500.0);
  plain.rail.slices = {};
  plain.search.conformal = true;
  model::WheelRailProblem same = sliced_crown(0.0, 500.0), sinking = sliced_crown(1.0, 500.0);
  same.search.conformal = sinking.search.conformal = true;
  const WheelRailSolution a = solve(plain), b = solve(same), c = solve(sinking);
  ASSERT_TRUE(b.patches[0].conformal.active);
  EXPECT_NEAR(b.z_ws_mm, a.z_ws_mm, 1e-6);
  EXPECT_NEAR(b.force_tr.x, a.force_tr.x, 1e-5 * 1e4);
  const std::vector<double>&ra = a.patches[0].conformal.row_alpha_rad,
        &rb = b.patches[0].conformal.row_alpha_rad;
  ASSERT_EQ(ra.size(), rb.size());
  for (std::size_t i = 0; i < ra.size(); ++i) EXPECT_NEAR(rb[i], ra[i], 1e-6);
  const double s = 1e-3, r = 460.0;
  EXPECT_NEAR(c.z_ws_mm - a.z_ws_mm, 0.5 - 0.5 * s * s * r, 2e-5);
  EXPECT_NEAR(c.patches[0].reference_tr.x, -s * r, 5e-3);
}

TEST(SlicedRail, GaugePointPlacementIsRefused) {
  model::WheelRailProblem p = sliced_crown(1.0, 500.0);
  p.track.gauge_height_mm = 14.0;
  EXPECT_THROW((void)WheelsetSolver().solve(p), ProblemError);
}

TEST(SlicedRail, SlicesFileThroughTheInpRoute) {
  // A crossing-nose-like rail: a crowned head that rises 0.4 mm over 200 mm, read from a .slcs
  // file of two plain tables; the case at S_WS = 100 mm solves, the wheel sits 0.2 mm higher
  // than on the first slice alone.
  const test_support::ScratchDir scratch("rc_sliced_rail");
  const std::filesystem::path& dir = scratch.path();
  auto crown = [](double dz) {
    std::string t;
    for (int i = -120; i <= 120; ++i) {
      const double y = 0.25 * i;
      t += std::to_string(y) + " " + std::to_string(300.0 - std::sqrt(300.0 * 300.0 - y * y) + dz) +
           "\n";
    }
    return t;
  };
  std::ofstream(dir / "low.txt") << crown(0.0);
  std::ofstream(dir / "high.txt") << crown(-0.4);
  std::ofstream(dir / "nose.slcs") << "% rising head\n 0.0 1.0\n 2\n 0\n 1\n 0.0 'low.txt'\n"
                                      " 200.0 'high.txt'\n";
  std::ofstream(dir / "wheel.txt") << "-60 0\n70 0\n";
  const std::string head =
      "  1 MODULE\n 1203100\n 0022033\n 0000321\n  999 100 30 1 1e-6\n  0.3 0.3\n"
      "  0.28 0.28 82000. 82000.\n  0.2 0.2 1.0 90d 8.0 4.0\n  0.0 750.0 0.0 0.0\n";
  const std::string tail =
      "' 0 1.0 0.0\n  0 0 0 0 0 0\n  1500.0 0.0 460.0\n  'wheel.txt' 0 1.0 0.0\n"
      "  100.0 0 10000. 0 0 0\n  2000. 0 0 0 0 -4.347826\n  0 MODULE\n";
  std::ofstream(dir / "sliced.inp") << head << "  'nose.slcs" << tail;
  std::ofstream(dir / "plain.inp") << head << "  'low.txt" << tail;
  const auto sliced = format::read_input_cases(dir / "sliced.inp");
  const auto plain = format::read_input_cases(dir / "plain.inp");
  ASSERT_EQ(sliced.size(), 1u);
  const model::WheelRailProblem ps =
      format::to_wheelrail_problem(std::get<format::WheelRailRecord>(sliced[0]));
  ASSERT_EQ(ps.rail.slices.u.size(), 2u);
  const WheelRailSolution a = solve(format::to_wheelrail_problem(
                              std::get<format::WheelRailRecord>(plain[0]))),
                          b = solve(ps);
  ASSERT_EQ(b.patches.size(), 1u);
  // Slope 2e-3 rising: the contact moves forward by R·s = 0.92 mm, the wheelset rises by 0.2 mm
  // less the gap's fall s²R/2 = 9.2e-4 mm.
  EXPECT_NEAR(b.patches[0].reference_tr.x, 460.0 * 2e-3, 5e-3);
  EXPECT_NEAR(b.z_ws_mm - a.z_ws_mm, -0.2 - 0.5 * 4e-6 * 460.0, 3e-5);
}

}  // namespace
}  // namespace rollcontact
