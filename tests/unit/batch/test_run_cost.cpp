// The cost estimate that orders several files of one `run` longest first: it must rank finer
// grids, more cases and prescribed vertical forces as costlier.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "batch/run_input.hpp"
#include "format/inp/builtin_example.hpp"
#include "rollcontact/errors.hpp"
#include "support/examples.hpp"
#include "support/files.hpp"

namespace rollcontact::batch {
namespace {

/// Writes `text` to the file `name` in a scratch folder that lasts as long as the test program.
std::filesystem::path write(const std::string& name, const std::string& text) {
  static const test_support::ScratchDir scratch("rc-cost");
  const auto path = scratch / name;
  std::ofstream(path) << text;
  return path;
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

TEST(RunCost, GridElementsOfModule3) {
  const std::string base(format::builtin_example_inp);
  const auto small = write("rc-cost-40.inp", base);
  const auto large = write("rc-cost-80.inp", replaced(base, "   40   40   ", "   80   80   "));
  EXPECT_DOUBLE_EQ(estimated_run_cost(small), 40.0 * 40.0);
  EXPECT_DOUBLE_EQ(estimated_run_cost(large), 4.0 * estimated_run_cost(small));
  EXPECT_THROW(estimated_run_cost("/nonexistent/x.inp"), InputError);
}

TEST(RunCost, WheelRailSweepsFinerAndForcePrescribedFirst) {
  REQUIRE_EXAMPLES();
  // mbench_a22_right: DX = DS = 0.2 mm, FZ = 10 kN prescribed (N=1) in its 21 cases.
  const double right = estimated_run_cost(test_support::kExamples / "mbench_a22_right.inp");
  EXPECT_NEAR(right, 21 * 2.0 * 25.0 / (0.2 * 0.2), 1e-9 * right);
}

}  // namespace
}  // namespace rollcontact::batch
