// RunOptions::keep_fields: the command-line program releases each case's per-element fields once
// its report and JSON are made, so that a run's memory does not grow with its number of cases;
// the outputs and each case's totals, statistics and status stay exactly those of a run that
// keeps everything.

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

/// Two runs of `input`, keeping and releasing the fields, into folders below `dir`.
std::pair<RunResult, RunResult> run_both(const fs::path& input, const fs::path& dir,
                                         int threads = 1) {
  RunOptions keep;
  keep.threads = threads;
  keep.output_dir = dir / "keep";
  RunOptions release = keep;
  release.output_dir = dir / "release";
  release.keep_fields = false;
  return {run_input_file(input, keep), run_input_file(input, release)};
}

void expect_same_totals(const Solution& kept, const Solution& released) {
  EXPECT_EQ(kept.totals.fn, released.totals.fn);
  EXPECT_EQ(kept.totals.fx, released.totals.fx);
  EXPECT_EQ(kept.totals.fy, released.totals.fy);
  EXPECT_EQ(kept.totals.pen, released.totals.pen);
  EXPECT_EQ(kept.statistics.ncon, released.statistics.ncon);
  EXPECT_EQ(kept.solver.converged, released.solver.converged);
}

TEST(RunFields, ReleasedFieldsLeaveOutputsTotalsAndStatusAlone) {
  const test_support::ScratchDir scratch("rollcontact_run_fields");
  const fs::path& dir = scratch.path();
  // A shift sequence: each case continues from the previous one's tractions, which the solver
  // keeps itself; the released outcomes must not be what it continues from.
  std::ofstream(dir / "seq.toml") << R"(version = 1
[[case]]
[case.normal]
force_N = 10000.0
[case.tangential]
problem = "shift"
shift_x_mm = 2e-4
shift_y_mm = 0.0
[case.material]
body1 = { poisson = 0.28, shear_modulus_MPa = 82000.0 }
body2 = { poisson = 0.28, shear_modulus_MPa = 82000.0 }
[case.grid]
hertz = { elements = [24, 24], semi_axes_mm = [3.0, 2.0], scale = 1.2 }

[[case]]
previous_state = "continue"
[case.normal]
force_N = 10000.0
[case.tangential]
problem = "shift"
shift_x_mm = -3e-4
shift_y_mm = 1e-4
[case.material]
body1 = { poisson = 0.28, shear_modulus_MPa = 82000.0 }
body2 = { poisson = 0.28, shear_modulus_MPa = 82000.0 }
[case.grid]
hertz = { elements = [24, 24], semi_axes_mm = [3.0, 2.0], scale = 1.2 }
)";
  // One thread, and two: the workers make the outputs and release the fields themselves.
  for (const int threads : {1, 2}) {
    const auto [kept, released] =
        run_both(dir / "seq.toml", dir / ("threads" + std::to_string(threads)), threads);
    ASSERT_EQ(kept.cases.size(), 2U);
    ASSERT_EQ(released.cases.size(), 2U);
    EXPECT_EQ(file_text(kept.report_path), file_text(released.report_path));
    EXPECT_EQ(file_text(kept.json_path), file_text(released.json_path));
    for (std::size_t k = 0; k < 2; ++k) {
      const Solution& a = kept.cases[k].solution;
      const Solution& b = released.cases[k].solution;
      EXPECT_EQ(a.pn.size(), 24U * 24U);
      EXPECT_TRUE(b.pn.empty() && b.px.empty() && b.ux.empty() && b.h.empty() && b.state.empty());
      EXPECT_EQ(b.pn.capacity(), 0U) << "released, not only cleared";
      expect_same_totals(a, b);
      EXPECT_EQ(kept.cases[k].solved, released.cases[k].solved);
    }
    EXPECT_NE(released.cases[1].solution.totals.fx, 0.0);
  }
}

TEST(RunFields, WheelRailPatchesReleaseTheirFields) {
  REQUIRE_EXAMPLES();
  const test_support::ScratchDir scratch("rollcontact_run_fields_wheelrail");
  const fs::path& dir = scratch.path();
  const auto [kept, released] = run_both(test_support::kExamples / "mbench_a22_right.inp", dir);
  ASSERT_EQ(kept.cases.size(), released.cases.size());
  EXPECT_EQ(file_text(kept.json_path), file_text(released.json_path));
  std::size_t patches = 0;
  for (std::size_t k = 0; k < kept.cases.size(); ++k) {
    const WheelRailSolution& a = kept.cases[k].wheelrail;
    const WheelRailSolution& b = released.cases[k].wheelrail;
    ASSERT_EQ(a.patches.size(), b.patches.size());
    EXPECT_EQ(a.converged, b.converged);
    EXPECT_EQ(a.force_tr.z, b.force_tr.z);
    for (std::size_t i = 0; i < a.patches.size(); ++i, ++patches) {
      EXPECT_FALSE(a.patches[i].solution.pn.empty());
      EXPECT_TRUE(b.patches[i].solution.pn.empty());
      expect_same_totals(a.patches[i].solution, b.patches[i].solution);
    }
  }
  EXPECT_GT(patches, 20U);
}

TEST(RunFields, WithoutOutcomesTheRunKeepsOnlyItsCounts) {
  // RunOptions::keep_outcomes = false (the command-line program): the same files, the counts
  // of cases and of refusals, and no per-case results held; on_case still sees every case.
  REQUIRE_EXAMPLES();
  const test_support::ScratchDir scratch("rollcontact_run_fields_outcomes");
  RunOptions keep;
  keep.output_dir = scratch / "keep";
  RunOptions lean = keep;
  lean.output_dir = scratch / "lean";
  lean.keep_fields = false;
  lean.keep_outcomes = false;
  std::size_t seen = 0;
  lean.on_case = [&seen](const CaseOutcome&, std::size_t k, std::size_t) { seen = k + 1; };
  // wheelflat: every case refused (wheel slices are not validated); mbench_a22_right: solved.
  for (const char* name : {"wheelflat.inp", "mbench_a22_right.inp"}) {
    const RunResult a = run_input_file(test_support::kExamples / name, keep);
    const RunResult b = run_input_file(test_support::kExamples / name, lean);
    EXPECT_EQ(file_text(a.report_path), file_text(b.report_path)) << name;
    EXPECT_EQ(file_text(a.json_path), file_text(b.json_path)) << name;
    EXPECT_EQ(a.case_count, a.cases.size()) << name;
    EXPECT_EQ(b.case_count, a.cases.size()) << name;
    EXPECT_TRUE(b.cases.empty()) << name;
    EXPECT_EQ(seen, a.cases.size()) << name;
    std::size_t refused = 0;
    for (const CaseOutcome& c : a.cases) refused += !c.solved && c.refused_unvalidated ? 1 : 0;
    EXPECT_EQ(refused, std::string(name) == "wheelflat.inp" ? a.cases.size() : 0U) << name;
    EXPECT_EQ(a.refused_unvalidated, refused) << name;
    EXPECT_EQ(b.refused_unvalidated, refused) << name;
    EXPECT_EQ(b.failed, a.failed) << name;
  }
}

}  // namespace
}  // namespace rollcontact::batch
