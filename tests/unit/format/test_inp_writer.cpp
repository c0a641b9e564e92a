// .inp -> Problems -> .inp text -> Problems for every module-3 reference example, and details of
// the written text (explicit digits, module lines, round-trip precision).

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "format/inp/inp_reader.hpp"
#include "format/inp/inp_writer.hpp"
#include "support/examples.hpp"
#include "support/problem_compare.hpp"

namespace rollcontact::format {
namespace {

const std::filesystem::path examples_dir{ROLLCONTACT_EXAMPLES_DIR};

class InpWriterRoundTrip : public ::testing::TestWithParam<std::string> {};

TEST_P(InpWriterRoundTrip, WrittenInpReadsBackToSameProblems) {
  REQUIRE_EXAMPLES();
  const std::vector<format::CaseRecord> original =
      read_inp_file(examples_dir / (GetParam() + ".inp"));
  const std::string text = write_inp_string(original, examples_dir);
  std::vector<format::CaseRecord> again;
  ASSERT_NO_THROW(again = read_inp_string(text, GetParam() + "_written.inp", examples_dir)) << text;
  test::expect_same_problems(original, again);
  EXPECT_EQ(write_inp_string(test::without_source(again), examples_dir),
            write_inp_string(test::without_source(original), examples_dir));
}

INSTANTIATE_TEST_SUITE_P(Module3Examples, InpWriterRoundTrip,
                         ::testing::Values("bentall", "carter2d", "catt_to_cart", "cattaneo",
                                           "conformal", "ertz_temperature", "fastsim",
                                           "plastic_3bl", "spence35", "subsurf", "tractcurv",
                                           "veldep_fric", "visc_cylindr"),
                         [](const auto& param_info) { return std::string(param_info.param); });

TEST(InpWriter, WritesExplicitDigitsAndFullPrecision) {
  const std::string input =
      "3 MODULE\n"
      "  201120 \n 022020 \n 0101541\n"
      " 0.1 0.3333333333333333 0.0 0.0\n"
      " 0.4 0.4\n"
      " 0.42 0.42 200. 200.\n"
      " 1\n 19 19 -1.26667 -1.26667 .13333 .13333\n"
      " 1 1\n 0.01 0 0.01 0 0 0\n"
      " 0 MODULE\n";
  const auto problems = read_inp_string(input, "x.inp");
  const std::string text = write_inp_string(problems);
  EXPECT_NE(text.find("0.3333333333333333"), std::string::npos) << text;
  EXPECT_NE(text.find("  3  MODULE"), std::string::npos);
  EXPECT_NE(text.find("  0  MODULE"), std::string::npos);
  // G=1 (keep) is written as the method in effect, with its iteration line.
  EXPECT_NE(text.find("MAXGS MAXIN MAXNR MAXOUT EPS"), std::string::npos) << text;
  const auto again = read_inp_string(text, "y.inp");
  ASSERT_EQ(again.size(), 1U);
  EXPECT_EQ(again[0].kinematics.fx_rel, problems[0].kinematics.fx_rel);
  EXPECT_EQ(again[0].digits.g, 0);
}

TEST(InpWriter, ResultElementsGetModuleLines) {
  format::CaseRecord p;
  p.result_element = 7;
  p.contact_problem = 2;
  p.digits.n = 1;
  p.kinematics.fn = 100.0;
  p.potential.ipotcn = -3;
  p.potential.mx = p.potential.my = 5;
  p.potential.values = {1.0, 2.0, 1.1, 0.0};
  const std::string text = write_inp_string({p, p});
  EXPECT_NE(text.find("3 7 2  MODULE"), std::string::npos) << text;
  const auto again = read_inp_string(text, "z.inp");
  ASSERT_EQ(again.size(), 2U);
  EXPECT_EQ(again[1].result_element, 7);
  EXPECT_EQ(again[1].contact_problem, 2);
  EXPECT_EQ(again[1].case_number, 2);
}

}  // namespace
}  // namespace rollcontact::format
