// Module-1 (wheel/rail) reader on small inputs: optional values and their defaults, keep
// semantics, variants of the layout (roller rigs, massless rail, flexible wheelset, profile
// options) and the interplay with module 3 in one file.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <tuple>
#include <utility>
#include <variant>
#include <vector>

#include "format/inp/inp_reader.hpp"
#include "format/inp/to_wheelrail.hpp"
#include "rollcontact/errors.hpp"
#include "support/files.hpp"

namespace rollcontact::format {
namespace {

// The test profiles live next to the malformed inputs that use them.
const std::filesystem::path kData = std::filesystem::path(ROLLCONTACT_TEST_DATA_DIR) / "malformed";
constexpr double kDeg = std::numbers::pi / 180.0;

std::vector<InputCase> read(const std::string& text) {
  return read_input_string(text, "m1.inp", kData);
}

const format::WheelRailRecord& wr(const std::vector<InputCase>& cases, std::size_t k) {
  return std::get<format::WheelRailRecord>(cases.at(k));
}

// Case 1 of a right wheel on track; `extra` replaces the control words where given.
std::string first_case(const std::string& w1 = "1203100", const std::string& w2 = "0022033",
                       const std::string& w3 = "0000321") {
  return " 1 MODULE\n " + w1 + "\n " + w2 + "\n " + w3 +
         "\n"
         "  999 100 30 1 1e-5 5000\n"
         "  0.30 0.30\n"
         "  0.28 0.28 82000. 82000.\n"
         "  0.2 0.25 1.0 -1.0 -8.0 -9.0 3.0 0.1\n"
         "  14.0 0 1435.0 0.5d 1e-4\n"
         "  'profiles/rail_arc.txt' 0 1.0 0.0\n"
         "  0.1 0.2 1d 0.3 0.4 2d\n"
         "  1360.0 -70.0 460.0 12.5\n"
         "  'profiles/wheel_cone.txt' 0 1.0 0.0 -1 2\n"
         "  1 150d 20d 5d 3.0\n"
         "  -1 0.25\n"
         "  0.0 1.5 10000. 0.1d 0.2d 0.3d\n"
         "  2000. 0.1 0.2 0.3 0.4 -4.3\n";
}

TEST(InpModule1, OptionalValuesAndDefaults) {
  const auto cases = read(first_case() + " 0 MODULE\n");
  ASSERT_EQ(cases.size(), 1u);
  const format::WheelRailRecord& c = wr(cases, 0);
  EXPECT_EQ(c.npot_max, 5000);
  const auto& ds = c.discretisation;
  EXPECT_DOUBLE_EQ(ds.ds, 0.25);
  EXPECT_DOUBLE_EQ(ds.a_sep, 0.0);    // negative A_SEP set to 0
  EXPECT_DOUBLE_EQ(ds.d_sep, 0.0);    // negative D_SEP set to 0 ...
  EXPECT_DOUBLE_EQ(ds.d_comb, -9.0);  // ... which is still >= D_COMB
  EXPECT_DOUBLE_EQ(ds.d_turn, 3.0);
  EXPECT_DOUBLE_EQ(ds.g_miss, 0.1);
  EXPECT_DOUBLE_EQ(c.track.cant, 0.5 * kDeg);
  EXPECT_DOUBLE_EQ(c.track.curv, 1e-4);
  EXPECT_DOUBLE_EQ(c.rail_deviations.dz, 0.2);
  EXPECT_DOUBLE_EQ(c.rail_deviations.droll, kDeg);
  EXPECT_DOUBLE_EQ(c.rail_deviations.vroll, 2.0 * kDeg);
  EXPECT_DOUBLE_EQ(c.wheelset.ytape, 12.5);
  EXPECT_EQ(c.wheel.mirror_z, -1);
  EXPECT_EQ(c.wheel.prfopt, 2);
  EXPECT_EQ(c.wheel.ismooth, 1);
  EXPECT_DOUBLE_EQ(c.wheel.zigthrs, 150.0 * kDeg);
  EXPECT_DOUBLE_EQ(c.wheel.kinkhigh, 20.0 * kDeg);
  EXPECT_DOUBLE_EQ(c.wheel.kinklow, 5.0 * kDeg);
  EXPECT_DOUBLE_EQ(c.wheel.kinkwid, 3.0);
  EXPECT_EQ(c.wheel.errhnd, -1);
  EXPECT_DOUBLE_EQ(c.wheel.maxomit, 0.25);
  EXPECT_EQ(c.rail.prfopt, 0);
  EXPECT_DOUBLE_EQ(c.rail.zigthrs, 5.0 * std::numbers::pi / 6.0);
  EXPECT_EQ(c.rail.profile->y.size(), 61u);
  EXPECT_DOUBLE_EQ(c.rail.profile->y.front(), -30.0);
  EXPECT_EQ(c.wheel.profile->y.size(), 61u);
  EXPECT_DOUBLE_EQ(c.wheel.profile->y.front(), 60.0);
  EXPECT_DOUBLE_EQ(c.motion.y, 1.5);
  EXPECT_DOUBLE_EQ(c.motion.pitch, 0.3 * kDeg);
  EXPECT_DOUBLE_EQ(c.motion.vz, 0.2);
  EXPECT_DOUBLE_EQ(c.motion.vpitch, -4.3);
}

TEST(InpModule1, KeepSemanticsAndOverrides) {
  const std::string text = first_case("1003100", "0022033", "0010321") +
                           " 1 MODULE\n 1003100\n 0100002\n 0100321\n"
                           "  0.0 2.5 12000. 0 0 0\n"
                           "  2000. 0 0 0 0 -4.2\n"
                           " 1 MODULE\n 1003100\n 0111000\n 0100321\n"
                           " 0 MODULE\n";
  const auto cases = read(text);
  ASSERT_EQ(cases.size(), 3u);
  const format::WheelRailRecord& c1 = wr(cases, 0);
  // First case of the element: P=0 and I=1 are overridden with a warning.
  EXPECT_EQ(c1.digits.p, 2);
  EXPECT_EQ(c1.digits.i, 0);
  EXPECT_EQ(c1.source.warnings.size(), 2u);
  const format::WheelRailRecord& c2 = wr(cases, 1);
  // C=0 is forced to 1 (warning); everything not read is kept.
  EXPECT_EQ(c2.digits.c, 1);
  ASSERT_EQ(c2.source.warnings.size(), 1u);
  EXPECT_NE(c2.source.warnings[0].find("C=0 overridden to 1"), std::string::npos);
  EXPECT_DOUBLE_EQ(c2.motion.y, 2.5);
  EXPECT_DOUBLE_EQ(c2.motion.fz, 12000.0);
  EXPECT_DOUBLE_EQ(c2.motion.vpitch, -4.2);
  EXPECT_DOUBLE_EQ(c2.discretisation.ds, 0.25);
  EXPECT_DOUBLE_EQ(c2.wheelset.ytape, 12.5);
  EXPECT_EQ(c2.rail.profile->y.size(), 61u);
  EXPECT_EQ(c2.npot_max, 5000);
  // E=0 keeps position and velocity too.
  const format::WheelRailRecord& c3 = wr(cases, 2);
  EXPECT_DOUBLE_EQ(c3.motion.y, 2.5);
  EXPECT_EQ(c3.case_number, 3);
  // A kept profile is the same data, not a copy: thousands of cases hold one profile.
  EXPECT_EQ(c2.rail.profile.get(), c1.rail.profile.get());
  EXPECT_EQ(c3.rail.profile.get(), c1.rail.profile.get());
  EXPECT_EQ(c3.wheel.profile.get(), c1.wheel.profile.get());
}

/// The line and message of the InputError reading `text` throws (0, "" if none).
std::pair<int, std::string> input_error(const std::string& text) {
  try {
    read(text);
  } catch (const InputError& e) {
    return {e.line(), e.message()};
  }
  return {0, ""};
}

/// first_case() with F=3 and the massless rail line after the rail deviations (line 17).
std::string massless_case(const std::string& w1, const std::string& rail_line) {
  std::string text = first_case(w1);
  const std::string deviations = "  0.1 0.2 1d 0.3 0.4 2d\n";
  text.insert(text.find(deviations) + deviations.size(), rail_line);
  return text + " 0 MODULE\n";
}

TEST(InpModule1, PrescribedPitchMomentReplacesVpitch) {
  // F=2 (docs/decisions.md "Prescribed pitch moment"): MY_WS [N mm] in place of VPITCH, with
  // N=1. The digit check had refused it while the rest of the reader read it.
  const auto cases = read(first_case("1203120") + " 0 MODULE\n");
  EXPECT_EQ(wr(cases, 0).digits.f, 2);
  EXPECT_DOUBLE_EQ(wr(cases, 0).motion.my, -4.3);
  auto [line, message] = input_error(first_case("1203020") + " 0 MODULE\n");
  EXPECT_EQ(line, 2);
  EXPECT_NE(message.find("F=2 (prescribed MY_WS) requires N=1"), std::string::npos) << message;
}

TEST(InpModule1, MasslessRailNeedsTangentialAndVerticalEquations) {
  // Accepted: T=3, N=1 (δz from FZ), and N=0 with KZRAIL > 0.
  EXPECT_EQ(input_error(massless_case("1203130", "  1e4 0 0 0\n")).first, 0);
  EXPECT_EQ(input_error(massless_case("1203030", "  1e4 0 1e5 0 0.5\n")).first, 0);
  // T=0: refused at the control line (line 2 of the text).
  auto [line, message] = input_error(massless_case("1200130", "  1e4 0 1e5 0\n"));
  EXPECT_EQ(line, 2);
  EXPECT_NE(message.find("T=0"), std::string::npos) << message;
  // N=0 without a vertical spring: refused at the massless rail line (line 12).
  std::tie(line, message) = input_error(massless_case("1203030", "  1e4 0 0 0\n"));
  EXPECT_EQ(line, 12);
  EXPECT_NE(message.find("KZRAIL"), std::string::npos) << message;
}

TEST(InpModule1, RollerRigMasslessRailAndFlexibleWheelset) {
  // C1=5 right wheel on roller, F=3 massless rail, E=5 with flexible wheel deviations.
  const std::string text =
      " 1 2 MODULE\n 5203130\n 0022035\n 10000321\n 1000000 2\n"
      "  999 100 30 1 1e-5\n"
      "  0.30 0.30\n"
      "  0.28 0.28 82000. 82000.\n"
      "  0.2 0.2 1.0 90d 8.0 4.0\n"
      "  -1 5.0 -10.0 600.0\n"
      "  'profiles/rail_arc.txt' 0 1.0 0.0\n"
      "  0 0 0 0 0 0\n"
      "  1e5 -200 2e5 300\n"
      "  1360.0 -70.0 460.0\n"
      "  'profiles/wheel_cone.txt' 0 1.0 0.0\n"
      "  10.0 0.5 10000. 0 0 0\n"
      "  3.0d 0 0 0 0 -4.3\n"
      "  0.1 0.2 0.3 1d 2d 3d\n"
      "  1 2 3 4 5 6\n"
      " 0 MODULE\n";
  const auto cases = read(text);
  ASSERT_EQ(cases.size(), 1u);
  const format::WheelRailRecord& c = wr(cases, 0);
  EXPECT_EQ(c.result_element, 2);
  EXPECT_TRUE(c.is_roller());
  EXPECT_EQ(c.digits.x, 1);
  EXPECT_EQ(c.digits.debug.p, 1);
  EXPECT_EQ(c.digits.debug.readln, 2);
  EXPECT_DOUBLE_EQ(c.track.raily0, 5.0);  // GAUGHT <= 0
  EXPECT_DOUBLE_EQ(c.track.railz0, -10.0);
  EXPECT_DOUBLE_EQ(c.track.nomradr, 600.0);
  ASSERT_TRUE(c.has_massless_rail);
  EXPECT_DOUBLE_EQ(c.massless_rail.ky, 1e5);
  EXPECT_DOUBLE_EQ(c.massless_rail.fz, 300.0);
  EXPECT_DOUBLE_EQ(c.massless_rail.dystep0, 1.0);
  EXPECT_DOUBLE_EQ(c.motion.s, 10.0);  // X_WS for rollers
  EXPECT_DOUBLE_EQ(c.motion.rpitch, 3.0 * kDeg);
  EXPECT_DOUBLE_EQ(c.wheel_deviations.dz, 0.3);
  EXPECT_DOUBLE_EQ(c.wheel_deviations.dpitch, 3.0 * kDeg);
  EXPECT_DOUBLE_EQ(c.wheel_deviations.vpitch, 6.0);
}

TEST(InpModule1, InternalRollerHasANegativeRadiusAndZeroIsRefused) {
  // NOMRADR < 0: an internal roller (a ring around the wheel); |NOMRADR| < 1 mm: no roller.
  auto roller_case = [](const std::string& nomradr) {
    return " 1 MODULE\n 5203100\n 0022033\n 0000321\n  999 100 30 1 1e-5\n  0.30 0.30\n"
           "  0.28 0.28 82000. 82000.\n  0.2 0.2 1.0 90d 8.0 4.0\n  14.0 0 1435.0 " +
           nomradr +
           "\n  'profiles/rail_arc.txt' 0 1.0 0.0\n  0 0 0 0 0 0\n  1360.0 -70.0 460.0\n"
           "  'profiles/wheel_cone.txt' 0 1.0 0.0\n  0 0 10000. 0 0 0\n  2.0 0 0 0 0 -4.3\n"
           " 0 MODULE\n";
  };
  const auto cases = read(roller_case("-1500.0"));
  ASSERT_EQ(cases.size(), 1u);
  EXPECT_DOUBLE_EQ(wr(cases, 0).track.nomradr, -1500.0);
  EXPECT_DOUBLE_EQ(wr(cases, 0).motion.rpitch, 2.0);
  const auto [line, message] = input_error(roller_case("0.0"));
  EXPECT_EQ(line, 9);
  EXPECT_NE(message.find("NOMRADR = 0"), std::string::npos) << message;
}

TEST(InpModule1, SearchVariantsAreSolvedByTheirNeighboursWithANote) {
  // D=6 and 9 (gap-grid variants) are solved as D=5, D=3, 7 and 8 (planar variants) as D=2,
  // each with a note; D=4 is conformal contact (a curved reference per patch), also for
  // shifts and transient rolling (T=1, 2) on the super grid; only wheel slices are refused.
  for (const char* w2 : {"0062033", "0092033", "0032033", "0072033", "0082033"}) {
    const auto cases = read(first_case("1203100", w2) + " 0 MODULE\n");
    const format::WheelRailRecord& c = wr(cases, 0);
    ASSERT_FALSE(c.source.warnings.empty()) << w2;
    EXPECT_NE(c.source.warnings.back().find("is solved with"), std::string::npos) << w2;
    const model::WheelRailProblem p = format::to_wheelrail_problem(c);
    const bool grid = w2[2] == '6' || w2[2] == '9';
    EXPECT_EQ(p.search.method, grid ? model::ContactSearch::GapGrid : model::ContactSearch::Locus)
        << w2;
  }
  const auto conformal = read(first_case("1203100", "0042033") + " 0 MODULE\n");
  const model::WheelRailProblem p = format::to_wheelrail_problem(wr(conformal, 0));
  EXPECT_TRUE(p.search.conformal);
  EXPECT_EQ(p.search.method, model::ContactSearch::Locus);
  const auto transient = read(first_case("1202100", "0042033") + " 0 MODULE\n");
  EXPECT_TRUE(format::to_wheelrail_problem(wr(transient, 0)).search.conformal);
}

TEST(InpModule1, FxWsReplacesVpitchWithF1) {
  const auto cases = read(first_case("1203110") + " 0 MODULE\n");
  EXPECT_DOUBLE_EQ(wr(cases, 0).motion.fx, -4.3);
  EXPECT_DOUBLE_EQ(wr(cases, 0).motion.vpitch, 0.0);
}

TEST(InpModule1, ForceDampingIsRefusedWhereItWouldAct) {
  // M2=2 (damping line after the materials): a new sequence (P=2) has no damping and is solved;
  // a case that continues it (P=0) would add C·dF/dt, which is not implemented: refused per case
  // instead of reported undamped. Zero time constants damp nothing and stay accepted.
  std::string text = first_case("1203100", "0022033 2");
  const std::string materials = "  0.28 0.28 82000. 82000.\n";
  text.replace(text.find(materials), materials.size(), materials + "  0.001 0.002 1e6 2e6\n");
  const std::string next_position =
      "  0.0 1.6 10000. 0.1d 0.2d 0.3d\n  2000. 0.1 0.2 0.3 0.4 -4.3\n";
  text += " 1 MODULE\n 1003100\n 0111002\n 0100321\n" + next_position;  // P=0: continues
  text += " 1 MODULE\n 1203100\n 0111002\n 0100321\n" + next_position;  // P=2: new sequence
  const auto cases = read(text + " 0 MODULE\n");
  ASSERT_EQ(cases.size(), 3u);
  EXPECT_TRUE(wr(cases, 1).damping.enabled);
  EXPECT_DOUBLE_EQ(wr(cases, 1).damping.cdampt, 0.002);
  EXPECT_NO_THROW((void)to_wheelrail_problem(wr(cases, 0)));
  try {
    (void)to_wheelrail_problem(wr(cases, 1));
    ADD_FAILURE() << "a damped continuation was accepted";
  } catch (const NotSupportedError& e) {
    EXPECT_NE(std::string(e.what()).find("force damping M2=2"), std::string::npos) << e.what();
  }
  EXPECT_NO_THROW((void)to_wheelrail_problem(wr(cases, 2)));
  format::WheelRailRecord undamped = wr(cases, 1);
  undamped.damping.cdampn = undamped.damping.cdampt = 0.0;
  EXPECT_NO_THROW((void)to_wheelrail_problem(undamped));
}

TEST(InpModule1, CaseNumbersAreSharedWithModule3) {
  const std::string module3 =
      " 3 MODULE\n 100\n 022020\n 0000001\n  100 100 30 1 1e-4\n  0.1 0 0 0\n"
      "  0.3 0.3\n  0.28 0.28 82000 82000\n  1\n  3 3 -1.5 -1.5 1 1\n  1 1\n"
      "  0.01 0 0.01 0 0 0\n";
  const auto cases = read(module3 + first_case() + module3 + " 0 MODULE\n");
  ASSERT_EQ(cases.size(), 3u);
  EXPECT_EQ(input_case_module(cases[0]), 3);
  EXPECT_EQ(input_case_module(cases[1]), 1);
  EXPECT_EQ(input_case_module(cases[2]), 3);
  EXPECT_EQ(std::get<format::CaseRecord>(cases[0]).case_number, 1);
  EXPECT_EQ(wr(cases, 1).case_number, 2);
  EXPECT_EQ(std::get<format::CaseRecord>(cases[2]).case_number, 3);
  // The module-3 reader refuses files with module-1 cases, at the module line.
  try {
    read_inp_string(module3 + first_case() + " 0 MODULE\n", "m1.inp", kData);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 13);
    EXPECT_NE(e.message().find("module 1 (wheel/rail) input is not supported yet"),
              std::string::npos);
  }
}

TEST(InpModule1, RZeroContinuesWithoutModuleLine) {
  const std::string text = first_case("1203100", "0022033", "0000320") +
                           " 1203100\n 0111002\n 0100321\n  0 3.0 10000. 0 0 0\n"
                           "  2000. 0 0 0 0 -4.3\n 0 MODULE\n";
  const auto cases = read(text);
  ASSERT_EQ(cases.size(), 2u);
  EXPECT_EQ(wr(cases, 1).source.module_line, 0);
  EXPECT_DOUBLE_EQ(wr(cases, 1).motion.y, 3.0);
}

TEST(InpModule1, ProfileNamesWithWindowsSeparators) {
  // Issue 18: 'profiles\rail_arc.txt' names profiles/rail_arc.txt on every platform, as in CONTACT.
  std::string text = first_case();
  text.replace(text.find("profiles/rail_arc.txt"), 21, "profiles\\rail_arc.txt");
  const auto cases = read(text + " 0 MODULE\n");
  ASSERT_EQ(cases.size(), 1u);
  EXPECT_EQ(std::filesystem::path(wr(cases, 0).rail.path).filename(), "rail_arc.txt");
  EXPECT_GE(wr(cases, 0).rail.profile->y.size(), 2u);
}

TEST(InpModule1, ErrorsInsideProfileFilesNameTheProfileFile) {
  const test_support::ScratchDir scratch("rc_m1_profile_err");
  const std::filesystem::path& dir = scratch.path();
  { std::ofstream(dir / "bad.txt") << "0 0\n1 1\n2 oops\n"; }
  std::string text = first_case();
  text.replace(text.find("profiles/wheel_cone.txt"), 23, "bad.txt");
  text.replace(text.find("profiles/rail_arc.txt"), 21, (kData / "profiles/rail_arc.txt").string());
  try {
    read_input_string(text + " 0 MODULE\n", "m1.inp", dir);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), (dir / "bad.txt").string());
    EXPECT_EQ(e.line(), 3);
    EXPECT_EQ(e.offending(), "oops");
    EXPECT_NE(e.message().find("wheel profile named at m1.inp:13"), std::string::npos)
        << e.message();
  }
}

}  // namespace
}  // namespace rollcontact::format
