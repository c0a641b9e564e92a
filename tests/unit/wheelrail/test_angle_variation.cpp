// Release 25.1's warning for planar contact (D=2) on a strongly curved contact
// (spec/wheelrail-advanced.md §6.1): where the rail turns by more than 13.9° against the patch
// plane between lateral neighbours deep in the interpenetration, the planar gap is more than 3 %
// off and the report says so. A hollow wheel conforming to a 20 mm crown is such a contact; a
// cylinder on a 300 mm crown is not.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "rollcontact/wheelrail.hpp"
#include "wheelrail_problems.hpp"

namespace rollcontact {
namespace {

bool warns_about_angles(const WheelRailSolution& s) {
  for (const std::string& w : s.warnings)
    if (w.find("large angle variation within contact patch") != std::string::npos) return true;
  return false;
}

TEST(AngleVariation, ConformingHollowWheelWarnsATreadContactDoesNot) {
  // Crown of 20 mm radius under a hollow wheel of 20.5 mm profile radius: B = (1/20 − 1/20.5)/2,
  // at 100 kN a contact about 14 mm wide around the crown, 0.09 mm deep, whose rail turns by
  // ±14° and more within it.
  model::WheelRailProblem conformal = test_support::crowned_rail_problem(300.0);
  const double rr = 20.0, rw = 20.5;
  conformal.rail.points = test_support::sampled_profile(
      [rr](double y) { return rr - std::sqrt(rr * rr - y * y); }, -15.0, 15.0, 0.1, false);
  conformal.wheel.points = test_support::sampled_profile(
      [rw](double y) { return rw - std::sqrt(rw * rw - y * y); }, -18.0, 18.0, 0.1, true);
  conformal.vertical = model::VerticalLoading::Force;
  conformal.motion.fz_N = 100000.0;
  WheelsetSolver a;
  const WheelRailSolution s = a.solve(conformal);
  ASSERT_TRUE(s.converged) << s.message;
  ASSERT_EQ(s.patches.size(), 1u);
  EXPECT_TRUE(warns_about_angles(s));  // measured: approach 0.090 mm, 120 rows of 0.2 mm
  // The same load on the 300 mm crown under a cylinder: a tread-like contact, no warning.
  model::WheelRailProblem tread = test_support::crowned_rail_problem(300.0);
  tread.vertical = model::VerticalLoading::Force;
  tread.motion.fz_N = 20000.0;
  WheelsetSolver b;
  const WheelRailSolution t = b.solve(tread);
  ASSERT_TRUE(t.converged) << t.message;
  EXPECT_FALSE(warns_about_angles(t));
}

}  // namespace
}  // namespace rollcontact
