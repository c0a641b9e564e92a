// `rollcontact run --threads N`: the sequences of a file (result elements) run in parallel, each
// in its order, and the report and results are those of a one-thread run, byte for byte.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "batch/run_input.hpp"
#include "support/examples.hpp"
#include "support/files.hpp"

namespace rollcontact::batch {
namespace {

namespace fs = std::filesystem;
using test_support::file_text;

/// Three transient sequences (result elements 1-3) of four shifts each, interleaved.
std::string interleaved_sequences() {
  std::string text = "version = 1\n";
  for (int k = 0; k < 4; ++k)
    for (int e = 1; e <= 3; ++e) {
      text += fmt::format(
          "\n[[case]]\nresult_element = {}\nprevious_state = \"{}\"\n"
          "[case.normal]\nforce_N = {}\n"
          "[case.tangential]\nproblem = \"shift\"\nshift_x_mm = {}\nshift_y_mm = 0.0\n"
          "[case.material]\nbody1 = {{ poisson = 0.28, shear_modulus_MPa = 82000.0 }}\n"
          "body2 = {{ poisson = 0.28, shear_modulus_MPa = 82000.0 }}\n"
          "[case.grid]\nhertz = {{ elements = [{}, {}], semi_axes_mm = [3.0, 2.0], scale = 1.2 "
          "}}\n",
          e, k == 0 ? "new" : "continue", 5000.0 * e, 2e-4 * (k + 1) * (k % 2 ? -1 : 1), 20 + 4 * e,
          20 + 4 * e);
    }
  return text;
}

TEST(ParallelRun, ThreadsGiveTheOneThreadOutputsByteForByte) {
  const test_support::ScratchDir scratch("rollcontact_parallel_run");
  const fs::path& dir = scratch.path();
  std::ofstream(dir / "seq.toml") << interleaved_sequences();
  RunOptions one;
  one.output_dir = dir / "one";
  RunOptions three = one;
  three.output_dir = dir / "three";
  three.threads = 3;
  std::size_t progress_calls = 0;
  three.on_progress = [&](std::size_t, std::size_t count) {
    ++progress_calls;
    EXPECT_EQ(count, 12U);
  };
  const RunResult a = run_input_file(dir / "seq.toml", one);
  const RunResult b = run_input_file(dir / "seq.toml", three);
  ASSERT_EQ(a.cases.size(), 12U);
  ASSERT_EQ(b.cases.size(), 12U);
  EXPECT_EQ(a.failed, 0);
  EXPECT_EQ(b.failed, 0);
  EXPECT_EQ(file_text(a.report_path), file_text(b.report_path));
  EXPECT_EQ(file_text(a.json_path), file_text(b.json_path));
  EXPECT_GE(progress_calls, 1U);  // at least the final call
  // The sequences matter: case 4 continues from case 1's tractions (same element).
  EXPECT_NE(a.cases[3].solution.totals.fx, 0.0);
}

TEST(ParallelRun, WheelRailElementsInParallel) {
  REQUIRE_EXAMPLES();
  const fs::path examples{ROLLCONTACT_EXAMPLES_DIR};
  const test_support::ScratchDir scratch("rollcontact_parallel_wheelrail");
  const fs::path& dir = scratch.path();
  RunOptions one;
  one.output_dir = dir / "one";
  RunOptions two = one;
  two.output_dir = dir / "two";
  two.threads = 2;
  const RunResult a = run_input_file(examples / "mbench_a22_left.inp", one);
  const RunResult b = run_input_file(examples / "mbench_a22_left.inp", two);
  EXPECT_EQ(file_text(a.report_path), file_text(b.report_path));
  EXPECT_EQ(file_text(a.json_path), file_text(b.json_path));
}

}  // namespace
}  // namespace rollcontact::batch
