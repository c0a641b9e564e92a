// Acceptance: a case solved from its .inp and from its TOML conversion gives identical totals;
// `run` accepts .toml files; examples/toml/ holds the TOML twin of every examples/*.inp (in its
// own folder, so that the two write different outputs).

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <variant>
#include <vector>

#include "batch/run_input.hpp"
#include "format/inp/inp_reader.hpp"
#include "format/toml/toml_case_reader.hpp"
#include "format/toml/toml_case_writer.hpp"
#include "rollcontact/errors.hpp"
#include "rollcontact/solve.hpp"
#include "support/examples.hpp"
#include "support/files.hpp"
#include "support/problem_compare.hpp"

namespace rollcontact::batch {
namespace {

const std::filesystem::path examples_dir{ROLLCONTACT_EXAMPLES_DIR};
const std::filesystem::path repo_examples =
    std::filesystem::path(ROLLCONTACT_TEST_DATA_DIR) / ".." / ".." / "examples";

TEST(TomlAcceptance, CattaneoCase1SolvesIdenticallyFromTomlAndInp) {
  REQUIRE_EXAMPLES();
  const auto from_inp = format::read_inp_file(examples_dir / "cattaneo.inp");
  const auto from_toml =
      format::read_toml_string(format::write_toml_string(from_inp), "cattaneo.toml");
  PatchSolver s1;
  PatchSolver s2;
  const Solution a = solve_case(from_inp.at(0), s1);
  const Solution b = solve_case(from_toml.at(0), s2);
  ASSERT_TRUE(a.solver.converged);
  EXPECT_EQ(a.totals.fn, b.totals.fn);
  EXPECT_EQ(a.totals.pen, b.totals.pen);
  EXPECT_EQ(a.totals.pmax, b.totals.pmax);
  EXPECT_EQ(a.totals.contact_area, b.totals.contact_area);
  EXPECT_EQ(a.totals.elastic_energy, b.totals.elastic_energy);
  EXPECT_EQ(a.pn, b.pn);
}

TEST(TomlAcceptance, RunDispatchesOnTomlExtension) {
  REQUIRE_EXAMPLES();
  const test_support::ScratchDir scratch("rollcontact_toml_run_test");
  const std::filesystem::path& dir = scratch.path();
  const auto problems = format::read_inp_file(examples_dir / "cattaneo.inp");
  format::write_toml_file(dir / "catt1.toml", {problems.at(0)});
  RunOptions options;
  const RunResult r = run_input_file(dir / "catt1.toml", options);
  ASSERT_EQ(r.cases.size(), 1U);
  EXPECT_TRUE(r.cases[0].solved) << r.cases[0].error;
  EXPECT_TRUE(std::filesystem::exists(dir / "catt1.out"));
}

/// The cases written as TOML without their source lines (file, line numbers): two lists of
/// wheel/rail cases describe the same problems when these texts are equal (profile files named
/// relative to `base_dir`, every value with round-trip precision).
std::string problems_as_toml(std::vector<format::InputCase> cases,
                             const std::filesystem::path& base_dir) {
  for (auto& c : cases) std::visit([](auto& r) { r.source = {}; }, c);
  return format::write_toml_input_string(cases, base_dir);
}

TEST(TomlAcceptance, ExamplePairsDescribeTheSameProblems) {
  int pairs = 0;
  for (const auto& entry : std::filesystem::directory_iterator(repo_examples / "toml")) {
    if (entry.path().extension() != ".toml") continue;
    const auto inp = repo_examples / entry.path().filename().replace_extension(".inp");
    SCOPED_TRACE(entry.path().string());
    ASSERT_TRUE(std::filesystem::exists(inp)) << "missing .inp twin";
    std::vector<format::InputCase> a;
    std::vector<format::InputCase> b;
    ASSERT_NO_THROW(a = format::read_toml_input_file(entry.path()));
    ASSERT_NO_THROW(b = format::read_input_cases(inp));
    const auto module3 = [](const format::InputCase& c) {
      return std::holds_alternative<format::CaseRecord>(c);
    };
    if (std::all_of(a.begin(), a.end(), module3) && std::all_of(b.begin(), b.end(), module3)) {
      test::expect_same_problems(format::read_toml_file(entry.path()), format::read_inp_file(inp));
    } else {  // wheel/rail cases (module 1): compared through their resolved TOML form
      EXPECT_EQ(problems_as_toml(a, repo_examples), problems_as_toml(b, repo_examples));
    }
    ++pairs;
  }
  EXPECT_GE(pairs, 8);
}

TEST(SolveCase, CheckOnlyCasesAreChecked) {
  // solve = false (R=3, CONTACT's "check, do not compute"): a negative density in its heat
  // table is refused as in a solved case (the checks were skipped and the run reported success).
  const test_support::ScratchDir scratch("rollcontact_check_only");
  const std::string text =
      "version = 1\n[[case]]\nsolve = false\n[case.normal]\nforce_N = 100.0\n"
      "[case.material]\nbody1 = { poisson = 0.28, shear_modulus_MPa = 82000 }\n"
      "body2 = { poisson = 0.28, shear_modulus_MPa = 82000 }\n"
      "[case.heat]\nbody1 = { temperature_C = 0.0, heat_capacity_J_per_kg_C = 450.0, "
      "conductivity_W_per_mm_C = 0.05, density_kg_per_mm3 = -7.8e-6 }\n"
      "body2 = { temperature_C = 0.0, heat_capacity_J_per_kg_C = 450.0, "
      "conductivity_W_per_mm_C = 0.05, density_kg_per_mm3 = 7.8e-6 }\n"
      "[case.grid]\nhertz = { elements = [10, 10], semi_axes_mm = [3.0, 2.0], scale = 1.1 }\n";
  std::ofstream(scratch / "check.toml") << text;
  try {
    (void)run_input_file(scratch / "check.toml", RunOptions{});
    FAIL() << "a check-only case with a negative density passed";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("density"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(scratch / "check.out"));
}

TEST(SolveCase, GeometryErrorsNameFileLineAndCase) {
  format::CaseRecord r;
  r.case_number = 7;
  r.source.file = "demo.inp";
  r.source.first_line = 42;
  r.digits.n = 1;
  r.kinematics.fn = 1.0;
  r.potential = {1, 3, 3, {0.0, 0.0, 1.0, 1.0}};
  r.geometry.ibase = 1;
  r.geometry.coeffs = {1.0, 0.0, 1.0, 0.0, 0.0, 0.0};
  r.geometry.iplan = 2;
  r.geometry.planform = {0, 0, 0, 0, 0, 1.0};  // form ≥ 0 everywhere: no element left
  PatchSolver solver;
  try {
    (void)solve_case(r, solver);
    FAIL() << "expected GeometryError";
  } catch (const GeometryError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind("demo.inp:42: case 7: ", 0), 0u) << what;
    EXPECT_NE(what.find("excludes every element"), std::string::npos) << what;
    EXPECT_EQ(e.code(), ErrorCode::Discretisation);
  }
  // In a run the case's error names its file and line once (the run adds them to errors that
  // lack them).
  const test_support::ScratchDir scratch("rollcontact_geometry_error_once");
  RunOptions options;
  const RunResult run = run_problems({r}, "demo.inp", scratch / "demo", options);
  const std::string& error = run.cases.at(0).error;
  EXPECT_EQ(error.rfind("demo.inp:42: case 7: ", 0), 0u) << error;
  EXPECT_EQ(error.find("demo.inp:42", 1), std::string::npos) << error;
}

}  // namespace
}  // namespace rollcontact::batch
