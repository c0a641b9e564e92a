// Bad TOML case files: every error is an InputError naming file, line and key path.

#include <gtest/gtest.h>

#include <string>

#include "format/toml/toml_case_reader.hpp"
#include "rollcontact/errors.hpp"

namespace rollcontact::format {
namespace {

/// A valid single-case file; tests replace one line to break it.
std::string minimal_case(const std::string& normal_extra = {}, const std::string& body1 =
                                                                   "poisson = 0.28, "
                                                                   "shear_modulus_MPa = 82000") {
  return "[[case]]\n"           // 1
         "[case.normal]\n"      // 2
         "force_N = 100.0\n" +  // 3
         normal_extra +         // 4 (optional)
         "[case.material]\n"
         "body1 = { " +
         body1 +
         " }\n"
         "body2 = { poisson = 0.28, shear_modulus_MPa = 82000 }\n"
         "[case.grid]\n"
         "hertz = { elements = [10, 10], semi_axes_mm = [3.0, 2.0], scale = 1.1 }\n";
}

/// The message of the InputError that reading `text` throws ("" if none).
std::string error_of(const std::string& text) {
  try {
    (void)read_toml_string(text, "bad.toml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(TomlCaseErrors, MinimalCaseIsValid) {
  const auto problems = read_toml_string(minimal_case(), "ok.toml");
  ASSERT_EQ(problems.size(), 1U);
  EXPECT_EQ(problems[0].digits.n, 1);
  EXPECT_EQ(problems[0].kinematics.fn, 100.0);
  EXPECT_EQ(problems[0].potential.ipotcn, -3);
  EXPECT_EQ(problems[0].friction.fkin, 0.3);  // default Coulomb
  EXPECT_EQ(problems[0].case_number, 1);
}

TEST(TomlCaseErrors, WrongTypeNamesFileLineAndKey) {
  const std::string m =
      error_of(minimal_case("tolerance_x = 1\n")
                   .replace(minimal_case().find("force_N = 100.0"), 15, "force_N = \"100\""));
  EXPECT_NE(m.find("bad.toml:3:"), std::string::npos) << m;
  EXPECT_NE(m.find("case[1].normal.force_N"), std::string::npos) << m;
  EXPECT_NE(m.find("expected a number but found the string \"100\""), std::string::npos) << m;
}

TEST(TomlCaseErrors, UnknownKeyNamesFileLineAndKey) {
  const std::string m = error_of(minimal_case("forse_N = 3\n"));
  EXPECT_NE(m.find("bad.toml:4:"), std::string::npos) << m;
  EXPECT_NE(m.find("case[1].normal.forse_N: unknown key"), std::string::npos) << m;
}

TEST(TomlCaseErrors, MissingRequiredValue) {
  const std::string m = error_of(minimal_case({}, "poisson = 0.28"));
  EXPECT_NE(m.find("bad.toml:5:"), std::string::npos) << m;
  EXPECT_NE(m.find("case[1].material.body1: missing required key 'shear_modulus_MPa'"),
            std::string::npos)
      << m;
}

TEST(TomlCaseErrors, OutOfRangeValues) {
  std::string m = error_of(minimal_case({}, "poisson = 0.6, shear_modulus_MPa = 82000"));
  EXPECT_NE(m.find("bad.toml:5: case[1].material.body1.poisson: 0.6 outside [0, 0.5]"),
            std::string::npos)
      << m;
  m = error_of(minimal_case({}, "poisson = 0.3, shear_modulus_MPa = -1"));
  EXPECT_NE(m.find("shear_modulus_MPa: -1 must be at least"), std::string::npos) << m;
  std::string big = minimal_case();
  big.replace(big.find("[10, 10]"), 8, "[2000, 2000]");
  m = error_of(big);
  EXPECT_NE(m.find("bad.toml:8: case[1].grid.hertz.elements: MX·MY = 4000000 exceeds"),
            std::string::npos)
      << m;
  m = error_of(minimal_case() + "[case.solver]\nmax_inner_iterations = 0\n");
  EXPECT_NE(m.find("bad.toml:10: case[1].solver.max_inner_iterations: 0 outside 1..9999"),
            std::string::npos)
      << m;
}

TEST(TomlCaseErrors, LayerAndSimplifiedTheoryValuesAreCheckedAtTheirKeys) {
  // A negative layer flexibility solved to an approach of -53 mm; K0 = 0 zeroes Fastsim's slope.
  std::string m =
      error_of(minimal_case("method = \"exact_with_layer\"\n"
                            "layer_flexibility_mm3_per_N = -1.0\n"));
  EXPECT_NE(m.find("case[1].normal.layer_flexibility_mm3_per_N: -1 must be positive"),
            std::string::npos)
      << m;
  std::string fastsim = minimal_case();
  fastsim.replace(fastsim.find("[case.material]\n"), 16,
                  "[case.material]\nmodel = \"fastsim_three_flexibilities\"\n"
                  "slope_reduction = { k0 = 0.0, alpha = 1.0, beta = 1.0 }\n");
  m = error_of(fastsim);
  EXPECT_NE(m.find("slope_reduction.k0: 0 must be positive"), std::string::npos) << m;
}

TEST(TomlCaseErrors, DivisorsAndFallingFrictionTermsAreCheckedAtTheirKeys) {
  const std::string grid =
      "rectangle = { elements = [10, 10], lower_left_mm = [-1.0, -1.0], "
      "upper_right_mm = [1.0, 1.0] }\n";
  std::string base = minimal_case();
  base.replace(base.find("hertz = {"), std::string::npos, grid);
  const auto geometry = [&](const std::string& g) { return base + "[case.geometry]\n" + g; };
  ASSERT_EQ(error_of(geometry("sines = [0, 1, 0, 0, 1, 0, 460, 460]\n")), "");
  std::string m = error_of(geometry("sines = [0, 1, 0, 0, 1, 0, 460, 0]\n"));
  EXPECT_NE(m.find("case[1].geometry.sines: B7 and B8 must be non-zero"), std::string::npos) << m;
  const std::string profile =
      "[case.geometry.profile]\ny_first_mm = -1.0\ny_step_mm = 1.0\nheights_mm = [0.0, 0.0]\n";
  ASSERT_EQ(error_of(geometry(profile + "x_radius_mm = 250.0\n")), "");
  m = error_of(geometry(profile + "x_radius_mm = 0.0\n"));
  EXPECT_NE(m.find("case[1].geometry.profile.x_radius_mm: 0: must be non-zero"), std::string::npos)
      << m;

  const auto friction = [&](const std::string& excess, const std::string& speed) {
    return minimal_case() +
           "[case.friction]\nlaw = \"linear_falling\"\nkinetic = 0.2\nexcess = " + excess +
           "\ndecay_speed_mm_per_s = " + speed + "\n";
  };
  ASSERT_EQ(error_of(friction("[0.1, 0.0]", "[100.0, 0.0]")), "");
  m = error_of(friction("[0.1, -0.05]", "[100.0, 1000.0]"));
  EXPECT_NE(m.find("case[1].friction.excess: -0.05 must be at least 0"), std::string::npos) << m;
  m = error_of(friction("[0.1, 0.05]", "[-100.0, 1000.0]"));
  EXPECT_NE(m.find("case[1].friction.decay_speed_mm_per_s: -100 must be at least 0"),
            std::string::npos)
      << m;
}

TEST(TomlCaseErrors, BadChoiceListsTheNames) {
  const std::string m = error_of(minimal_case("method = \"exactly\"\n"));
  EXPECT_NE(m.find("bad.toml:4: case[1].normal.method: \"exactly\" is not one of \"exact\""),
            std::string::npos)
      << m;
}

TEST(TomlCaseErrors, ConsistencyRules) {
  // Two loads, a rectangle grid without geometry, Hertz geometry given.
  EXPECT_NE(error_of(minimal_case("approach_mm = 0.1\n")).find("not both"), std::string::npos);
  std::string rect = minimal_case();
  rect.replace(rect.find("hertz = {"), 9,
               "rectangle = { lower_left_mm = [0, 0], element_size_mm = [1, 1], ");
  rect.replace(rect.find(", semi_axes_mm = [3.0, 2.0], scale = 1.1"), 40, "");
  EXPECT_NE(error_of(rect).find("missing required table 'geometry'"), std::string::npos)
      << error_of(rect);
  EXPECT_NE(error_of(minimal_case() + "[case.geometry]\nquadratic = [1,0,1,0,0,0]\n")
                .find("not allowed here"),
            std::string::npos);
  EXPECT_NE(error_of(minimal_case() + "[case.heat]\n").find("missing required table 'body1'"),
            std::string::npos);
}

TEST(TomlCaseErrors, SyntaxErrorHasLine) {
  const std::string m = error_of("[[case]]\nname = \"unterminated\n");
  EXPECT_NE(m.find("bad.toml:2: TOML syntax error"), std::string::npos) << m;
}

TEST(TomlCaseErrors, NoCasesAndUnknownTopLevelKey) {
  EXPECT_NE(error_of("version = 1\n").find("no [[case]] found"), std::string::npos);
  const std::string m = error_of("cases = 3\n" + minimal_case());
  EXPECT_NE(m.find("bad.toml:1: cases: unknown key"), std::string::npos) << m;
}

TEST(TomlCaseErrors, FirstCaseOverridesAreWarnings) {
  const auto problems = read_toml_string(
      minimal_case().replace(0, 9, "[[case]]\nprevious_state = \"continue\"\n"), "w.toml");
  ASSERT_EQ(problems.size(), 1U);
  EXPECT_EQ(problems[0].digits.p, 2);
  ASSERT_EQ(problems[0].source.warnings.size(), 1U);
  EXPECT_NE(problems[0].source.warnings[0].find("overridden"), std::string::npos);
}

// TOML has inf and nan literals: every one is an input error at its line, whatever the key
// (issue 11: force_N = inf was solved, shear_modulus_MPa = inf gave a rigid body).
TEST(TomlCaseErrors, NonFiniteNumbersAreRejectedAtTheirLine) {
  const std::string base = minimal_case();
  for (const char* bad : {"inf", "-inf", "nan", "+inf"}) {
    std::string text = base;
    text.replace(text.find("force_N = 100.0"), 15, std::string("force_N = ") + bad);
    const std::string m = error_of(text);
    EXPECT_NE(m.find("bad.toml:3:"), std::string::npos) << m;
    EXPECT_NE(m.find("case[1].normal.force_N"), std::string::npos) << m;
    EXPECT_NE(m.find("is not a finite number"), std::string::npos) << m;
  }
  const std::string m = error_of(minimal_case({}, "poisson = 0.28, shear_modulus_MPa = inf"));
  EXPECT_NE(m.find("shear_modulus_MPa"), std::string::npos) << m;
  EXPECT_NE(m.find("is not a finite number"), std::string::npos) << m;
}

}  // namespace
}  // namespace rollcontact::format
