// KPEC (B=5) and modified ANALYN (B=6) in module 1: mbench_a22_kpec through the `.inp` route
// (every case in one solver, as `rollcontact run` does), against CONTACT's printed numbers, and
// the refusal of the two cases that do not agree yet (docs/decisions.md, "KPEC").

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <variant>

#include "format/inp/inp_reader.hpp"
#include "format/inp/to_wheelrail.hpp"
#include "rollcontact/errors.hpp"
#include "rollcontact/wheelrail.hpp"
#include "support/examples.hpp"

namespace rollcontact {
namespace {

/// CONTACT's printed values (mbench_a22_kpec.ref_out) [N, N·mm, N/mm²].
struct Reference {
  std::size_t index;  ///< case − 1
  double fx_tr, fy_tr, fz_tr, fn, fs, mn, pmax;
};

// Module-1 validation tolerances (spec validation.md §3): forces 0.5 % + 2e-4·FZ; MN with a
// 1 µm lever arm on FZ (docs/decisions.md); PMAX 1 %.
constexpr double kFz = 1.0e4;
double force_tol(double ref) {
  return 5e-3 * std::abs(ref) + 2e-4 * kFz;
}
double moment_tol(double ref) {
  return 5e-3 * std::abs(ref) + 1e-3 * kFz;
}

TEST(ApproximateWheelRail, MbenchKpecCasesAgreeWithContact) {
  REQUIRE_EXAMPLES();
  const std::filesystem::path dir{ROLLCONTACT_EXAMPLES_DIR};
  const auto cases = format::read_input_cases(dir / "mbench_a22_kpec.inp");
  const Reference refs[] = {
      {1, -973.6, -1695.0, 1.0e4, 9890.0, -2255.0, -3796.0, 569.8},   // KPEC, two lobes
      {2, -965.9, 69.44, 1.0e4, 9625.0, -2720.0, -1355.0, 1625.0},    // KPEC, flange root
      {3, 340.5, 30.55, 1.0e4, 9997.0, -261.7, -3304.0, 352.1},       // ANALYN, centred
      {4, -1088.0, -1750.0, 1.0e4, 9886.0, -2307.0, -2875.0, 710.3},  // ANALYN, y_ws 0.5 mm
  };
  WheelsetSolver solver;
  std::size_t next = 0;
  for (const Reference& ref : refs) {
    // Earlier cases of the sequence first (their solutions start the next case's iterations).
    for (; next < ref.index; ++next) {
      try {
        (void)solver.solve(
            format::to_wheelrail_problem(std::get<format::WheelRailRecord>(cases.at(next))));
      } catch (const NotSupportedError&) {
        // case 1: refused, see below
      }
    }
    const WheelRailSolution s = solver.solve(
        format::to_wheelrail_problem(std::get<format::WheelRailRecord>(cases.at(ref.index))));
    ++next;
    SCOPED_TRACE("case " + std::to_string(ref.index + 1));
    ASSERT_TRUE(s.converged) << s.message;
    ASSERT_EQ(s.patches.size(), 1U);
    const Totals& t = s.patches[0].solution.totals;
    EXPECT_NEAR(s.force_tr.x, ref.fx_tr, force_tol(ref.fx_tr));
    EXPECT_NEAR(s.force_tr.y, ref.fy_tr, force_tol(ref.fy_tr));
    EXPECT_NEAR(s.force_tr.z, ref.fz_tr, 1e-3 * kFz);
    EXPECT_NEAR(t.fn, ref.fn, force_tol(ref.fn));
    EXPECT_NEAR(t.fy, ref.fs, force_tol(ref.fs));
    EXPECT_NEAR(t.mz, ref.mn, moment_tol(ref.mn));
    double pmax = 0.0;
    for (double p : s.patches[0].solution.pn) pmax = std::max(pmax, p);
    EXPECT_NEAR(pmax, ref.pmax, 1e-2 * ref.pmax);
    // Full solves only (a patch set-up costs more than Fastsim, so normal-only estimates save
    // nothing): 4–10 iterates, where the split iteration took 6–18. (Case 2 passes through
    // states with a second lobe, whose F_z(z) changed when their rows kept the ellipse's
    // virtual length: 9 → 10 iterates, ending 6 N instead of 1 N from FZ on a bracket
    // narrower than EPS, as CONTACT's case 1 ends.)
    EXPECT_LE(s.trace.size(), 11U);
  }
}

// KPEC continues a sweep from the previous cases' approaches, but not from a state with a second
// lobe (case 1, solved here through the API): where F_z(z) jumps the start decides which state
// the iteration ends in, and the next case (y_ws 0.5 mm) must not inherit the two-lobe one.
TEST(ApproximateWheelRail, ASecondLobeStateIsNotASweepStart) {
  REQUIRE_EXAMPLES();
  const std::filesystem::path dir{ROLLCONTACT_EXAMPLES_DIR};
  const auto cases = format::read_input_cases(dir / "mbench_a22_kpec.inp");
  auto problem = [&](std::size_t k) {
    model::WheelRailProblem p =
        format::to_wheelrail_problem(std::get<format::WheelRailRecord>(cases.at(k)));
    p.validated_only = false;
    return p;
  };
  WheelsetSolver sweep;
  const WheelRailSolution first = sweep.solve(problem(0));
  ASSERT_TRUE(first.converged) << first.message;
  ASSERT_GT(first.patches.at(0).solution.solver.kpec_rows_beyond_interpenetration, 0);
  const WheelRailSolution next = sweep.solve(problem(1));
  model::WheelRailProblem alone = problem(1);
  alone.first_of_sequence = true;
  const WheelRailSolution fresh = WheelsetSolver().solve(alone);
  ASSERT_GE(next.trace.size(), 2U);
  ASSERT_GE(fresh.trace.size(), 2U);
  EXPECT_EQ(next.trace[1].z_ws_mm, fresh.trace[1].z_ws_mm);  // Hertz's estimate in both
  EXPECT_NEAR(next.force_tr.z, fresh.force_tr.z, 10.0);
}

// Case 1 at CONTACT's printed height (z_ws 0.1956 mm, N=0): the gap has a second lobe beyond the
// equivalent ellipse, where the ellipse correction asks for ε(y) > 1. Its rows keep their virtual
// length (beyond the interpenetration) and are cut where the bodies do not interpenetrate. That
// gives CONTACT's forces and elastic energy within 2 %; clamping ε to 1 (physics.md §7.3 as
// written) left the lower lobe 6 % short of CONTACT's FN and FX 23 % (9386 N, −262.8 N). PMAX
// still differs (353 against 442.6 N/mm²) and the case stays refused by default.
TEST(ApproximateWheelRail, SecondLobeKeepsTheVirtualRowsOfItsEllipse) {
  REQUIRE_EXAMPLES();
  const std::filesystem::path dir{ROLLCONTACT_EXAMPLES_DIR};
  const auto cases = format::read_input_cases(dir / "mbench_a22_kpec.inp");
  format::WheelRailRecord r = std::get<format::WheelRailRecord>(cases.at(0));
  r.digits.n = 0;
  r.motion.z = 0.1956;
  model::WheelRailProblem p = format::to_wheelrail_problem(r);
  p.validated_only = false;
  const WheelRailSolution s = WheelsetSolver().solve(p);
  ASSERT_TRUE(s.converged) << s.message;
  ASSERT_EQ(s.patches.size(), 1U);
  const Solution& patch = s.patches[0].solution;
  EXPECT_GT(patch.solver.kpec_rows_beyond_interpenetration, 0);
  const Totals& t = patch.totals;
  EXPECT_NEAR(t.fn, 9980.0, 0.01 * 9980.0);                  // measured 9972
  EXPECT_NEAR(t.fx, -341.7, 0.03 * 341.7);                   // −347.1
  EXPECT_NEAR(t.fy, -228.8, 0.04 * 228.8);                   // −234.4
  EXPECT_NEAR(t.mz, -8018.0, 0.03 * 8018.0);                 // −8149
  EXPECT_NEAR(t.elastic_energy, 5.369e-2, 0.01 * 5.369e-2);  // 5.349e-2
}

TEST(ApproximateWheelRail, CasesThatDifferAreRefused) {
  REQUIRE_EXAMPLES();
  const std::filesystem::path dir{ROLLCONTACT_EXAMPLES_DIR};
  const auto cases = format::read_input_cases(dir / "mbench_a22_kpec.inp");
  WheelsetSolver solver;
  // Case 1: KPEC where a second lobe of the gap lies outside the equivalent ellipse.
  EXPECT_THROW((void)solver.solve(
                   format::to_wheelrail_problem(std::get<format::WheelRailRecord>(cases.at(0)))),
               NotValidatedError);
  // Case 6: ANALYN on a patch combined from two interpenetration regions.
  EXPECT_THROW((void)solver.solve(
                   format::to_wheelrail_problem(std::get<format::WheelRailRecord>(cases.at(5)))),
               NotValidatedError);
  // Through the API without `validated_only` both are solved (not yet CONTACT's numbers).
  model::WheelRailProblem p =
      format::to_wheelrail_problem(std::get<format::WheelRailRecord>(cases.at(5)));
  p.validated_only = false;
  const WheelRailSolution s = solver.solve(p);
  EXPECT_TRUE(s.converged) << s.message;
  EXPECT_NEAR(s.force_tr.z, kFz, 1e-3 * kFz);
  const auto said = [&](const std::string& what) {
    for (const std::string& w : s.warnings)
      if (w.find("not validated against CONTACT: " + what) != std::string::npos) return true;
    return false;
  };
  EXPECT_TRUE(said("ANALYN (B=6) on a patch combined")) << s.warnings.size();
  // The same through the .inp conversion's switch (`rollcontact run --unvalidated`).
  EXPECT_FALSE(format::to_wheelrail_problem(std::get<format::WheelRailRecord>(cases.at(0)), true)
                   .validated_only);
}

}  // namespace
}  // namespace rollcontact
