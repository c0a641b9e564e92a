// CONTACT's tractcurv cases 91–120 (Modified Fastsim, parabolic bound, slope reduction and an
// exponentially falling friction law with memory) through the .inp route, against the numbers
// of tractcurv.ref_out: the creep force curve that rises to −3.246E+04 at ξ = 0.022 and falls to
// −1.874E+04 at ξ = 0.25, where the whole patch slides at μ_s(V·ξ) (docs/decisions.md).

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <variant>

#include "format/inp/inp_reader.hpp"
#include "format/inp/to_model.hpp"
#include "format/report/report_parser.hpp"
#include "rollcontact/solve.hpp"
#include "support/examples.hpp"

namespace rollcontact {
namespace {

TEST(TractcurvFastsim, FallingFrictionCurveIsContacts) {
  REQUIRE_EXAMPLES();
  const std::filesystem::path dir{ROLLCONTACT_EXAMPLES_DIR};
  const auto cases = format::read_input_cases(dir / "tractcurv.inp");
  const format::Report ref = format::parse_report_file(dir / "tractcurv.ref_out");
  ASSERT_GE(cases.size(), 120U);
  PatchSolver solver;
  for (int k = 91; k <= 120; ++k) {
    const auto& record = std::get<format::CaseRecord>(cases.at(static_cast<std::size_t>(k - 1)));
    const Solution s = solver.solve(format::to_patch_problem(record));
    ASSERT_TRUE(s.solver.converged) << "case " << k << ": " << s.solver.message;
    const format::ReportCase* r = ref.find(k);
    ASSERT_NE(r, nullptr);
    // Fastsim forces within 2e-3 (spec/validation.md §3); the printed numbers have 4 digits.
    const double fx = *r->value("FX");
    EXPECT_NEAR(s.totals.fx, fx, 2e-3 * std::abs(fx)) << "case " << k;
    EXPECT_NEAR(s.statistics.nslip, *r->value("NSLIP"), 2.0) << "case " << k;
  }
}

}  // namespace
}  // namespace rollcontact
