// Wheel/rail (module-1) cases written back to .inp: every module-1 example of CONTACT and of the
// repository reads back to the same cases (compared through their resolved TOML form, which names
// every value), writing is a fixed point, and profiles given as points become companion tables
// that read back to the same points.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "format/inp/inp_reader.hpp"
#include "format/inp/inp_writer.hpp"
#include "format/toml/toml_case_reader.hpp"
#include "format/toml/toml_case_writer.hpp"
#include "rollcontact/errors.hpp"
#include "support/examples.hpp"
#include "support/files.hpp"

namespace rollcontact::format {
namespace {

namespace fs = std::filesystem;
const fs::path examples_dir{ROLLCONTACT_EXAMPLES_DIR};
const fs::path repo_examples = fs::path(ROLLCONTACT_TEST_DATA_DIR) / ".." / ".." / "examples";

std::vector<InputCase> without_source(std::vector<InputCase> cases) {
  for (auto& c : cases) std::visit([](auto& r) { r.source = {}; }, c);
  return cases;
}

/// Two lists of cases describe the same problems when their TOML forms are equal (every value
/// with round-trip precision, profile files relative to `dir`).
std::string as_toml(const std::vector<InputCase>& cases, const fs::path& dir) {
  return write_toml_input_string(without_source(cases), dir);
}

void expect_round_trip(const fs::path& inp) {
  const fs::path dir = inp.parent_path();
  const std::vector<InputCase> original = read_input_cases(inp);
  ASSERT_FALSE(original.empty());
  const InpText written = write_inp_text(original, dir);
  EXPECT_TRUE(written.companions.empty()) << "every profile of an .inp file has a file";
  std::vector<InputCase> again;
  ASSERT_NO_THROW(again =
                      read_input_string(written.text, inp.stem().string() + "_written.inp", dir))
      << written.text;
  ASSERT_EQ(again.size(), original.size());
  for (std::size_t k = 0; k < original.size(); ++k) {
    ASSERT_EQ(again[k].index(), original[k].index()) << "case index " << k;
    if (const auto* r = std::get_if<WheelRailRecord>(&original[k])) {
      const auto& s = std::get<WheelRailRecord>(again[k]);
      EXPECT_EQ(s.case_number, r->case_number);
      EXPECT_EQ(s.wheel.sliced, r->wheel.sliced);
      // The same points, read from the same files.
      const Profile& a = s.wheel.sliced ? s.wheel.slices->slices.front() : *s.wheel.profile;
      const Profile& b = r->wheel.sliced ? r->wheel.slices->slices.front() : *r->wheel.profile;
      EXPECT_EQ(a.y, b.y);
      EXPECT_EQ(a.z, b.z);
      EXPECT_EQ(s.rail.profile->z, r->rail.profile->z);
    }
  }
  EXPECT_EQ(as_toml(again, dir), as_toml(original, dir));
  // Writing what was read gives the same text again: the explicit form is a fixed point.
  EXPECT_EQ(write_inp_text(without_source(again), dir).text,
            write_inp_text(without_source(original), dir).text);
}

class InpWriterModule1 : public ::testing::TestWithParam<std::string> {};

TEST_P(InpWriterModule1, ContactExampleReadsBackToTheSameCases) {
  REQUIRE_EXAMPLES();
  expect_round_trip(examples_dir / (GetParam() + ".inp"));
}

// Keep digits of every kind (the benchmark files' follow-up cases), KPEC/ANALYN, friction
// along the rail (V=1, 2), conformal search (D=4), and wheel slices (a wheel flat).
INSTANTIATE_TEST_SUITE_P(Module1Examples, InpWriterModule1,
                         ::testing::Values("mbench_a22_right", "mbench_a22_left", "mbench_a22_kpec",
                                           "mbench_a22_varfric", "wheelflat"),
                         [](const auto& param_info) { return std::string(param_info.param); });

TEST(InpWriterModule1, RepositoryExamplesReadBackToTheSameCases) {
  // A massless rail (F=3), roller rigs (C1=4,5), a flexible wheelset (E=5), the 54E1 head,
  // planar and conformal flange-root contact and a viscoelastic wheel (M=1).
  for (const char* name : {"massless_rail", "roller_rig", "flexible_wheelset",
                           "conformal_flange_root", "s1002_54e1", "viscoelastic_wheel"}) {
    SCOPED_TRACE(name);
    expect_round_trip(repo_examples / (std::string(name) + ".inp"));
  }
}

TEST(InpWriterModule1, FollowUpCasesAreWrittenWithEveryBlock) {
  // Case 2 of the benchmark keeps almost everything (0111002 / 0100321): written, it carries
  // its own digits, friction, materials, discretisation, track and wheelset.
  REQUIRE_EXAMPLES();
  const std::vector<InputCase> cases = read_input_cases(examples_dir / "mbench_a22_right.inp");
  const std::string text = write_inp_text({cases.at(1)}, examples_dir).text;
  for (const char* expected :
       {"  1  MODULE\n", "  1203100 ", "  0022033 0 ", "  0000321 ", "  999 100 30 1 1e-05 20000 ",
        "  0.3 0.3 ", "  0.28 0.28 82000. 82000. ", "  'MBench_UIC60_v3.prr' 0 1. 0. 0 2 ",
        "  'MBench_S1002_v3.prw' 0 1. 0. 0 2 ", "  1360. -70. 460. 1000. ", "  0  MODULE\n"})
    EXPECT_NE(text.find(expected), std::string::npos) << expected << " missing in\n" << text;
}

/// A TOML wheel/rail case with the rail profile given as points (a 300 mm arc, 60 mm wide, z
/// downwards) and the benchmark's wheel.
std::string points_case(const fs::path& wheel_file, const std::string& wheel_options = "") {
  std::string y = "[", z = "[";
  for (int k = 0; k <= 60; ++k) {
    const double yk = -30.0 + k;
    y += (k ? ", " : "") + std::to_string(yk);
    z += (k ? ", " : "") + std::to_string(yk * yk / 600.0);
  }
  return "version = 1\n[[case]]\n[case.friction]\nlaw = \"coulomb\"\nstatic = 0.3\nkinetic = 0.3\n"
         "[case.material]\nbody1 = { poisson = 0.28, shear_modulus_MPa = 82000.0 }\n"
         "body2 = { poisson = 0.28, shear_modulus_MPa = 82000.0 }\n"
         "[case.wheel_rail]\nvertical_force_N = 10000.0\n"
         "[case.wheel_rail.discretisation]\nelement_size_mm = [0.5, 0.5]\n"
         "[case.wheel_rail.track]\ngauge_height_mm = 14.0\ngauge_width_mm = 1435.0\n"
         "[case.wheel_rail.rail]\npoints = { y_mm = " +
         y + "], z_mm = " + z +
         "] }\nmirror_z = \"no\"\n"
         "[case.wheel_rail.wheelset]\nflange_back_distance_mm = 1360.0\n"
         "flange_back_position_mm = -70.0\nnominal_radius_mm = 460.0\n"
         "[case.wheel_rail.wheel]\nfile = \"" +
         wheel_file.generic_string() + "\"\n" + wheel_options +
         "[case.wheel_rail.position]\ny_mm = 0.0\n"
         "[case.wheel_rail.velocity]\nforward_mm_per_s = 2000.0\npitch_rad_per_s = -4.348\n";
}

TEST(InpWriterModule1, ProfilePointsBecomeACompanionTable) {
  const test_support::ScratchDir scratch("rollcontact_inp_points");
  const fs::path wheel = fs::absolute(repo_examples / "profiles" / "MBench_S1002_v3.prw");
  const std::vector<InputCase> cases =
      read_toml_input_string(points_case(wheel), "points.toml", scratch.path());
  const auto& r = std::get<WheelRailRecord>(cases.at(0));
  ASSERT_TRUE(r.rail.path.empty());
  write_inp_input_file(scratch / "points.inp", cases);
  ASSERT_TRUE(fs::exists(scratch / "points_rail1.txt"));
  const std::vector<InputCase> again = read_input_cases(scratch / "points.inp");
  const auto& s = std::get<WheelRailRecord>(again.at(0));
  EXPECT_EQ(s.rail.file, "points_rail1.txt");
  // Bit for bit the points the TOML case holds (canonical: y ascending, z downwards).
  EXPECT_EQ(s.rail.profile->y, r.rail.profile->y);
  EXPECT_EQ(s.rail.profile->z, r.rail.profile->z);
  EXPECT_EQ(s.wheel.profile->z, r.wheel.profile->z);
  EXPECT_EQ(s.motion.fz, r.motion.fz);
}

TEST(InpWriterModule1, EqualPointsInSeveralCasesShareOneTable) {
  // Two cases read from TOML separately hold two copies of the same rail points: one table.
  const test_support::ScratchDir scratch("rollcontact_inp_points_shared");
  const fs::path wheel = fs::absolute(repo_examples / "profiles" / "MBench_S1002_v3.prw");
  std::vector<InputCase> cases =
      read_toml_input_string(points_case(wheel), "points.toml", scratch.path());
  cases.push_back(read_toml_input_string(points_case(wheel), "points.toml", scratch.path()).at(0));
  ASSERT_NE(std::get<WheelRailRecord>(cases[0]).rail.profile,
            std::get<WheelRailRecord>(cases[1]).rail.profile);
  const std::vector<fs::path> written = write_inp_input_file(scratch / "two.inp", cases);
  EXPECT_EQ(written.size(), 1U);
  EXPECT_TRUE(fs::exists(scratch / "two_rail1.txt"));
  EXPECT_FALSE(fs::exists(scratch / "two_rail2.txt"));
  const std::vector<InputCase> again = read_input_cases(scratch / "two.inp");
  ASSERT_EQ(again.size(), 2U);
  for (const InputCase& c : again)
    EXPECT_EQ(std::get<WheelRailRecord>(c).rail.file, "two_rail1.txt");
}

TEST(InpWriterModule1, ACompanionNeverReplacesAProfileTheCasesRead) {
  // The rail points' table would be named like the wheel's own profile file (a plain table of a
  // 1:20 cone): refused, nothing written.
  const test_support::ScratchDir scratch("rollcontact_inp_points_clash");
  {
    std::ofstream wheel(scratch / "out_rail1.txt");
    for (int k = 0; k <= 130; ++k) wheel << 70.0 - k << " " << 0.05 * (70.0 - k) << "\n";
  }
  const std::vector<InputCase> cases = read_toml_input_string(
      points_case(scratch / "out_rail1.txt", "mirror_z = \"no\"\n"), "points.toml", scratch.path());
  EXPECT_THROW(write_inp_input_file(scratch / "out.inp", cases), InputError);
  EXPECT_FALSE(fs::exists(scratch / "out.inp"));
}

}  // namespace
}  // namespace rollcontact::format
