#pragma once
// Solving one patch problem in a test: a fresh solver, and the test fails where it does not
// converge.

#include <gtest/gtest.h>

#include "rollcontact/solve.hpp"

namespace rollcontact::test {

/// The solution of `p` by a new PatchSolver; a solve that does not converge fails the test,
/// with the solver's message.
inline Solution solve_converged(const model::PatchProblem& p) {
  PatchSolver solver;
  Solution s = solver.solve(p);
  EXPECT_TRUE(s.solver.converged) << s.solver.message;
  return s;
}

}  // namespace rollcontact::test
