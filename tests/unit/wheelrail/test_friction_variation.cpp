// Friction that varies with the contact's place (CONTACT's V=1, 2 in module 1; physics.md
// §10.4): the interpolation itself, and the Manchester benchmark variant mbench_a22_varfric
// case 4 through the C++ API, against CONTACT's printed coefficient and forces.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <variant>

#include "format/inp/inp_reader.hpp"
#include "format/inp/to_wheelrail.hpp"
#include "rollcontact/errors.hpp"
#include "rollcontact/wheelrail.hpp"
#include "support/examples.hpp"
#include "wheelrail/friction_variation.hpp"

namespace rollcontact::wheelrail {
namespace {

TEST(FrictionVariation, LinearBetweenControlPointsConstantOutside) {
  model::FrictionVariation v;
  v.along = model::FrictionVariation::Along::RailInclination;
  v.positions = {-0.3491, -0.1745};
  v.values = {{0.2, 0.2}, {0.3, 0.3}};
  EXPECT_DOUBLE_EQ(friction_at(v, -1.0).static_coefficient, 0.2);
  EXPECT_DOUBLE_EQ(friction_at(v, 0.0).static_coefficient, 0.3);
  const double mid = 0.5 * (-0.3491 - 0.1745);
  EXPECT_NEAR(friction_at(v, mid).static_coefficient, 0.25, 1e-12);
  EXPECT_NEAR(friction_at(v, mid).kinetic_coefficient, 0.25, 1e-12);
}

TEST(FrictionVariation, BenchmarkCase4ThroughTheApiGivesContactsNumbers) {
  REQUIRE_EXAMPLES();
  const std::filesystem::path dir{ROLLCONTACT_EXAMPLES_DIR};
  const auto cases = format::read_input_cases(dir / "mbench_a22_varfric.inp");
  auto record = std::get<format::WheelRailRecord>(cases.at(3));  // y = 5.5 mm, yaw 13.2 mrad
  ASSERT_EQ(record.variable_friction.v, 1);
  const format::VariableFriction table = record.variable_friction;
  record.variable_friction = {};
  record.subsurface = {};
  model::WheelRailProblem p = format::to_wheelrail_problem(record);
  p.friction_variation.along = model::FrictionVariation::Along::RailInclination;
  p.friction_variation.positions = table.positions;
  for (const auto& f : table.sets) p.friction_variation.values.push_back({f.fstat, f.fkin});
  WheelsetSolver solver;
  const WheelRailSolution s = solver.solve(p);
  ASSERT_TRUE(s.converged) << s.message;
  ASSERT_EQ(s.patches.size(), 1U);
  const WheelRailPatch& w = s.patches[0];
  // CONTACT: DELTCP -0.3363 rad, FSTAT 0.2076, FX(TR) -608.6 N, FY(TR) 1417 N, FN 9907 N.
  // The coefficient is interpolated at the contact angle in the wheel-profile frame (δ minus
  // the wheelset's roll, −0.3358 rad): CONTACT's 0.2076 to its printed digits.
  EXPECT_NEAR(w.contact_angle_rad, -0.3363, 1.05e-4);
  EXPECT_NEAR(w.friction.static_coefficient, 0.2076, 5e-5);
  // Forces within the module-1 validation tolerance: 5e-3 relative + 2e-4·FZ.
  auto tol = [](double f) { return 5e-3 * std::abs(f) + 2.0; };
  EXPECT_NEAR(s.force_tr.x, -608.6, tol(608.6));
  EXPECT_NEAR(s.force_tr.y, 1417.0, tol(1417.0));
  EXPECT_NEAR(w.solution.totals.fn, 9907.0, tol(9907.0));
}

TEST(FrictionVariation, TurnedPatchesAreRefusedThroughTheInpRouteOnly) {
  // mbench_a22_varfric case 3: tread and flange-root patches between D_SEP and D_TURN apart
  // along the contact (the mean of the rail's and the wheel's arc between the regions' zero
  // crossings, 6.815 mm), their angles turned towards their weighted mean by (D_TURN − d)/
  // (D_TURN − D_SEP): CONTACT's −0.2480 and −0.2930 rad (unturned −0.1326 and −0.2984). The
  // turned tread patch's approach is its interpenetration along its own normal. The angles
  // move by 11 rad per mm of z_ws, and the flange patch (0.25 % softer than CONTACT's, as the
  // benchmark's flange contacts are) sets z_ws 2e-5 mm higher than CONTACT's: 3e-4 rad, beyond
  // the validation's 1e-4, so the .inp route (validated_only) refuses the case; the API solves
  // it. V=1 takes the friction at the turned angle in the wheel's frame: 0.258 on the tread
  // patch, as CONTACT's FS/FN.
  REQUIRE_EXAMPLES();
  const std::filesystem::path dir{ROLLCONTACT_EXAMPLES_DIR};
  const auto cases = format::read_input_cases(dir / "mbench_a22_varfric.inp");
  model::WheelRailProblem p =
      format::to_wheelrail_problem(std::get<format::WheelRailRecord>(cases.at(2)));
  ASSERT_TRUE(p.validated_only);
  EXPECT_THROW((void)WheelsetSolver().solve(p), NotSupportedError);
  p.validated_only = false;
  const WheelRailSolution s = WheelsetSolver().solve(p);
  ASSERT_TRUE(s.converged) << s.message;
  ASSERT_EQ(s.patches.size(), 2U);
  EXPECT_NEAR(s.patches[0].contact_angle_rad, -0.2480, 4e-4);
  EXPECT_NEAR(s.patches[1].contact_angle_rad, -0.2930, 1.05e-4);
  EXPECT_NEAR(s.patches[0].friction.static_coefficient, 0.258, 1e-3);
  // The patches' forces and the tread's approach within the module-1 validation tolerances
  // (0.5 % + 2e-4·FZ; approach 0.5 %): tread 1536 N at 6.464 µm, flange 8244 N. Along the
  // turned normal the tread's approach was 6.505 µm and its force 1548 N.
  auto tol = [](double f) { return 5e-3 * std::abs(f) + 2.0; };
  EXPECT_NEAR(s.patches[0].solution.totals.fn, 1536.0, tol(1536.0));
  EXPECT_NEAR(s.patches[1].solution.totals.fn, 8244.0, tol(8244.0));
  EXPECT_NEAR(s.patches[0].solution.totals.pen, 6.464e-3, 5e-3 * 6.464e-3);
  // Solved, but said: the warning names what is not validated.
  ASSERT_FALSE(s.warnings.empty());
  EXPECT_NE(s.warnings.back().find("not validated against CONTACT: patches between D_SEP and "
                                   "D_TURN"),
            std::string::npos);
}

}  // namespace
}  // namespace rollcontact::wheelrail
