// The module-1 (wheel/rail) CONTACT examples parse into WheelRailProblems, with spot checks of
// parsed values against the files (spec/inp-format.md §5.2).

#include <gtest/gtest.h>

#include <filesystem>
#include <numbers>
#include <string>
#include <variant>
#include <vector>

#include "format/inp/inp_reader.hpp"
#include "support/examples.hpp"

namespace rollcontact::format {
namespace {

using test_support::kExamples;
constexpr double kDeg = std::numbers::pi / 180.0;

std::vector<format::WheelRailRecord> wheel_rail_cases(const std::string& name) {
  std::vector<format::WheelRailRecord> out;
  for (auto& c : read_input_cases(kExamples / name)) {
    EXPECT_EQ(input_case_module(c), 1);
    out.push_back(std::get<format::WheelRailRecord>(std::move(c)));
  }
  return out;
}

struct ExampleCount {
  const char* file;
  std::size_t cases;
};

TEST(InpModule1Examples, CaseCounts) {
  REQUIRE_EXAMPLES();
  for (const auto& ex : {ExampleCount{"mbench_a22_right.inp", 21},
                         {"mbench_a22_left.inp", 21},
                         {"mbench_a22_kpec.inp", 9},
                         {"mbench_a22_varfric.inp", 7},
                         {"wheelflat.inp", 26}}) {
    SCOPED_TRACE(ex.file);
    std::vector<format::WheelRailRecord> cases;
    ASSERT_NO_THROW(cases = wheel_rail_cases(ex.file));
    ASSERT_EQ(cases.size(), ex.cases);
    for (std::size_t k = 0; k < cases.size(); ++k) {
      EXPECT_EQ(cases[k].case_number, static_cast<int>(k) + 1);
      EXPECT_EQ(cases[k].result_element, 0);
      EXPECT_EQ(cases[k].source.file, (kExamples / ex.file).string());
      EXPECT_GT(cases[k].source.module_line, 0);
      // Every case has a rail and a wheel profile (stored from case 1 where kept).
      EXPECT_GE(cases[k].rail.profile->y.size() + cases[k].rail.slices->slices.size(), 2u);
      EXPECT_TRUE(cases[k].wheel.sliced || cases[k].wheel.profile->y.size() >= 2u);
    }
  }
}

TEST(InpModule1Examples, MbenchLeftCase1AsAnnotated) {
  REQUIRE_EXAMPLES();
  const auto cases = wheel_rail_cases("mbench_a22_left.inp");
  const format::WheelRailRecord& c = cases.at(0);
  EXPECT_EQ(c.source.module_line, 12);
  EXPECT_EQ(c.source.first_line, 13);
  EXPECT_EQ(c.config, 0);
  EXPECT_TRUE(c.is_left());
  const ControlDigits& d = c.digits;
  EXPECT_EQ(d.p, 2);
  EXPECT_EQ(d.b, 0);
  EXPECT_EQ(d.t, 3);
  EXPECT_EQ(d.n, 1);
  EXPECT_EQ(d.f, 0);
  EXPECT_EQ(d.s, 0);
  EXPECT_EQ(d.v, 0);
  EXPECT_EQ(d.l, 0);
  EXPECT_EQ(d.d, 2);
  EXPECT_EQ(d.c, 2);
  EXPECT_EQ(d.m, 0);
  EXPECT_EQ(d.z, 3);
  EXPECT_EQ(d.e, 3);
  EXPECT_EQ(d.h, 0);
  EXPECT_EQ(d.g, 0);
  EXPECT_EQ(d.a, 0);
  EXPECT_EQ(d.o, 3);
  EXPECT_EQ(d.w, 2);
  EXPECT_EQ(d.r, 1);
  EXPECT_EQ(c.solver.maxgs, 999);
  EXPECT_EQ(c.solver.maxin, 100);
  EXPECT_EQ(c.solver.maxnr, 30);
  EXPECT_EQ(c.solver.maxout, 1);
  EXPECT_DOUBLE_EQ(c.solver.eps, 1e-5);
  EXPECT_EQ(c.npot_max, 20000);
  EXPECT_EQ(c.friction.law, 0);
  EXPECT_DOUBLE_EQ(c.friction.fstat, 0.3);
  EXPECT_DOUBLE_EQ(c.friction.fkin, 0.3);
  EXPECT_DOUBLE_EQ(c.materials.poiss1, 0.28);
  EXPECT_DOUBLE_EQ(c.materials.gg2, 82000.0);
  EXPECT_EQ(c.discretisation.method, 2);
  EXPECT_DOUBLE_EQ(c.discretisation.dx, 0.2);
  EXPECT_DOUBLE_EQ(c.discretisation.ds, 0.2);
  EXPECT_DOUBLE_EQ(c.discretisation.dqrel, 1.0);
  EXPECT_DOUBLE_EQ(c.discretisation.a_sep, 90.0 * kDeg);
  EXPECT_DOUBLE_EQ(c.discretisation.d_sep, 8.0);
  EXPECT_DOUBLE_EQ(c.discretisation.d_comb, 4.0);
  EXPECT_DOUBLE_EQ(c.discretisation.d_turn, 12.0);  // default 2 D_SEP - D_COMB
  EXPECT_DOUBLE_EQ(c.discretisation.g_miss, -1.0);
  EXPECT_DOUBLE_EQ(c.track.gaught, 14.0);
  EXPECT_DOUBLE_EQ(c.track.gaugsq, 0.0);
  EXPECT_DOUBLE_EQ(c.track.gaugwd, 1435.0);
  EXPECT_DOUBLE_EQ(c.track.cant, 0.0);
  EXPECT_EQ(c.rail.file, "MBench_UIC60_v3.prr");
  EXPECT_EQ(c.rail.path, (kExamples / "MBench_UIC60_v3.prr").lexically_normal().string());
  EXPECT_EQ(c.rail.mirror_y, 0);
  EXPECT_DOUBLE_EQ(c.rail.scale_yz, 1.0);
  EXPECT_DOUBLE_EQ(c.rail.smooth, 0.0);
  EXPECT_EQ(c.rail.mirror_z, 0);
  EXPECT_FALSE(c.rail.sliced);
  EXPECT_EQ(c.rail.profile->format, ProfileFormat::Simpack);
  EXPECT_EQ(c.rail.profile->y.size(), 495u);
  EXPECT_LT(c.rail.profile->y.front(), c.rail.profile->y.back());  // rail: ascending y
  EXPECT_DOUBLE_EQ(c.rail_deviations.dy, 0.0);
  EXPECT_DOUBLE_EQ(c.wheelset.fbdist, 1360.0);
  EXPECT_DOUBLE_EQ(c.wheelset.fbpos, -70.0);
  EXPECT_DOUBLE_EQ(c.wheelset.nomradw, 460.0);
  EXPECT_DOUBLE_EQ(c.wheelset.ytape, 1000.0);
  EXPECT_EQ(c.wheel.file, "MBench_S1002_v3.prw");
  EXPECT_EQ(c.wheel.profile->format, ProfileFormat::Simpack);
  EXPECT_EQ(c.wheel.profile->y.size(), 399u);  // one of 400 points repeats its predecessor
  EXPECT_GT(c.wheel.profile->y.front(), c.wheel.profile->y.back());  // wheel: descending y
  EXPECT_DOUBLE_EQ(c.motion.s, 0.0);
  EXPECT_DOUBLE_EQ(c.motion.y, 0.0);
  EXPECT_DOUBLE_EQ(c.motion.fz, 10000.0);
  EXPECT_DOUBLE_EQ(c.motion.vs, 2000.0);
  EXPECT_DOUBLE_EQ(c.motion.vpitch, -4.34811810);

  // Follow-up cases: L=1, D=1, C=1, Z=0, E=2, G=1: only position and velocity are read.
  const format::WheelRailRecord& c2 = cases.at(1);
  EXPECT_EQ(c2.digits.l, 1);
  EXPECT_EQ(c2.digits.d, 1);
  EXPECT_EQ(c2.digits.z, 0);
  EXPECT_EQ(c2.digits.e, 2);
  EXPECT_EQ(c2.digits.g, 1);
  EXPECT_EQ(c2.digits.i, 0);
  EXPECT_DOUBLE_EQ(c2.motion.y, 0.5);
  EXPECT_DOUBLE_EQ(c2.motion.roll, -0.00002304);
  EXPECT_DOUBLE_EQ(c2.motion.yaw, 0.0012);
  EXPECT_DOUBLE_EQ(c2.motion.vpitch, -4.34741340);
  EXPECT_DOUBLE_EQ(c2.discretisation.dx, 0.2);  // kept
  EXPECT_DOUBLE_EQ(c2.friction.fkin, 0.3);      // kept
  EXPECT_EQ(c2.rail.profile->y.size(), 495u);   // kept
  EXPECT_EQ(c2.solver.maxgs, 999);              // kept
  EXPECT_TRUE(c2.source.warnings.empty());
  EXPECT_DOUBLE_EQ(cases.at(20).motion.y, 10.0);
}

TEST(InpModule1Examples, MbenchRightIsRightWheel) {
  REQUIRE_EXAMPLES();
  const auto cases = wheel_rail_cases("mbench_a22_right.inp");
  EXPECT_EQ(cases.at(0).config, 1);
  EXPECT_FALSE(cases.at(0).is_left());
}

TEST(InpModule1Examples, KpecUsesModifiedFastsimMaterial) {
  REQUIRE_EXAMPLES();
  const auto cases = wheel_rail_cases("mbench_a22_kpec.inp");
  const format::WheelRailRecord& c = cases.at(0);
  EXPECT_EQ(c.digits.b, 5);
  EXPECT_EQ(c.digits.m, 3);
  EXPECT_EQ(c.digits.a, 1);
  EXPECT_DOUBLE_EQ(c.materials.model_params[0], 1.0);  // K0_MF
  EXPECT_DOUBLE_EQ(c.materials.model_params[2], 1.0);  // BETAMF
  EXPECT_EQ(cases.at(3).digits.b, 6);                  // ANALYN
  EXPECT_EQ(cases.at(6).digits.b, 0);                  // CONTACT
  EXPECT_EQ(cases.at(6).digits.m, 0);
}

TEST(InpModule1Examples, VarfricTablesAndSubsurface) {
  REQUIRE_EXAMPLES();
  const auto cases = wheel_rail_cases("mbench_a22_varfric.inp");
  const format::WheelRailRecord& c = cases.at(0);
  EXPECT_EQ(c.digits.v, 1);
  EXPECT_EQ(c.digits.s, 3);
  ASSERT_EQ(c.variable_friction.positions.size(), 2u);
  EXPECT_DOUBLE_EQ(c.variable_friction.positions[0], -20.0 * kDeg);
  EXPECT_DOUBLE_EQ(c.variable_friction.positions[1], -10.0 * kDeg);
  EXPECT_DOUBLE_EQ(c.variable_friction.sets[0].fkin, 0.2);
  EXPECT_DOUBLE_EQ(c.variable_friction.sets[1].fstat, 0.3);
  EXPECT_DOUBLE_EQ(c.friction.fkin, 0.2);
  EXPECT_DOUBLE_EQ(c.discretisation.d_sep, 6.0);
  EXPECT_EQ(c.subsurface.matfil, 2);
  EXPECT_EQ(c.subsurface.output, 1);
  ASSERT_EQ(c.subsurface.blocks.size(), 1u);
  EXPECT_EQ(c.subsurface.blocks[0].z.size(), 11u);
  // Case 5: conformal discretisation D=4 with a new discretisation line, friction kept (V=1).
  const format::WheelRailRecord& c4 = cases.at(4);
  EXPECT_EQ(c4.digits.d, 4);
  EXPECT_EQ(c4.discretisation.method, 4);
  EXPECT_DOUBLE_EQ(c4.discretisation.d_sep, 9.0);
  EXPECT_EQ(c4.variable_friction.positions.size(), 2u);
  EXPECT_EQ(cases.at(2).digits.s, 1);  // stored subsurface points
  // Case 6: V=2, friction against the track position.
  const format::WheelRailRecord& c5 = cases.at(5);
  EXPECT_EQ(c5.digits.v, 2);
  ASSERT_EQ(c5.variable_friction.positions.size(), 2u);
  EXPECT_DOUBLE_EQ(c5.variable_friction.positions[1], 100.0);
  EXPECT_DOUBLE_EQ(c5.variable_friction.sets[1].fkin, 0.3);
  EXPECT_DOUBLE_EQ(c5.motion.s, 60.0);
}

TEST(InpModule1Examples, WheelflatSlicesAndPitch) {
  REQUIRE_EXAMPLES();
  const auto cases = wheel_rail_cases("wheelflat.inp");
  const format::WheelRailRecord& c = cases.at(0);
  EXPECT_DOUBLE_EQ(c.discretisation.dx, 0.4);
  EXPECT_DOUBLE_EQ(c.track.cant, 0.02);
  EXPECT_EQ(c.rail.mirror_z, -1);
  EXPECT_EQ(c.rail.profile->format, ProfileFormat::Simpack);
  EXPECT_DOUBLE_EQ(c.wheelset.nomradw, 490.0);
  EXPECT_TRUE(c.wheel.sliced);
  EXPECT_EQ(c.wheel.mirror_z, -1);
  EXPECT_DOUBLE_EQ(c.wheel.smooth, 5.0);
  const SlicedProfile& sp = *c.wheel.slices;
  ASSERT_EQ(sp.slices.size(), 258u);
  ASSERT_EQ(sp.u.size(), 258u);
  EXPECT_EQ(sp.u_intpol, 2);
  EXPECT_DOUBLE_EQ(sp.u.front(), -3.0995);
  EXPECT_EQ(sp.slices.front().y.size(), 150u);
  for (std::size_t k = 1; k < sp.u.size(); ++k) EXPECT_GT(sp.u[k], sp.u[k - 1]);
  EXPECT_DOUBLE_EQ(c.motion.fz, 125000.0);
  EXPECT_DOUBLE_EQ(c.motion.pitch, -25.0 * kDeg);
  EXPECT_DOUBLE_EQ(cases.at(1).motion.pitch, -26.0 * kDeg);
  EXPECT_TRUE(cases.at(1).wheel.sliced);  // kept (E=2)
  EXPECT_DOUBLE_EQ(cases.at(25).motion.pitch, -50.0 * kDeg);
}

}  // namespace
}  // namespace rollcontact::format
