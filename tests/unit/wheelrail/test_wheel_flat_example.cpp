// CONTACT's `wheelflat` example (S1002 with a measured wheel flat, 258 slices, on a 300 mm
// crowned rail, 125 kN) through the .inp conversion: refused by default (the contact location
// near the flat's edges is not yet CONTACT's, docs/decisions.md "Variable wheel profiles"),
// solved with a warning when the run asks for unvalidated features; cases 3 and 4, where the
// flat's first slices reach into the interpenetration ahead of the contact, agree with the
// reference within the validation tolerances (location 5e-3 mm, forces 1 %, z_ws 2e-3 mm).

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <variant>

#include "format/inp/inp_reader.hpp"
#include "format/inp/to_wheelrail.hpp"
#include "rollcontact/errors.hpp"
#include "rollcontact/wheelrail.hpp"
#include "support/examples.hpp"

namespace rollcontact {
namespace {

struct Reference {
  int case_number;
  double z_ws_mm, xcp_mm, ycp_mm, fx_N, fy_N;
};

TEST(WheelFlatExample, RefusedByDefaultSolvedWithAWarningOnRequest) {
  REQUIRE_EXAMPLES();
  const std::filesystem::path dir{ROLLCONTACT_EXAMPLES_DIR};
  const auto cases = format::read_input_cases(dir / "wheelflat.inp");
  ASSERT_EQ(cases.size(), 26u);
  const auto record = [&](int k) { return std::get<format::WheelRailRecord>(cases.at(k - 1)); };
  EXPECT_THROW((void)WheelsetSolver().solve(format::to_wheelrail_problem(record(3))),
               NotSupportedError);
  // wheelflat.ref_out: Z_WS, XCP(TR), YCP(TR), FX(TR), FY(TR).
  for (const Reference& ref : {Reference{3, 0.3729, 0.0249, 759.3348, 7474.0, 337.9},
                               Reference{4, 0.3732, -0.2233, 759.4313, 6583.0, 717.0}}) {
    SCOPED_TRACE(ref.case_number);
    const WheelRailSolution s =
        WheelsetSolver().solve(format::to_wheelrail_problem(record(ref.case_number), true));
    ASSERT_TRUE(s.converged) << s.message;
    ASSERT_EQ(s.patches.size(), 1u);
    ASSERT_FALSE(s.warnings.empty());
    EXPECT_NE(s.warnings.front().find("not validated against CONTACT: variable wheel profiles"),
              std::string::npos);
    EXPECT_NEAR(s.z_ws_mm, ref.z_ws_mm, 2e-3);
    EXPECT_NEAR(s.patches[0].reference_tr.x, ref.xcp_mm, 5e-3);
    EXPECT_NEAR(s.patches[0].reference_tr.y, ref.ycp_mm, 5e-3);
    EXPECT_NEAR(s.force_tr.x, ref.fx_N, 0.01 * std::abs(ref.fx_N) + 25.0);
    EXPECT_NEAR(s.force_tr.y, ref.fy_N, 0.01 * std::abs(ref.fy_N) + 25.0);
  }
}

}  // namespace
}  // namespace rollcontact
