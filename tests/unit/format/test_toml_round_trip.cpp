// Round trips of every module-3 reference example: .inp -> Problems -> TOML -> Problems must give
// the same Problems (test_toml_problem_compare.hpp), and writing is idempotent.

#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "format/inp/inp_reader.hpp"
#include "format/inp/wheelrail_record.hpp"
#include "format/toml/toml_case_reader.hpp"
#include "format/toml/toml_case_writer.hpp"
#include "rollcontact/errors.hpp"
#include "support/examples.hpp"
#include "support/problem_compare.hpp"

namespace rollcontact::format {
namespace {

const std::filesystem::path examples_dir{ROLLCONTACT_EXAMPLES_DIR};

/// The module-3 example files (module 1 is not read yet).
const std::vector<std::string> module3_examples{
    "bentall",          "carter2d",    "catt_to_cart", "cattaneo", "conformal",
    "ertz_temperature", "fastsim",     "plastic_3bl",  "spence35", "subsurf",
    "tractcurv",        "veldep_fric", "visc_cylindr"};

class TomlRoundTrip : public ::testing::TestWithParam<std::string> {};

TEST_P(TomlRoundTrip, InpToTomlGivesSameProblems) {
  REQUIRE_EXAMPLES();
  const auto path = examples_dir / (GetParam() + ".inp");
  const std::vector<format::CaseRecord> from_inp = read_inp_file(path);
  ASSERT_FALSE(from_inp.empty());
  const std::string toml = write_toml_string(from_inp, examples_dir);
  std::vector<format::CaseRecord> from_toml;
  ASSERT_NO_THROW(from_toml = read_toml_string(toml, GetParam() + ".toml", examples_dir)) << toml;
  test::expect_same_problems(from_inp, from_toml);
  // Writing what was read gives the same text again: the TOML form is a fixed point.
  EXPECT_EQ(write_toml_string(test::without_source(from_toml), examples_dir),
            write_toml_string(test::without_source(from_inp), examples_dir));
}

INSTANTIATE_TEST_SUITE_P(Module3Examples, TomlRoundTrip, ::testing::ValuesIn(module3_examples),
                         [](const auto& param_info) { return param_info.param; });

TEST(TomlRoundTrip, Module1ExamplesAreNotSupportedYet) {
  REQUIRE_EXAMPLES();
  for (const char* name : {"mbench_a22_kpec", "mbench_a22_left", "mbench_a22_right",
                           "mbench_a22_varfric", "wheelflat"}) {
    try {
      (void)read_inp_file(examples_dir / (std::string(name) + ".inp"));
      ADD_FAILURE() << name << " was read; add it to the round-trip list";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("not supported yet"), std::string::npos) << e.what();
    }
  }
}

TEST(TomlRoundTrip, WheelSlicesRoundTrip) {
  // wheelflat: 26 cases on a wheel given by 258 slices (S1002_flat.slcw) -> TOML `file =` the
  // slices file -> the same cases and the same slices, bit for bit.
  REQUIRE_EXAMPLES();
  std::vector<InputCase> from_inp = read_input_cases(examples_dir / "wheelflat.inp");
  const std::string toml = write_toml_input_string(from_inp, examples_dir);
  EXPECT_NE(toml.find("file = \"S1002_flat.slcw\""), std::string::npos);
  std::vector<InputCase> from_toml;
  ASSERT_NO_THROW(from_toml = read_toml_input_string(toml, "wheelflat.toml", examples_dir));
  ASSERT_EQ(from_toml.size(), from_inp.size());
  for (auto* cases : {&from_inp, &from_toml})
    for (auto& c : *cases) std::visit([](auto& r) { r.source = {}; }, c);
  EXPECT_EQ(write_toml_input_string(from_toml, examples_dir),
            write_toml_input_string(from_inp, examples_dir));
  const auto& a = std::get<WheelRailRecord>(from_inp.back()).wheel;
  const auto& b = std::get<WheelRailRecord>(from_toml.back()).wheel;
  ASSERT_TRUE(b.sliced);
  ASSERT_EQ(b.slices->slices.size(), a.slices->slices.size());
  EXPECT_EQ(b.slices->u, a.slices->u);
  EXPECT_EQ(b.slices->slices[130].z, a.slices->slices[130].z);
  // A wheel's slices as the rail: refused with the key.
  std::string wrong = toml;
  wrong.replace(wrong.find("file = \"r300_wide.prr\""),
                std::string("file = \"r300_wide.prr\"").size(), "file = \"S1002_flat.slcw\"");
  try {
    (void)read_toml_input_string(wrong, "wrong.toml", examples_dir);
    ADD_FAILURE() << "a .slcw rail was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(".slcs slices file"), std::string::npos) << e.what();
  }
}

TEST(TomlRoundTrip, ExamplesCoverEveryFeatureOnce) {
  REQUIRE_EXAMPLES();
  // Sanity check of the test itself: the examples exercise shifts, rolling, subsurface points,
  // temperature and several friction laws, so the round trips above are not only Hertz cases.
  std::set<int> t, s, h, l, m;
  for (const auto& name : module3_examples) {
    for (const format::CaseRecord& p : read_inp_file(examples_dir / (name + ".inp"))) {
      t.insert(p.digits.t);
      s.insert(p.digits.s);
      h.insert(p.digits.h);
      l.insert(p.friction.law);
      m.insert(p.digits.m);
    }
  }
  EXPECT_GE(t.size(), 3U);
  EXPECT_GE(s.size(), 2U);
  EXPECT_GE(h.size(), 2U);
  EXPECT_GE(l.size(), 2U);
  EXPECT_GE(m.size(), 3U);
}

}  // namespace
}  // namespace rollcontact::format
