// Flash temperatures of wheel/rail patches (H=3 in module 1, spec/physics.md §15): each patch
// computes the surface temperatures of module 3 with its own rolling speed. Checked with the
// moving-heat-source scaling: at fixed creepages the frictional heat flux grows like V and the
// temperature rise of a fast source like q·√(a/V), so doubling the speed raises it by √2.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <variant>

#include "format/inp/inp_reader.hpp"
#include "format/inp/to_wheelrail.hpp"
#include "rollcontact/wheelrail.hpp"
#include "support/examples.hpp"
#include "support/files.hpp"

namespace rollcontact {
namespace {

/// mbench_a22_right case 7 (y 3 mm, tread contact) with H=3 (steel, 0 °C background) at forward
/// speed `vs` [mm/s] (VPITCH scaled alike: the same creepages).
WheelRailSolution solve_heated(double vs) {
  const std::filesystem::path dir{ROLLCONTACT_EXAMPLES_DIR};
  std::ifstream in(dir / "mbench_a22_right.inp");
  std::string text, line;
  for (int n = 1; std::getline(in, line) && n <= 26; ++n) {
    if (n == 15) line = " 3000321";
    if (n == 25) line = "  0.0  3.0  10000. -0.00018030 0.0072  0.0";
    if (n == 26)
      line = " " + std::to_string(vs) + " 0.0 0.0 0.0 0.0 " +
             std::to_string(-4.34515030 * vs / 2000.0);
    text += line + "\n";
    if (n == 18) text += "  0.0 450.0 50e-3 7.85e-6\n  0.0 450.0 50e-3 7.85e-6\n";
  }
  text += " 0 MODULE\n";
  const test_support::ScratchDir scratch("rc_heat");
  for (const char* f : {"MBench_UIC60_v3.prr", "MBench_S1002_v3.prw"})
    std::filesystem::copy_file(dir / f, scratch / f);
  std::ofstream(scratch / "heat.inp") << text;
  const auto cases = format::read_input_cases(scratch / "heat.inp");
  return WheelsetSolver().solve(
      format::to_wheelrail_problem(std::get<format::WheelRailRecord>(cases.at(0))));
}

TEST(WheelRailHeat, FlashTemperatureGrowsWithTheSquareRootOfTheSpeed) {
  REQUIRE_EXAMPLES();
  const WheelRailSolution slow = solve_heated(2000.0), fast = solve_heated(4000.0);
  ASSERT_TRUE(slow.converged && fast.converged);
  ASSERT_EQ(slow.patches.size(), 1u);
  ASSERT_EQ(fast.patches.size(), 1u);
  const Totals &a = slow.patches[0].solution.totals, &b = fast.patches[0].solution.totals;
  ASSERT_GT(a.max_temp1, 0.1);  // frictional power −a few W heats the surfaces
  EXPECT_NEAR(b.frictional_power / a.frictional_power, 2.0, 0.02);  // same creepages, 2V
  // Equal bodies share the heat: equal maxima. The speed ratio √2, within the discretisation
  // of the slip zone (Péclet number a·V/κ ≈ 800: the fast-source limit).
  EXPECT_NEAR(a.max_temp1, a.max_temp2, 1e-6 * a.max_temp1 + 1e-9);
  EXPECT_NEAR(b.max_temp1 / a.max_temp1, std::sqrt(2.0), 0.05);
}

}  // namespace
}  // namespace rollcontact
