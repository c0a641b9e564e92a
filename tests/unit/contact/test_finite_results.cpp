// Finite in, finite out (issue 11): the C++ API refuses non-finite values with the model's
// check, refuses grids whose influence coefficients would overflow, and never reports a
// non-finite result as converged.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "contact/result_check.hpp"
#include "rollcontact/errors.hpp"
#include "rollcontact/solve.hpp"
#include "support/hertz_problem.hpp"

namespace rollcontact {
namespace {

TEST(FiniteResults, TheApiRefusesNonFiniteValuesByField) {
  model::PatchProblem p = test::hertz_problem(3.0, 2.0, 1000.0, 82000.0, 0.28, 11, 11, 1.1);
  p.bodies.body1.shear_modulus_N_mm2 = std::numeric_limits<double>::infinity();
  PatchSolver solver;
  try {
    (void)solver.solve(p);
    FAIL() << "an infinite modulus was solved (as a rigid body)";
  } catch (const InvalidValueError& e) {
    EXPECT_EQ(e.field(), "bodies.body1.shear_modulus_N_mm2");
  }
}

TEST(FiniteResults, AGridThatWouldOverflowIsAGeometryError) {
  // Semi-axes of 1e20 mm: elements of ~1e19 mm, far beyond what the coefficients represent.
  const model::PatchProblem p = test::hertz_problem(1e20, 1e20, 1000.0, 82000.0, 0.28, 11, 11, 1.1);
  PatchSolver solver;
  try {
    (void)solver.solve(p);
    FAIL() << "solved";
  } catch (const GeometryError& e) {
    EXPECT_NE(std::string(e.what()).find("over- or underflow"), std::string::npos) << e.what();
  }
}

TEST(FiniteResults, FirstNonFiniteNamesTheTotalOrTheElement) {
  Solution s;
  s.pn = {1.0, 2.0, 3.0};
  EXPECT_EQ(first_non_finite(s), "");
  s.pn[2] = std::nan("");
  EXPECT_EQ(first_non_finite(s), "pn[2] = nan");
  s.totals.fx = -std::numeric_limits<double>::infinity();
  EXPECT_EQ(first_non_finite(s), "FX = -inf");  // totals first: what a user reads first
  s.totals.fx = 0.0;
  s.pn[2] = 3.0;
  s.subsurface.resize(1);
  s.subsurface[0].szz = {0.0, std::nan("")};
  EXPECT_EQ(first_non_finite(s), "subsurface szz[1] = nan");
  s.subsurface.clear();
  // Every position of a longer field is checked: in the blocks of four and in the remainder.
  for (const std::size_t at : {0U, 3U, 4U, 8U, 9U}) {
    s.ux.assign(10, 1e300);
    s.ux[at] = std::numeric_limits<double>::infinity();
    EXPECT_EQ(first_non_finite(s), "ux[" + std::to_string(at) + "] = inf");
  }
  s.ux.assign(10, -1e300);  // large but finite
  EXPECT_EQ(first_non_finite(s), "");
}

TEST(FiniteResults, ASolvedCaseIsFiniteAndConverged) {
  const model::PatchProblem p = test::hertz_problem(3.0, 2.0, 1000.0, 82000.0, 0.28, 21, 21, 1.1);
  PatchSolver solver;
  const Solution s = solver.solve(p);
  EXPECT_TRUE(s.solver.converged) << s.solver.message;
  EXPECT_EQ(first_non_finite(s), "");
}

}  // namespace
}  // namespace rollcontact
