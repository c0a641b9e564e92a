// The module-1 input echo's variants no reference report shows (docs/decisions.md, "The module-1
// report's input echo"): the rail placed by RAILY0, RAILZ0 (GAUGHT ≤ 0), a roller rig's NOMRADR
// in place of the cant, the blocks selected by the digits; every value right-aligned under its
// 12-column label as in CONTACT's track block.

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "format/report/report_wheelrail_inputs.hpp"

namespace rollcontact::format {
namespace {

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

/// The two lines after " TRACK DIMENSIONS AND RAIL POSITION".
std::pair<std::string, std::string> track_block(const WheelRailRecord& r) {
  std::ostringstream os;
  report::write_wheelrail_input_blocks(os, r, CombinedMaterial{});
  const std::vector<std::string> l = lines_of(os.str());
  for (std::size_t i = 0; i + 2 < l.size(); ++i)
    if (l[i] == " TRACK DIMENSIONS AND RAIL POSITION") return {l[i + 1], l[i + 2]};
  return {};
}

TEST(WheelRailReportInputs, RailPlacedByItsOriginOnARollerRig) {
  WheelRailRecord r;
  r.digits.z = 1;  // track dimensions only: no rail profile block
  r.config = 5;    // right wheel on a roller
  r.track.gaught = -1.0;
  r.track.raily0 = 752.5;
  r.track.railz0 = -0.25;
  r.track.nomradr = 685.0;
  const auto [header, values] = track_block(r);
  EXPECT_EQ(header, "    RAILY0      RAILZ0     NOMRADR        CURV");
  EXPECT_EQ(values, "   752.500      -0.250     685.000       0.000");
  std::ostringstream os;
  report::write_wheelrail_input_blocks(os, r, CombinedMaterial{});
  EXPECT_EQ(os.str().find("RAIL PROFILE"), std::string::npos);
  EXPECT_EQ(os.str().find("WHEEL PROFILE"), std::string::npos);
}

TEST(WheelRailReportInputs, GaugePointPlacementWithCant) {
  WheelRailRecord r;
  r.digits.z = 3;
  r.config = 1;
  r.track.cant = 0.025;
  const auto [header, values] = track_block(r);
  EXPECT_EQ(header, "    GAUGHT      GAUGWD        CANT        CURV");
  EXPECT_EQ(values, "    14.000    1435.000      0.0250       0.000");
}

TEST(WheelRailReportInputs, MethodAndRollingLinesFollowTheDigits) {
  WheelRailRecord r;
  r.digits.n = 0;
  r.digits.b = 5;
  r.digits.t = 3;
  r.digits.m = 3;
  std::ostringstream os;
  report::write_wheelrail_problem_lines(os, r);
  EXPECT_EQ(os.str(),
            " VERTICAL PROBLEM WITH PRESCRIBED POSITION, APPROXIMATE KPEC SOLUTION\n"
            " STEADY STATE ROLLING, \"FASTSIM APPROACH\", CREEPAGE PRESCRIBED\n"
            " JOHNSON\"S METHOD IS USED FOR THE FRICTIONAL STRESS\n");
}

}  // namespace
}  // namespace rollcontact::format
