// A wheel/rail problem built in C++ with the public API alone (rollcontact/profiles.hpp,
// rollcontact/model/wheelrail.hpp, rollcontact/wheelrail.hpp) is the problem the .inp reader
// builds: Manchester benchmark, right wheel, case 1 (mbench_a22_right.inp) gives the same
// forces as the .inp route, and CONTACT's.

#include <gtest/gtest.h>

#include <cmath>
#include <variant>

#include "format/inp/inp_reader.hpp"
#include "format/inp/to_wheelrail.hpp"
#include "rollcontact/errors.hpp"
#include "rollcontact/profiles.hpp"
#include "rollcontact/wheelrail.hpp"
#include "support/examples.hpp"

namespace rollcontact {
namespace {

/// Case 1 of mbench_a22_right.inp written out with the model's names.
model::WheelRailProblem benchmark_case_1() {
  using test_support::kExamples;
  model::WheelRailProblem p;
  p.side = model::WheelSide::Right;
  p.rail.points = read_profile(kExamples / "MBench_UIC60_v3.prr", {.is_wheel = false});
  p.wheel.points = read_profile(kExamples / "MBench_S1002_v3.prw", {.is_wheel = true});
  p.track.gauge_height_mm = 14.0;
  p.track.gauge_width_mm = 1435.0;
  p.wheelset = {.flange_back_distance_mm = 1360.0,
                .flange_back_position_mm = -70.0,
                .nominal_radius_mm = 460.0};
  p.vertical = model::VerticalLoading::Force;
  p.motion.fz_N = 10000.0;
  p.motion.vs_mm_s = 2000.0;
  p.motion.vpitch_rad_s = -4.34811810;
  p.search.dx_mm = p.search.ds_mm = 0.2;
  model::PatchProblem& patch = p.patch;
  patch.bodies.body1 = patch.bodies.body2 = {.poisson_ratio = 0.28, .shear_modulus_N_mm2 = 82000.0};
  patch.friction = {0.3, 0.3};
  patch.tangential.kind = model::TangentialKind::SteadyRolling;
  patch.solver.tolerance = 1e-5;
  patch.solver.max_newton_iterations = 30;
  return p;
}

TEST(WheelRailApi, BenchmarkCaseBuiltInCodeEqualsTheInpRoute) {
  REQUIRE_EXAMPLES();
  WheelsetSolver api_solver;
  const WheelRailSolution api = api_solver.solve(benchmark_case_1());
  ASSERT_TRUE(api.converged) << api.message;

  const std::vector<format::InputCase> cases =
      format::read_input_cases(test_support::kExamples / "mbench_a22_right.inp");
  const auto& record = std::get<format::WheelRailRecord>(cases.front());
  WheelsetSolver inp_solver;
  const WheelRailSolution inp = inp_solver.solve(format::to_wheelrail_problem(record));
  ASSERT_TRUE(inp.converged) << inp.message;

  ASSERT_EQ(api.patches.size(), 1u);
  ASSERT_EQ(inp.patches.size(), 1u);
  // Same problem, same arithmetic: equal to rounding.
  EXPECT_NEAR(api.z_ws_mm, inp.z_ws_mm, 1e-12);
  EXPECT_NEAR(api.force_tr.y, inp.force_tr.y, 1e-9);
  EXPECT_NEAR(api.patches[0].solution.totals.fn, inp.patches[0].solution.totals.fn, 1e-9);
  // CONTACT (mbench_a22_right.ref_out, case 1): FY(TR) 36.24, FZ(TR) 10000, Z_WS 0.1981,
  // FN 9997, FS −253.6 N, within validation.md's module-1 tolerances.
  EXPECT_NEAR(api.force_tr.y, 36.24, 0.005 * 36.24 + 2.0);
  EXPECT_NEAR(api.force_tr.z, 10000.0, 10.0);
  EXPECT_NEAR(api.z_ws_mm, 0.1981, 2e-3);
  EXPECT_NEAR(api.patches[0].solution.totals.fn, 9997.0, 0.005 * 9997.0 + 2.0);
  EXPECT_NEAR(api.patches[0].solution.totals.fy, -253.6, 0.005 * 253.6 + 2.0);
}

TEST(WheelRailApi, ProfileInMetresIsRejectedWithTheUnitsHint) {
  REQUIRE_EXAMPLES();
  try {
    read_profile(test_support::kExamples / "MBench_UIC60_v3.prr",
                 {.is_wheel = false, .scale_yz = 0.001});
    FAIL() << "a 0.07 mm long profile was accepted";
  } catch (const GeometryError& e) {
    EXPECT_NE(std::string(e.what()).find("SCALEYZ"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace rollcontact
