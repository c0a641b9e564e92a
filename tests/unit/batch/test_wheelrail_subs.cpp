// Module-1 .subs files (S >= 1, MATFIL_S >= 1): one per contact patch, <stem>.<nnnn>a.subs, b,
// ... (spec/outputs.md §1 and §6), holding the patch's subsurface blocks; no file for a case
// without subsurface points.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "batch/run_input.hpp"
#include "support/examples.hpp"
#include "support/files.hpp"

namespace rollcontact::batch {
namespace {

namespace fs = std::filesystem;
const fs::path examples_dir{ROLLCONTACT_EXAMPLES_DIR};

/// The numbers of the first data row after the column titles of the first block.
std::vector<double> first_point(const fs::path& p, std::vector<int>& counts) {
  std::ifstream in(p);
  std::string line;
  std::vector<double> v;
  int comment = 0;
  while (std::getline(in, line)) {
    if (line.rfind('%', 0) == 0) {
      ++comment;
      continue;
    }
    std::istringstream s(line);
    if (comment == 1) {  // NX NY NZ
      for (int n; counts.size() < 3 && s >> n;) counts.push_back(n);
      continue;
    }
    for (double x; s >> x;) v.push_back(x);
    break;
  }
  return v;
}

TEST(WheelRailSubs, OneFilePerPatchWithItsBlocks) {
  // mbench_a22_varfric: case 1 (S = 3, MATFIL_S = 2) has one patch, case 3 two (tread and
  // flange root; refused as not validated by default, so solved here on request), case 2 no
  // subsurface points.
  REQUIRE_EXAMPLES();
  const test_support::ScratchDir scratch("rollcontact_wheelrail_subs");
  const fs::path& dir = scratch.path();
  for (const char* name : {"mbench_a22_varfric.inp", "MBench_UIC60_v3.prr", "MBench_S1002_v3.prw"})
    fs::copy_file(examples_dir / name, dir / name);
  RunOptions options;
  options.solve_unvalidated = true;
  const RunResult r = run_input_file(dir / "mbench_a22_varfric.inp", options);
  ASSERT_GE(r.cases.size(), 3U);
  for (const char* f : {"mbench_a22_varfric.0001a.subs", "mbench_a22_varfric.0003a.subs",
                        "mbench_a22_varfric.0003b.subs"})
    EXPECT_TRUE(fs::exists(dir / f)) << f;
  EXPECT_FALSE(fs::exists(dir / "mbench_a22_varfric.0001b.subs"));
  EXPECT_FALSE(fs::exists(dir / "mbench_a22_varfric.0002a.subs"));
  // The file's first point is the patch's first subsurface point: coordinates, displacements,
  // SIGHYD, SIGVM and (MATFIL_S = 2) the six stresses, printed with at least 5 significant
  // digits (fmt(12,6,5): small values as 1.0345E-04).
  const CaseOutcome& c1 = r.cases[0];
  ASSERT_TRUE(c1.solved) << c1.error;
  const SubsurfaceResult& b = c1.wheelrail.patches.at(0).solution.subsurface.at(0);
  std::vector<int> counts;
  const std::vector<double> v = first_point(dir / "mbench_a22_varfric.0001a.subs", counts);
  ASSERT_EQ(counts.size(), 3U);
  EXPECT_EQ(counts[0], static_cast<int>(b.x.size()));
  EXPECT_EQ(counts[1], static_cast<int>(b.y.size()));
  EXPECT_EQ(counts[2], static_cast<int>(b.z.size()));
  ASSERT_EQ(v.size(), 14U);
  const double expected[] = {b.x[0],  b.y[0],  b.z[0],      b.ux[0],
                             b.uy[0], b.uz[0], b.sighyd[0], b.sigvm[0]};
  for (int k = 0; k < 8; ++k)
    EXPECT_NEAR(v[k], expected[k], 6e-5 * std::abs(expected[k]) + 1e-12) << "column " << k;
}

}  // namespace
}  // namespace rollcontact::batch
