// Wheel/rail cases in TOML case files (docs/case-files.md): the same WheelRailRecord and the same
// answer as the .inp route, and errors with file, line and key path.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "batch/run_input.hpp"
#include "format/inp/to_wheelrail.hpp"
#include "format/toml/toml_case_reader.hpp"
#include "format/toml/toml_case_writer.hpp"
#include "rollcontact/errors.hpp"
#include "support/examples.hpp"
#include "support/files.hpp"

namespace rollcontact::batch {
namespace {

namespace fs = std::filesystem;
const fs::path examples_dir{ROLLCONTACT_EXAMPLES_DIR};
const fs::path toml_case = fs::path(ROLLCONTACT_TEST_DATA_DIR) / "toml" / "mbench_right_y3.toml";

/// `scratch` with the benchmark's two profiles copied in; returns its path.
const fs::path& with_profiles(const test_support::ScratchDir& scratch) {
  for (const char* f : {"MBench_UIC60_v3.prr", "MBench_S1002_v3.prw"})
    fs::copy_file(examples_dir / f, scratch / f);
  return scratch.path();
}

/// The example case's text with the first `from` replaced by `to` (`from` empty: as it is).
std::string toml_case_with(const std::string& from = {}, const std::string& to = {}) {
  std::ifstream in(toml_case);
  std::stringstream all;
  all << in.rdbuf();
  std::string text = all.str();
  if (!from.empty()) text.replace(text.find(from), from.size(), to);
  return text;
}

/// The message of the InputError that reading `text`, written to `file`, throws, or "accepted".
std::string read_error(const fs::path& file, const std::string& text) {
  std::ofstream(file) << text;
  try {
    (void)format::read_toml_input_file(file);
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(TomlWheelRail, SameForcesAsTheInpCase) {
  REQUIRE_EXAMPLES();
  const test_support::ScratchDir scratch("rollcontact_toml_wheelrail");
  const fs::path& dir = with_profiles(scratch);
  fs::copy_file(toml_case, dir / "case.toml");
  // The .inp twin: case 1 of the benchmark file with the wheelset of its case 7.
  std::ifstream in(examples_dir / "mbench_a22_right.inp");
  std::string text, line;
  for (int n = 1; std::getline(in, line) && n <= 26; ++n) {
    if (n == 25) line = "  0.0  3.0  10000. -0.00018030 0.0072  0.0";
    if (n == 26) line = " 2000. 0.0    0.0   0.0        0.0  -4.34515030";
    text += line + "\n";
  }
  std::ofstream(dir / "twin.inp") << text << " 0 MODULE\n";
  RunOptions options;
  const RunResult a = run_input_file(dir / "case.toml", options);
  const RunResult b = run_input_file(dir / "twin.inp", options);
  ASSERT_TRUE(a.cases.at(0).solved) << a.cases[0].error;
  ASSERT_TRUE(b.cases.at(0).solved) << b.cases[0].error;
  const WheelRailSolution& s = a.cases[0].wheelrail;
  const WheelRailSolution& t = b.cases[0].wheelrail;
  EXPECT_EQ(s.force_tr.x, t.force_tr.x);
  EXPECT_EQ(s.force_tr.y, t.force_tr.y);
  EXPECT_EQ(s.force_tr.z, t.force_tr.z);
  ASSERT_EQ(s.patches.size(), t.patches.size());
  EXPECT_EQ(s.patches[0].solution.totals.fn, t.patches[0].solution.totals.fn);
}

TEST(TomlWheelRail, ErrorsNameFileLineAndKey) {
  REQUIRE_EXAMPLES();
  const test_support::ScratchDir scratch("rollcontact_toml_wheelrail_errors");
  const fs::path& dir = with_profiles(scratch);
  const std::string text =
      toml_case_with("file = \"MBench_S1002_v3.prw\"", "file = \"missing.prw\"");
  std::ofstream(dir / "bad.toml") << text;
  try {
    (void)format::read_toml_input_file(dir / "bad.toml");
    FAIL() << "a missing profile file was accepted";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("bad.toml:"), std::string::npos) << m;
    EXPECT_NE(m.find("case[1].wheel_rail.wheel.file"), std::string::npos) << m;
    EXPECT_NE(m.find("missing.prw"), std::string::npos) << m;
  }
  // Module-3-only readers refuse a wheel/rail case with a clear message.
  EXPECT_THROW((void)format::read_toml_file(toml_case), InputError);
}

TEST(TomlWheelRail, ProfileChecksAreTheInpReadersWithTheirKeys) {
  // The checks the .inp reader makes on a profile line (format/inp/profile_spec_checks), here
  // with TOML's names: a profile scaled as if in metres, a wheel's slices as the rail and rail
  // slices placed by a gauge height.
  REQUIRE_EXAMPLES();
  const test_support::ScratchDir scratch("rollcontact_toml_wheelrail_profiles");
  const fs::path& dir = with_profiles(scratch);
  const auto refused = [&](const std::string& from, const std::string& to) {
    return read_error(dir / "bad.toml", toml_case_with(from, to));
  };
  const std::string wheel = "file = \"MBench_S1002_v3.prw\"";
  const std::string metres = refused(wheel, wheel + "\nscale = 0.001");
  EXPECT_NE(metres.find("case[1].wheel_rail.wheel"), std::string::npos) << metres;
  EXPECT_NE(metres.find("outside 5..500 mm (check scale = 0.001"), std::string::npos) << metres;
  fs::copy_file(examples_dir / "S1002_flat.slcw", dir / "S1002_flat.slcw");
  const std::string rail = "file = \"MBench_UIC60_v3.prr\"";
  const std::string slcw = refused(rail, "file = \"S1002_flat.slcw\"");
  EXPECT_NE(slcw.find("case[1].wheel_rail.rail.file"), std::string::npos) << slcw;
  EXPECT_NE(slcw.find("needs a .slcs slices file"), std::string::npos) << slcw;
  fs::copy_file(examples_dir / "S1002_flat.slcw", dir / "rail.slcs");
  const std::string slcs = refused(rail, "file = \"rail.slcs\"");
  EXPECT_NE(slcs.find("need track.rail_origin_mm instead of a gauge height"), std::string::npos)
      << slcs;
}

TEST(TomlWheelRail, ConvertedBenchmarkFileGivesTheSameResults) {
  // .inp -> TOML text -> cases: every case of the benchmark file (keep digits resolved in the
  // TOML) solves to the same forces, bit for bit.
  REQUIRE_EXAMPLES();
  const auto from_inp = format::read_input_cases(examples_dir / "mbench_a22_right.inp");
  const std::string text = format::write_toml_input_string(from_inp, examples_dir);
  const auto from_toml = format::read_toml_input_string(text, "converted.toml", examples_dir);
  ASSERT_EQ(from_toml.size(), from_inp.size());
  WheelsetSolver a, b;
  for (std::size_t k = 0; k < from_inp.size(); k += 4) {  // every 4th case: 0 .. 20 mm
    const auto& wi = std::get<format::WheelRailRecord>(from_inp[k]);
    const auto& wt = std::get<format::WheelRailRecord>(from_toml[k]);
    EXPECT_EQ(wt.case_number, wi.case_number);
    const WheelRailSolution si = a.solve(format::to_wheelrail_problem(wi));
    const WheelRailSolution st = b.solve(format::to_wheelrail_problem(wt));
    EXPECT_EQ(st.force_tr.x, si.force_tr.x) << "case " << wi.case_number;
    EXPECT_EQ(st.force_tr.y, si.force_tr.y) << "case " << wi.case_number;
    EXPECT_EQ(st.force_tr.z, si.force_tr.z) << "case " << wi.case_number;
  }
}

TEST(TomlWheelRail, CaseKeysOfModule3AreReadOrRefusedNeverIgnored) {
  // name is a label; gap_weighting at the case or in the discretisation (not contradicting);
  // friction rows (V=3) and the module-3 pressure methods are refused with their keys.
  REQUIRE_EXAMPLES();
  const test_support::ScratchDir scratch("rollcontact_toml_wheelrail_case_keys");
  const fs::path& dir = with_profiles(scratch);
  const auto read = [&](const std::string& from, const std::string& to) {
    std::ofstream(dir / "variant.toml") << toml_case_with(from, to);
    try {
      return format::read_toml_input_file(dir / "variant.toml");
    } catch (const InputError& e) {
      ADD_FAILURE() << e.what();
      return std::vector<format::InputCase>{};
    }
  };
  const auto refused = [&](const std::string& from, const std::string& to) {
    return read_error(dir / "variant.toml", toml_case_with(from, to));
  };
  const std::string head = "[[case]]\n";
  const auto named = read(head, head + "name = \"y = 3 mm\"\n");
  ASSERT_EQ(named.size(), 1U);
  const auto linear = read(head, head + "gap_weighting = \"linear\"\n");
  ASSERT_EQ(linear.size(), 1U);
  EXPECT_EQ(std::get<format::WheelRailRecord>(linear[0]).digits.gapwgt, 1);
  const std::string both = refused("combination_mm = 4.0",
                                   "combination_mm = 4.0\ngap_weights = "
                                   "\"squared\"");
  EXPECT_EQ(both.find("contradicts"), std::string::npos) << "no case-level value: " << both;
  std::string twice =
      toml_case_with("combination_mm = 4.0", "combination_mm = 4.0\ngap_weights = \"squared\"");
  twice.replace(twice.find(head), head.size(), head + "gap_weighting = \"linear\"\n");
  const std::string contradiction = read_error(dir / "twice.toml", twice);
  EXPECT_NE(contradiction.find("discretisation.gap_weights: contradicts"), std::string::npos)
      << contradiction;
  const std::string rows =
      refused("static = 0.3\nkinetic = 0.3\n", "rows = [{ static = 0.3, kinetic = 0.3 }]\n");
  EXPECT_NE(rows.find("friction.rows"), std::string::npos) << rows;
  const std::string elliptic =
      refused("problem = \"steady_rolling\"\n",
              "problem = \"steady_rolling\"\n[case.normal]\nmethod = \"elliptic\"\n");
  EXPECT_NE(elliptic.find("module-3 methods"), std::string::npos) << elliptic;
}

/// The benchmark's first case with its control word 1 replaced and `extra` after line 18 (the
/// material line), followed by `more` (further cases), as an .inp text.
std::string benchmark_variant(const std::string& word1, const std::string& extra,
                              const std::string& more) {
  std::ifstream in(examples_dir / "mbench_a22_right.inp");
  std::string text, line;
  for (int n = 1; std::getline(in, line) && n <= 26; ++n) {
    if (n == 13) line = " " + word1 + "    C-P-B-T-N-F-S";
    text += line + "\n";
    if (n == 18) text += extra;
  }
  return text + more + " 0 MODULE\n";
}

TEST(TomlWheelRail, SequencesAndTheLayerConvertAndSolveTheSame) {
  // A transient-rolling sequence continued with P = 0, and B = 1 with its FLXZ: the TOML twin
  // keeps previous_state and layer_flexibility_mm3_per_N (they were refused or lost, and the
  // converted sequence started each case anew: case 2 FX -12.4 N instead of -24.2 N).
  REQUIRE_EXAMPLES();
  const test_support::ScratchDir scratch("rollcontact_toml_wheelrail_sequence");
  const fs::path& dir = with_profiles(scratch);
  const std::string next =
      "  1 MODULE\n 1002100\n 0111002\n 0100321\n  0.0  0.0  10000.  0.0 0.0  0.0\n"
      " 2000. 0.0    0.0   0.0        0.0  -4.34811810\n";
  std::ofstream(dir / "sequence.inp") << benchmark_variant("1202100", "", next + next);
  std::ofstream(dir / "layer.inp") << benchmark_variant("1213100", "  2e-5    FLXZ\n", "");
  for (const char* stem : {"sequence", "layer"}) {
    const auto from_inp = format::read_input_cases(dir / (std::string(stem) + ".inp"));
    const std::string text = format::write_toml_input_string(from_inp, dir);
    const auto from_toml = format::read_toml_input_string(text, "converted.toml", dir);
    ASSERT_EQ(from_toml.size(), from_inp.size()) << stem;
    WheelsetSolver a, b;
    for (std::size_t k = 0; k < from_inp.size(); ++k) {
      const auto& wi = std::get<format::WheelRailRecord>(from_inp[k]);
      const auto& wt = std::get<format::WheelRailRecord>(from_toml[k]);
      EXPECT_EQ(wt.digits.p, wi.digits.p) << stem << " case " << k + 1;
      EXPECT_EQ(wt.materials.flxz, wi.materials.flxz) << stem;
      const WheelRailSolution si = a.solve(format::to_wheelrail_problem(wi));
      const WheelRailSolution st = b.solve(format::to_wheelrail_problem(wt));
      EXPECT_EQ(st.force_tr.x, si.force_tr.x) << stem << " case " << k + 1;
      EXPECT_EQ(st.force_tr.y, si.force_tr.y) << stem << " case " << k + 1;
    }
  }
}

TEST(TomlWheelRail, FrictionAlongTheRailRoundTrip) {
  // mbench_a22_varfric: friction with the rail's inclination (V=1; cases 1-4, planar and
  // conformal) and along the track (V=2; cases 6, 7) as [case.friction] `along` and `points`:
  // the records' friction sets, and the answers of the cases solved in sequence, are the .inp's
  // bit for bit.
  REQUIRE_EXAMPLES();
  const auto from_inp = format::read_input_cases(examples_dir / "mbench_a22_varfric.inp");
  const std::string text = format::write_toml_input_string(from_inp, examples_dir);
  EXPECT_NE(text.find("along = \"inclination\""), std::string::npos);
  EXPECT_NE(text.find("along = \"track\""), std::string::npos);
  const auto from_toml = format::read_toml_input_string(text, "varfric.toml", examples_dir);
  ASSERT_EQ(from_toml.size(), from_inp.size());
  WheelsetSolver a, b;
  for (std::size_t k = 0; k < from_inp.size(); ++k) {
    const auto& wi = std::get<format::WheelRailRecord>(from_inp[k]);
    const auto& wt = std::get<format::WheelRailRecord>(from_toml[k]);
    SCOPED_TRACE("case " + std::to_string(wi.case_number));
    EXPECT_EQ(wt.digits.v, wi.digits.v);
    EXPECT_EQ(wt.variable_friction.v, wi.variable_friction.v);
    EXPECT_EQ(wt.variable_friction.positions, wi.variable_friction.positions);
    ASSERT_EQ(wt.variable_friction.sets.size(), wi.variable_friction.sets.size());
    for (std::size_t j = 0; j < wi.variable_friction.sets.size(); ++j)
      EXPECT_EQ(wt.variable_friction.sets[j].fkin, wi.variable_friction.sets[j].fkin);
    const WheelRailSolution si = a.solve(format::to_wheelrail_problem(wi, true));
    const WheelRailSolution st = b.solve(format::to_wheelrail_problem(wt, true));
    EXPECT_EQ(st.force_tr.x, si.force_tr.x);
    EXPECT_EQ(st.force_tr.y, si.force_tr.y);
    EXPECT_EQ(st.force_tr.z, si.force_tr.z);
  }
}

TEST(TomlWheelRail, FrictionPointsAreCheckedWithTheirKeys) {
  const std::string head =
      "[[case]]\n[case.normal]\nforce_N = 100\n[case.grid]\nhertz = { a_mm = 1, b_mm = 1 }\n"
      "[case.material]\nbody1 = { poisson = 0.28, shear_modulus_MPa = 82000 }\n"
      "body2 = { poisson = 0.28, shear_modulus_MPa = 82000 }\n[case.friction]\n";
  auto message = [&](const std::string& friction) {
    try {
      (void)format::read_toml_input_string(head + friction, "f.toml", ".");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  // A module-3 case has no rail to vary along.
  EXPECT_NE(message("along = \"track\"\npoints = [{ at = 0, kinetic = 0.3 }]\n")
                .find("is for wheel/rail cases"),
            std::string::npos);
  // A wheel/rail case: at most NVF = 10 points, strictly increasing, with `along` (as .inp).
  REQUIRE_EXAMPLES();
  const test_support::ScratchDir scratch("rollcontact_toml_friction_points");
  const fs::path& dir = with_profiles(scratch);
  const std::string coulomb = "static = 0.3\nkinetic = 0.3\n";
  auto wheel_rail_message = [&](const std::string& friction) {
    return read_error(dir / "f.toml", toml_case_with(coulomb, friction));
  };
  std::string eleven = "along = \"track\"\npoints = [";
  for (int k = 0; k < 11; ++k) eleven += fmt::format("{{ at = {}, kinetic = 0.3 }}, ", k);
  EXPECT_NE(wheel_rail_message(eleven + "]\n").find("at most 10 control points"),
            std::string::npos);
  EXPECT_NE(wheel_rail_message("along = \"track\"\npoints = [{ at = 1, kinetic = 0.3 }, "
                               "{ at = 1, kinetic = 0.2 }]\n")
                .find("strictly increasing"),
            std::string::npos);
  EXPECT_NE(wheel_rail_message("points = [{ at = 1, kinetic = 0.3 }]\n").find("'along'"),
            std::string::npos);
  EXPECT_EQ(wheel_rail_message("along = \"inclination\"\npoints = [{ at = -0.3, kinetic = 0.2 "
                               "}, { at = -0.1, kinetic = 0.3 }]\n"),
            "accepted");
}

TEST(TomlWheelRail, S1002On54E1ExampleAndItsTwin) {
  // examples/s1002_54e1.inp (the static case and the rolling case with traction of
  // docs/validation-fe.md) and its TOML twin solve to the same answers bit for bit. Case 1
  // balances: FZ as prescribed, and with no tangential problem the patch carries only its normal
  // force FN, tilted by the contact angle δ, so FZ(TR) = FN cos δ and FY(TR) = −FN sin δ. Case 2
  // (F=1) drives with FX = 0.25·FZ, and its pressure is case 1's: equal materials, no coupling.
  const fs::path repo_examples = fs::path(ROLLCONTACT_TEST_DATA_DIR) / ".." / ".." / "examples";
  const auto from_inp = format::read_input_cases(repo_examples / "s1002_54e1.inp");
  const auto from_toml = format::read_toml_input_file(repo_examples / "toml" / "s1002_54e1.toml");
  ASSERT_EQ(from_inp.size(), 2u);
  ASSERT_EQ(from_toml.size(), 2u);
  WheelsetSolver inp_solver, toml_solver;
  std::vector<WheelRailSolution> si, st;
  for (std::size_t k = 0; k < 2; ++k) {
    si.push_back(inp_solver.solve(
        format::to_wheelrail_problem(std::get<format::WheelRailRecord>(from_inp[k]))));
    st.push_back(toml_solver.solve(
        format::to_wheelrail_problem(std::get<format::WheelRailRecord>(from_toml[k]))));
    ASSERT_TRUE(si[k].converged) << si[k].message;
    ASSERT_EQ(si[k].patches.size(), 1u);
    ASSERT_EQ(st[k].patches.size(), 1u);
    EXPECT_EQ(st[k].force_tr.x, si[k].force_tr.x);
    EXPECT_EQ(st[k].force_tr.y, si[k].force_tr.y);
    EXPECT_EQ(st[k].force_tr.z, si[k].force_tr.z);
    EXPECT_EQ(st[k].vpitch_rad_s, si[k].vpitch_rad_s);
    EXPECT_EQ(st[k].patches[0].solution.totals.pmax, si[k].patches[0].solution.totals.pmax);
    EXPECT_EQ(st[k].patches[0].solution.totals.contact_area,
              si[k].patches[0].solution.totals.contact_area);
  }
  const double eps = 1e-5;  // EPS of the file
  EXPECT_NEAR(si[0].force_tr.z, 1e5, 10.0 * eps * 1e5);
  const WheelRailPatch& p = si[0].patches[0];
  const double fn = p.solution.totals.fn;
  EXPECT_NEAR(si[0].force_tr.z, fn * std::cos(p.contact_angle_rad), 1e-9 * fn);
  EXPECT_NEAR(si[0].force_tr.y, -fn * std::sin(p.contact_angle_rad), 1e-9 * fn);
  EXPECT_EQ(si[0].force_tr.x, 0.0);
  // Case 2: F_x/F_z = FX_WS/FZ within EPS·μ, the wheel faster than free rolling, and PMAX and
  // the approach those of case 1 scaled by Hertz (∝ FN^(1/3), FN^(2/3)) within 0.1 %: FN
  // differs by the lateral force's share of FZ (F_s·sin δ ≈ 0.2 % of FZ).
  EXPECT_NEAR(si[1].force_ws.x / si[1].force_tr.z, -0.25, eps * 0.5);
  EXPECT_LT(si[1].vpitch_rad_s, -38888.9 / 460.0);
  const Totals& rolling = si[1].patches[0].solution.totals;
  const double ratio = rolling.fn / fn;
  const double pmax = p.solution.totals.pmax * std::cbrt(ratio);
  const double pen = p.solution.totals.pen * std::pow(ratio, 2.0 / 3.0);
  EXPECT_NEAR(rolling.pmax, pmax, 1e-3 * pmax);
  EXPECT_NEAR(rolling.pen, pen, 1e-3 * pen);
}

TEST(TomlWheelRail, RollerRigExampleAndItsTwin) {
  // examples/roller_rig.inp (C1 = 5) and its TOML twin solve to the same answers bit for bit.
  // Case 1: the roller's surface passes at RPITCH·NOMRADR = 2000 mm/s, rolling forward (χ = 0).
  // Case 2: the yawed wheelset touches the roller behind its top (x < 0). Case 3: a ring of the
  // same surface speed conforms, its patch is longer and carries less pressure than case 1's.
  const fs::path repo_examples = fs::path(ROLLCONTACT_TEST_DATA_DIR) / ".." / ".." / "examples";
  const auto from_inp = format::read_input_cases(repo_examples / "roller_rig.inp");
  const auto from_toml = format::read_toml_input_file(repo_examples / "toml" / "roller_rig.toml");
  ASSERT_EQ(from_inp.size(), 3u);
  ASSERT_EQ(from_toml.size(), 3u);
  WheelsetSolver inp_solver, toml_solver;
  std::vector<WheelRailSolution> si;
  for (std::size_t k = 0; k < 3; ++k) {
    const model::WheelRailProblem p =
        format::to_wheelrail_problem(std::get<format::WheelRailRecord>(from_inp[k]));
    ASSERT_TRUE(p.roller.enabled);
    si.push_back(inp_solver.solve(p));
    const WheelRailSolution st = toml_solver.solve(
        format::to_wheelrail_problem(std::get<format::WheelRailRecord>(from_toml[k])));
    ASSERT_TRUE(si[k].converged) << si[k].message;
    ASSERT_EQ(si[k].patches.size(), 1u);
    ASSERT_EQ(st.patches.size(), 1u);
    EXPECT_EQ(st.force_tr.x, si[k].force_tr.x);
    EXPECT_EQ(st.force_tr.y, si[k].force_tr.y);
    EXPECT_EQ(st.force_tr.z, si[k].force_tr.z);
    EXPECT_NEAR(si[k].force_tr.z, 1e4, 1e4 * 1e-5 * 1.01);
    EXPECT_NEAR(si[k].patches[0].veloc_mm_s, 2000.0, 1.0);
    EXPECT_EQ(si[k].patches[0].chi_rad, 0.0);
  }
  EXPECT_NEAR(si[0].patches[0].reference_tr.x, 0.0, 1e-6);
  EXPECT_LT(si[1].patches[0].reference_tr.x, -1.0);
  const Totals &outer = si[0].patches[0].solution.totals, &ring = si[2].patches[0].solution.totals;
  EXPECT_GT(ring.contact_area, 1.2 * outer.contact_area);
  EXPECT_LT(ring.pmax, 0.8 * outer.pmax);
}

TEST(TomlWheelRail, FlexibleWheelsetExampleAndItsTwin) {
  // examples/flexible_wheelset.inp (E = 4) and its TOML twin: the same answers bit for bit.
  // Case 2's wheel, yawed back by the wheelset's 7.2 mrad on it, touches at its lowest point
  // (x = 0 in wheel-profile coordinates); case 3's lateral rate VYWHL = 20 mm/s lowers η·V by
  // its component along the patch, 20·cos δ, against case 2 (the yaw rate VYAWW about the
  // marker moves the contact point along x only: its lever is lateral, x = 0).
  const fs::path repo_examples = fs::path(ROLLCONTACT_TEST_DATA_DIR) / ".." / ".." / "examples";
  const auto from_inp = format::read_input_cases(repo_examples / "flexible_wheelset.inp");
  const auto from_toml =
      format::read_toml_input_file(repo_examples / "toml" / "flexible_wheelset.toml");
  ASSERT_EQ(from_inp.size(), 3u);
  ASSERT_EQ(from_toml.size(), 3u);
  WheelsetSolver inp_solver, toml_solver;
  std::vector<WheelRailSolution> si;
  for (std::size_t k = 0; k < 3; ++k) {
    const auto& wi = std::get<format::WheelRailRecord>(from_inp[k]);
    const auto& wt = std::get<format::WheelRailRecord>(from_toml[k]);
    EXPECT_EQ(wt.wheel_deviations.dyaw, wi.wheel_deviations.dyaw);
    EXPECT_EQ(wt.wheel_deviations.vy, wi.wheel_deviations.vy);
    si.push_back(inp_solver.solve(format::to_wheelrail_problem(wi)));
    const WheelRailSolution st = toml_solver.solve(format::to_wheelrail_problem(wt));
    ASSERT_TRUE(si[k].converged) << si[k].message;
    ASSERT_EQ(si[k].patches.size(), 1u);
    ASSERT_EQ(st.patches.size(), 1u);
    EXPECT_EQ(st.force_tr.x, si[k].force_tr.x);
    EXPECT_EQ(st.force_tr.y, si[k].force_tr.y);
    EXPECT_EQ(st.force_tr.z, si[k].force_tr.z);
  }
  EXPECT_GT(std::abs(si[0].patches[0].reference_wheel.x), 0.1);
  EXPECT_NEAR(si[1].patches[0].reference_wheel.x, 0.0, 1e-3);
  const WheelRailPatch &still = si[1].patches[0], &moving = si[2].patches[0];
  EXPECT_NEAR(moving.eta * moving.veloc_mm_s - still.eta * still.veloc_mm_s,
              -20.0 * std::cos(moving.contact_angle_rad), 1e-3);
}

TEST(TomlWheelRail, ReportsNameTheRollerAndTheFlexibleWheel) {
  // The .out report says WHEEL-ROLLER and TOTAL FORCES ON ROLLER on a roller rig, X_WS and
  // RPITCH in the wheelset block, and prints the deviations of a flexible wheel.
  const fs::path repo_examples = fs::path(ROLLCONTACT_TEST_DATA_DIR) / ".." / ".." / "examples";
  const test_support::ScratchDir scratch("rollcontact_roller_report");
  const fs::path& out = scratch.path();
  RunOptions options;
  options.output_dir = out;
  auto report_of = [&](const char* name) {
    const RunResult r = run_input_file(repo_examples / name, options);
    EXPECT_EQ(r.failed, 0) << name;
    std::ifstream in(r.report_path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  };
  const std::string roller = report_of("roller_rig.inp");
  EXPECT_NE(roller.find(" WHEEL-ROLLER CONTACT, RIGHT WHEEL"), std::string::npos);
  EXPECT_NE(roller.find(" TOTAL FORCES ON ROLLER"), std::string::npos);
  EXPECT_NE(roller.find("     X_WS        Y_WS"), std::string::npos);
  EXPECT_NE(roller.find("     RPITCH      VY_WS"), std::string::npos);
  EXPECT_EQ(roller.find("FORCES ON RAIL"), std::string::npos);
  const std::string flexible = report_of("flexible_wheelset.inp");
  EXPECT_NE(flexible.find(" FLEXIBLE WHEEL-SET DEVIATIONS"), std::string::npos);
  EXPECT_NE(flexible.find("     VXWHL       VYWHL"), std::string::npos);
}

TEST(TomlWheelRail, MasslessRailRoundTrip) {
  // examples/massless_rail.inp (F=3) -> TOML -> the same rail data and the same deflections.
  const fs::path repo_examples = fs::path(ROLLCONTACT_TEST_DATA_DIR) / ".." / ".." / "examples";
  const auto from_inp = format::read_input_cases(repo_examples / "massless_rail.inp");
  const std::string text = format::write_toml_input_string(from_inp, repo_examples);
  EXPECT_NE(text.find("[case.wheel_rail.massless_rail]"), std::string::npos);
  const auto from_toml = format::read_toml_input_string(text, "converted.toml", repo_examples);
  ASSERT_EQ(from_toml.size(), from_inp.size());
  for (std::size_t k = 0; k < from_inp.size(); ++k) {
    const auto& wi = std::get<format::WheelRailRecord>(from_inp[k]);
    const auto& wt = std::get<format::WheelRailRecord>(from_toml[k]);
    EXPECT_EQ(wt.digits.f, 3);
    ASSERT_TRUE(wt.has_massless_rail);
    EXPECT_EQ(wt.massless_rail.ky, wi.massless_rail.ky);
    EXPECT_EQ(wt.massless_rail.fy, wi.massless_rail.fy);
    EXPECT_EQ(wt.massless_rail.kz, wi.massless_rail.kz);
    EXPECT_EQ(wt.massless_rail.fz, wi.massless_rail.fz);
    EXPECT_EQ(wt.massless_rail.dystep0, wi.massless_rail.dystep0);
  }
  const auto& w0 = std::get<format::WheelRailRecord>(from_inp[0]);
  const WheelRailSolution si = WheelsetSolver().solve(format::to_wheelrail_problem(w0));
  const WheelRailSolution st = WheelsetSolver().solve(
      format::to_wheelrail_problem(std::get<format::WheelRailRecord>(from_toml[0])));
  ASSERT_TRUE(si.converged) << si.message;
  EXPECT_EQ(st.rail_deflection.dy_mm, si.rail_deflection.dy_mm);
  EXPECT_EQ(st.force_tr.y, si.force_tr.y);
  // A prescribed position without a vertical rail spring has no vertical equation.
  std::string bad = text;
  bad.replace(bad.find("kz_N_per_mm = 100000.0"), 22, "kz_N_per_mm = 0.0");
  const std::string force_line = "vertical_force_N = 10000.0";
  ASSERT_NE(bad.find(force_line), std::string::npos);
  bad.replace(bad.find(force_line), force_line.size(), "");
  bad.replace(bad.find("y_mm = 9.0"), 10, "y_mm = 9.0\nz_mm = -7.0");
  try {
    (void)format::read_toml_input_string(bad, "bad.toml", repo_examples);
    ADD_FAILURE() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("kz_N_per_mm"), std::string::npos) << e.what();
    EXPECT_GT(e.line(), 0);
  }
}

TEST(TomlWheelRail, ConvertedBackToInpSolvesTheSame) {
  // `rollcontact convert case.toml case.inp` (module 1: every value explicit, the profiles named
  // relative to the .inp file): the .inp file solves to the TOML case's answer bit for bit.
  REQUIRE_EXAMPLES();
  const test_support::ScratchDir scratch("rollcontact_toml_to_inp");
  const fs::path& dir = with_profiles(scratch);
  fs::copy_file(toml_case, dir / "case.toml");
  fs::create_directories(dir / "sub");
  const std::string command = std::string(ROLLCONTACT_CLI) + " convert -q \"" +
                              (dir / "case.toml").string() + "\" \"" +
                              (dir / "sub" / "case.inp").string() + "\"";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  std::ifstream written(dir / "sub" / "case.inp");
  std::stringstream text;
  text << written.rdbuf();
  EXPECT_NE(text.str().find("'../MBench_UIC60_v3.prr'"), std::string::npos) << text.str();
  RunOptions options;
  const RunResult a = run_input_file(dir / "case.toml", options);
  const RunResult b = run_input_file(dir / "sub" / "case.inp", options);
  ASSERT_TRUE(a.cases.at(0).solved) << a.cases[0].error;
  ASSERT_TRUE(b.cases.at(0).solved) << b.cases[0].error;
  const WheelRailSolution& s = a.cases[0].wheelrail;
  const WheelRailSolution& t = b.cases[0].wheelrail;
  EXPECT_EQ(s.z_ws_mm, t.z_ws_mm);
  EXPECT_EQ(s.force_tr.x, t.force_tr.x);
  EXPECT_EQ(s.force_tr.y, t.force_tr.y);
  EXPECT_EQ(s.force_tr.z, t.force_tr.z);
  ASSERT_EQ(s.patches.size(), t.patches.size());
  EXPECT_EQ(s.patches[0].solution.totals.fn, t.patches[0].solution.totals.fn);
}

}  // namespace
}  // namespace rollcontact::batch

namespace rollcontact {
namespace {

TEST(TomlWheelRail, ConformalExampleAndItsTwin) {
  // examples/conformal_flange_root.inp: the same flange-root contact planar (case 1) and
  // conformal (case 2, D=4); the TOML twin solves to the same answers bit for bit. Sliding at
  // μ = 0.3, the two agree on the vertical and longitudinal forces, while the conformal
  // tractions turned row by row into the tangent plane give a lateral force 2 % lower.
  const std::filesystem::path repo_examples =
      std::filesystem::path(ROLLCONTACT_TEST_DATA_DIR) / ".." / ".." / "examples";
  const auto from_inp = format::read_input_cases(repo_examples / "conformal_flange_root.inp");
  const auto from_toml =
      format::read_toml_input_file(repo_examples / "toml" / "conformal_flange_root.toml");
  ASSERT_EQ(from_inp.size(), 2u);
  ASSERT_EQ(from_toml.size(), 2u);
  WheelsetSolver inp_solver, toml_solver;
  std::vector<WheelRailSolution> si;
  for (std::size_t k = 0; k < 2; ++k) {
    const model::WheelRailProblem p =
        format::to_wheelrail_problem(std::get<format::WheelRailRecord>(from_inp[k]));
    EXPECT_EQ(p.search.conformal, k == 1);
    si.push_back(inp_solver.solve(p));
    const WheelRailSolution st = toml_solver.solve(
        format::to_wheelrail_problem(std::get<format::WheelRailRecord>(from_toml[k])));
    ASSERT_TRUE(si[k].converged) << si[k].message;
    ASSERT_EQ(si[k].patches.size(), 1u);
    ASSERT_EQ(st.patches.size(), 1u);
    EXPECT_EQ(st.force_tr.x, si[k].force_tr.x);
    EXPECT_EQ(st.force_tr.y, si[k].force_tr.y);
    EXPECT_EQ(st.force_tr.z, si[k].force_tr.z);
    EXPECT_EQ(st.patches[0].conformal.active, k == 1);
  }
  EXPECT_NEAR(si[1].force_tr.x, si[0].force_tr.x, 1e-2 * std::abs(si[0].force_tr.x));
  EXPECT_NEAR(si[1].force_tr.z, si[0].force_tr.z, 5.0);
  EXPECT_LT(si[1].force_tr.y, 0.99 * si[0].force_tr.y);  // measured 561 vs 573 N
}

}  // namespace
}  // namespace rollcontact
