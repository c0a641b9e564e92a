// A transient-rolling sequence continued (P=0) in a case that gives its potential contact again
// (D=2, issue 18 item 6): the previous tractions are kept when the grid is the same and mapped
// with the material when the grid moves by whole elements, as CONTACT does; only a fresh start
// (P=2) forgets them.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "batch/run_input.hpp"
#include "format/inp/inp_reader.hpp"
#include "rollcontact/solve.hpp"

namespace rollcontact::batch {
namespace {

// Case 1: a Cattaneo shift of a Hertzian contact (7 mm diameter, 28 elements of 0.25 mm).
const std::string kFirst = R"(
 3  MODULE
  201100      P-B-T-N-F-S
  022020      L-D-C-M-Z-E
 0001341    H-G-I-A-O-W-R
   100   100    30     1      1e-7
  0.4705     -0.0177      0.000       0.000
  0.4013      0.4013
  0.280       0.280       1.000       1.000
    1
   34   33   -4.125    -4.125    0.250   0.250
       1           1
 0.002963    0.000     0.002963    0.000     0.000     0.000
)";

// Case 2: transient rolling by DQ = 0.8 mm (3.2 elements) at creepage -0.001, P given, with the
// grid kept (D=0) or given again (D=2) with its lower-left corner at `xl`.
std::string second_case(char p, bool regive, const std::string& xl) {
  std::string s = std::string("\n 3  MODULE\n  ") + p + "02100      P-B-T-N-F-S\n";
  s += regive ? "  122020      L-D-C-M-Z-E\n" : "  102000      L-D-C-M-Z-E\n";
  s += " 0011341    H-G-I-A-O-W-R\n   100   100    30     1      1e-7\n";
  s += "  0.4705     -0.0010      0.000       0.000\n";
  s += "  0.000       0.800        1000.\n";
  s += "  0.280       0.280       1.000       1.000\n";
  if (regive) {
    s += "    1\n   34   33   " + xl + "    -4.125    0.250   0.250\n       1           1\n";
    s += " 0.002963    0.000     0.002963    0.000     0.000     0.000\n";
  }
  return s;
}

/// The solution of the last case of `text`, its cases solved in order by one solver.
Solution solve_sequence(const std::string& text) {
  const auto cases = format::read_inp_string(text + "\n 0  MODULE\n", "sequence.inp");
  PatchSolver solver;
  Solution last;
  for (const auto& c : cases) last = solve_case(c, solver);
  return last;
}

TEST(RollingSequences, GridGivenAgainKeepsThePreviousTractions) {
  const Solution kept = solve_sequence(kFirst + second_case('0', false, ""));
  const Solution regiven = solve_sequence(kFirst + second_case('0', true, "-4.125"));
  const Solution fresh = solve_sequence(kFirst + second_case('2', true, "-4.125"));
  ASSERT_TRUE(kept.solver.converged && regiven.solver.converged && fresh.solver.converged);
  EXPECT_EQ(regiven.totals.fx, kept.totals.fx);
  EXPECT_EQ(regiven.px, kept.px);
  // The memory matters: starting afresh gives a clearly different force (about 4 % of μFN).
  const double mu_fn = 0.4013 * 0.4705;
  EXPECT_GT(std::abs(fresh.totals.fx - kept.totals.fx), 0.01 * mu_fn);
}

TEST(RollingSequences, GridMovedByWholeElementsCarriesTheTractions) {
  // The same contact on a grid moved 2 elements ahead: the previous tractions are mapped by
  // that offset, so the answer is the same up to round-off in the FFT products.
  const Solution kept = solve_sequence(kFirst + second_case('0', false, ""));
  const Solution moved = solve_sequence(kFirst + second_case('0', true, "-3.625"));
  ASSERT_TRUE(moved.solver.converged);
  const double mu_fn = 0.4013 * 0.4705;
  EXPECT_NEAR(moved.totals.fx, kept.totals.fx, 1e-6 * mu_fn);
  EXPECT_NEAR(moved.totals.fy, kept.totals.fy, 1e-6 * mu_fn);
}

}  // namespace
}  // namespace rollcontact::batch

namespace rollcontact::batch {
namespace {

TEST(SolverDigits, GdSteadyIsServedByTheSteadySolverWithANote) {
  // G=5 only chooses an algorithm: the case is solved (with rollcontact's steady-rolling solver)
  // and says so in its warnings, with the answer of G=0.
  const std::string head = " 3  MODULE\n  203100\n  022020\n";
  const std::string tail =
      "  10000.0  0.001  -0.0005  0.0001\n  0.3  0.3\n  0.0  0.1  2000.0\n"
      "  0.28 0.28 82000. 82000.\n  -1\n  30 30  0.002  0.004  1.1\n 0  MODULE\n";
  const auto g0 = format::read_inp_string(head + "  0000301\n  999 100 30 1 1e-5\n" + tail, "g0");
  const auto g5 = format::read_inp_string(
      head + "  0500301\n  999 100 30 1 1e-5\n  0.9 0.5 2 0.1 0.2 0.3 0.4 1.5\n" + tail, "g5");
  PatchSolver s0, s5;
  const Solution a = solve_case(g0.at(0), s0);
  const Solution b = solve_case(g5.at(0), s5);
  ASSERT_TRUE(a.solver.converged && b.solver.converged);
  EXPECT_EQ(a.totals.fx, b.totals.fx);
  EXPECT_EQ(a.totals.fy, b.totals.fy);
  bool noted = false;
  for (const auto& w : g5.at(0).source.warnings) noted |= w.find("G=5") != std::string::npos;
  EXPECT_TRUE(noted);
}

}  // namespace
}  // namespace rollcontact::batch
