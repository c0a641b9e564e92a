// Module-1 transient sequences (T=1 shifts, T=2 transient rolling; spec/wheelrail-advanced.md
// §5.2–5.4): each patch lives on a super grid that keeps its elements in place from case to
// case, so the previous case's tractions carry over. Checked against what the physics says:
// rolling from rest builds the tractions up over the contact length and ends in the steady
// state (T=3); a shift with zero increments keeps its tractions, a further shift adds to them.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <variant>

#include "format/inp/inp_reader.hpp"
#include "format/inp/to_wheelrail.hpp"
#include "rollcontact/wheelrail.hpp"
#include "support/examples.hpp"
#include "support/files.hpp"
#include "wheelrail_problems.hpp"

namespace rollcontact {
namespace {

/// A yawed cylinder on the crowned rail at 10 kN, turning 0.1 % slower than free rolling:
/// longitudinal and lateral creepage of about 1e-3 and 4e-3, partly sliding.
model::WheelRailProblem creeping_wheel(model::TangentialKind kind) {
  model::WheelRailProblem p = test_support::crowned_rail_problem(300.0);
  p.patch.tangential.kind = kind;
  p.vertical = model::VerticalLoading::Force;
  p.motion.fz_N = 10000.0;
  p.motion.yaw_rad = 0.004;
  p.motion.vpitch_rad_s *= 0.999;
  return p;
}

TEST(WheelRailTransient, RollingFromRestReachesTheSteadyState) {
  WheelsetSolver steady_solver;
  const WheelRailSolution steady =
      steady_solver.solve(creeping_wheel(model::TangentialKind::SteadyRolling));
  ASSERT_TRUE(steady.converged) << steady.message;
  ASSERT_EQ(steady.patches.size(), 1u);
  // 0.2 mm per step (DQREL = 1) over a contact about 6.6 mm long: 33 steps to roll through it.
  WheelsetSolver solver;
  model::WheelRailProblem p = creeping_wheel(model::TangentialKind::TransientRolling);
  std::vector<double> fx, fy;
  for (int step = 0; step < 70; ++step) {
    p.patch.sequence.continue_previous = step > 0;  // P = 2 first, then P = 0
    p.first_of_sequence = step == 0;
    p.motion.s_mm = 0.2 * step;
    const WheelRailSolution s = solver.solve(p);
    ASSERT_TRUE(s.converged) << "step " << step << ": " << s.message;
    ASSERT_EQ(s.patches.size(), 1u);
    fx.push_back(s.force_tr.x);
    fy.push_back(s.force_tr.y);
  }
  const double fx_ss = steady.force_tr.x, fy_ss = steady.force_tr.y;
  ASSERT_GT(std::abs(fx_ss), 100.0);
  // The first step has slipped 0.2 mm only: a fraction of the steady creep forces.
  EXPECT_LT(std::abs(fx.front()), 0.5 * std::abs(fx_ss));
  // Rolled 14 mm, twice the contact length: the steady state. Measured: 97 % of F_x after 10
  // steps, then a slow tail (the adhesion zone's tractions), 7e-5 off after 70 steps.
  EXPECT_NEAR(fx.back(), fx_ss, 1e-3 * std::abs(fx_ss));
  EXPECT_NEAR(fy.back(), fy_ss, 1e-3 * std::abs(fy_ss));
  // And it got there monotonically in F_x after the first steps (no lost tractions between the
  // moving grids: a restart would drop F_x back towards the first step's).
  for (std::size_t k = 3; k < fx.size(); ++k)
    EXPECT_LT(std::abs(fx[k] - fx_ss), std::abs(fx[3] - fx_ss) + 0.01 * std::abs(fx_ss))
        << "step " << k;
}

/// The crowned rail under a cylinder at 10 kN shifted sideways (T=1: the velocity line holds
/// one step's increments): the wheelset moves by 2 µm laterally, nothing else.
model::WheelRailProblem lateral_shift() {
  model::WheelRailProblem p = test_support::crowned_rail_problem(300.0);
  p.patch.tangential.kind = model::TangentialKind::Shift;
  p.vertical = model::VerticalLoading::Force;
  p.motion.fz_N = 10000.0;
  p.motion.vs_mm_s = 0.0;
  p.motion.vpitch_rad_s = 0.0;
  p.motion.vy_mm_s = 0.002;
  return p;
}

TEST(WheelRailTransient, ShiftWithZeroIncrementsKeepsTheTractions) {
  // T=1: the velocity line holds the increments of one step. A lateral shift of the wheelset by
  // 2 µm loads the contact sideways (Cattaneo); a case with zero increments keeps that load; a
  // second shift of 2 µm adds to it.
  model::WheelRailProblem p = lateral_shift();
  WheelsetSolver solver;
  p.patch.sequence.continue_previous = false;
  const WheelRailSolution first = solver.solve(p);
  ASSERT_TRUE(first.converged) << first.message;
  ASSERT_EQ(first.patches.size(), 1u);
  EXPECT_NEAR(first.patches[0].eta, -0.002, 1e-9);  // a shift distance: V = 1
  EXPECT_EQ(first.patches[0].veloc_mm_s, 1.0);
  p.patch.sequence.continue_previous = true;
  p.first_of_sequence = false;
  p.motion.vy_mm_s = 0.0;
  const WheelRailSolution kept = solver.solve(p);
  ASSERT_TRUE(kept.converged) << kept.message;
  EXPECT_NEAR(kept.force_tr.y, first.force_tr.y, 1e-4 * std::abs(first.force_tr.y) + 0.1);
  ASSERT_GT(std::abs(first.force_tr.y), 100.0);
  p.motion.vy_mm_s = 0.002;
  const WheelRailSolution more = solver.solve(p);
  ASSERT_TRUE(more.converged) << more.message;
  EXPECT_GT(std::abs(more.force_tr.y), 1.3 * std::abs(first.force_tr.y));
  EXPECT_LT(std::abs(more.force_tr.y), 0.3 * 10000.0 * 1.001);
  // Without the previous case (P = 2) the same increments give the first case's load again.
  p.patch.sequence.continue_previous = false;
  const WheelRailSolution fresh = solver.solve(p);
  EXPECT_NEAR(fresh.force_tr.y, first.force_tr.y, 1e-4 * std::abs(first.force_tr.y) + 0.1);
}

TEST(WheelRailTransient, BenchmarkRolledThroughTheInpRoute) {
  // mbench_a22_right case 7 (y 3 mm, yaw 7.2 mrad: tread contact) as T=2 from rest, 40 steps of
  // 0.2 mm (P=2, then P=0 with S_WS advancing), against the file's own T=3 answer.
  REQUIRE_EXAMPLES();
  const std::filesystem::path dir{ROLLCONTACT_EXAMPLES_DIR};
  std::ifstream in(dir / "mbench_a22_right.inp");
  std::string text, line;
  for (int n = 1; std::getline(in, line) && n <= 26; ++n) {
    if (n == 13) line = " 1202100";  // T=2, P=2
    if (n == 25) line = "  0.0  3.0  10000. -0.00018030 0.0072  0.0";
    if (n == 26) line = " 2000. 0.0    0.0   0.0        0.0  -4.34515030";
    text += line + "\n";
  }
  for (int step = 1; step < 40; ++step)
    text += " 1 MODULE\n 1002100\n 0111002\n 0100321\n  " + std::to_string(0.2 * step) +
            "  3.0  10000. -0.00018030 0.0072  0.0\n 2000. 0.0 0.0 0.0 0.0 -4.34515030\n";
  text += " 0 MODULE\n";
  const test_support::ScratchDir scratch("rc_transient");
  for (const char* f : {"MBench_UIC60_v3.prr", "MBench_S1002_v3.prw"})
    std::filesystem::copy_file(dir / f, scratch / f);
  const std::filesystem::path file = scratch / "transient.inp";
  std::ofstream(file) << text;
  const auto cases = format::read_input_cases(file);
  ASSERT_EQ(cases.size(), 40u);
  WheelsetSolver solver;
  WheelRailSolution last;
  for (const auto& c : cases) {
    last = solver.solve(format::to_wheelrail_problem(std::get<format::WheelRailRecord>(c)));
    ASSERT_TRUE(last.converged) << last.message;
  }
  // CONTACT's steady answer (mbench_a22_right.ref_out case 7): FX(TR) -417.5, FY(TR) -1988 N.
  EXPECT_NEAR(last.force_tr.x, -417.5, 0.005 * 417.5);
  EXPECT_NEAR(last.force_tr.y, -1988.0, 0.005 * 1988.0);
}

TEST(WheelRailTransient, ConformalRollingFromRestReachesTheConformalSteadyState) {
  // D=4 on the super grid (wheelrail-advanced.md §1.9): rows at multiples of DS of the rail's
  // own arc length, the grid carried with the wheelset; rolling from rest ends at D=4's steady
  // state as D=2's does at its own.
  model::WheelRailProblem steady_problem = creeping_wheel(model::TangentialKind::SteadyRolling);
  steady_problem.search.conformal = true;
  WheelsetSolver steady_solver;
  const WheelRailSolution steady = steady_solver.solve(steady_problem);
  ASSERT_TRUE(steady.converged) << steady.message;
  ASSERT_EQ(steady.patches.size(), 1u);
  WheelsetSolver solver;
  model::WheelRailProblem p = creeping_wheel(model::TangentialKind::TransientRolling);
  p.search.conformal = true;
  WheelRailSolution last;
  for (int step = 0; step < 70; ++step) {
    p.patch.sequence.continue_previous = step > 0;
    p.first_of_sequence = step == 0;
    p.motion.s_mm = 0.2 * step;
    last = solver.solve(p);
    ASSERT_TRUE(last.converged) << "step " << step << ": " << last.message;
    ASSERT_EQ(last.patches.size(), 1u);
    ASSERT_TRUE(last.patches[0].conformal.active);
  }
  // Steady rows lie at multiples of DS from the reference point, the super grid's at multiples
  // of DS of the rail's arc length (the reference at s_rail).
  const ConformalPatch &a = steady.patches[0].conformal, &b = last.patches[0].conformal;
  EXPECT_NEAR(std::remainder(a.row0_s_mm, a.ds_mm), 0.0, 1e-9);
  EXPECT_NEAR(std::remainder(b.row0_s_mm + last.patches[0].s_rail_mm, b.ds_mm), 0.0, 1e-6);
  EXPECT_NEAR(last.force_tr.x, steady.force_tr.x, 1e-3 * std::abs(steady.force_tr.x));
  EXPECT_NEAR(last.force_tr.y, steady.force_tr.y, 1e-3 * std::abs(steady.force_tr.y));
  EXPECT_NEAR(last.patches[0].xi, steady.patches[0].xi, 1e-9);
}

TEST(WheelRailTransient, ConformalShiftWithZeroIncrementsKeepsTheTractions) {
  // T=1 with D=4: a lateral shift of 2 µm, then a case with zero increments keeps the load.
  model::WheelRailProblem p = lateral_shift();
  p.search.conformal = true;
  WheelsetSolver solver;
  p.first_of_sequence = true;
  const WheelRailSolution a = solver.solve(p);
  ASSERT_TRUE(a.converged) << a.message;
  ASSERT_EQ(a.patches.size(), 1u);
  EXPECT_NEAR(a.patches[0].eta, -0.002, 1e-6);  // the shift itself, V = 1
  p.first_of_sequence = false;
  p.patch.sequence.continue_previous = true;
  p.motion.vy_mm_s = 0.0;
  const WheelRailSolution b = solver.solve(p);
  ASSERT_TRUE(b.converged) << b.message;
  EXPECT_GT(std::abs(a.force_tr.y), 100.0);
  EXPECT_NEAR(b.force_tr.y, a.force_tr.y, 1e-3 * std::abs(a.force_tr.y));
}

}  // namespace
}  // namespace rollcontact
