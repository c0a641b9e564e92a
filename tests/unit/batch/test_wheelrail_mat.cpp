// Module-1 .mat files (A digit): one per contact patch, <stem>.<nnnn>a.mat, b, ... with the
// wheel/rail header values, and element rows whose pressures are the patch's (spec/outputs.md
// §5); a left wheel's rows in reverse along y.

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

/// Case 8 of the benchmark (y = 3.5 mm: two patches) for side C1, with A = 2 (all elements).
fs::path write_case(const fs::path& dir, int side) {
  fs::create_directories(dir);
  for (const char* name : {"MBench_UIC60_v3.prr", "MBench_S1002_v3.prw"})
    fs::copy_file(examples_dir / name, dir / name, fs::copy_options::overwrite_existing);
  std::ifstream in(examples_dir / "mbench_a22_right.inp");
  std::string text, line;
  for (int n = 1; std::getline(in, line) && n <= 26; ++n) {
    if (n == 13) line[1] = static_cast<char>('0' + side);
    if (n == 15) line = "  0002321   H-G-I-A-O-W-R";
    if (n == 25)
      line = "  0.0  3.5  10000. -0.00021710 0.0084  0.0      S, Y, FZ, ROLL, YAW, PITCH";
    text += line + "\n";
  }
  const fs::path p = dir / "case.inp";
  std::ofstream(p) << text << " 0 MODULE\n";
  return p;
}

/// The data rows of a .mat file: columns I, IGS, H, MU, PN, PX, PY, ...
std::vector<std::vector<double>> rows_of(const fs::path& p, std::vector<std::string>* header) {
  std::ifstream in(p);
  std::string line;
  std::vector<std::vector<double>> rows;
  int header_lines = 0;
  while (std::getline(in, line)) {
    if (line.rfind('%', 0) == 0) continue;
    if (header_lines < 6) {  // the six value lines of the header
      ++header_lines;
      if (header != nullptr) header->push_back(line);
      continue;
    }
    std::istringstream s(line);
    std::vector<double> v;
    for (double x; s >> x;) v.push_back(x);
    rows.push_back(v);
  }
  return rows;
}

TEST(WheelRailMat, OneFilePerPatchWithThePatchesPressures) {
  REQUIRE_EXAMPLES();
  const test_support::ScratchDir scratch("rollcontact_wheelrail_mat");
  const fs::path& dir = scratch.path();
  RunOptions options;
  const RunResult r = run_input_file(write_case(dir / "right", 1), options);
  ASSERT_EQ(r.cases.size(), 1U);
  ASSERT_TRUE(r.cases[0].solved) << r.cases[0].error;
  const auto& patches = r.cases[0].wheelrail.patches;
  ASSERT_GE(patches.size(), 1U);
  for (std::size_t k = 0; k < patches.size(); ++k) {
    const fs::path mat = dir / "right" / ("case.0001" + std::string(1, char('a' + k)) + ".mat");
    ASSERT_TRUE(fs::exists(mat)) << mat;
    std::vector<std::string> header;
    const auto rows = rows_of(mat, &header);
    const Solution& s = patches[k].solution;
    ASSERT_EQ(rows.size(), s.grid.size());  // A = 2: every element
    double sum = 0.0;
    for (const auto& row : rows) sum += row[4];
    EXPECT_NEAR(sum * s.grid.dx * s.grid.dy, s.totals.fn, 1e-4 * s.totals.fn);  // g14.6 digits
    // NPATCH and IPATCH in the reference-position line.
    std::istringstream ref(header[2]);
    std::vector<double> v;
    for (double x; ref >> x;) v.push_back(x);
    ASSERT_GE(v.size(), 9U);
    EXPECT_EQ(v[7], double(patches.size()));
    EXPECT_EQ(v[8], double(k + 1));
  }
  EXPECT_FALSE(fs::exists(dir / "right" /
                          ("case.0001" + std::string(1, char('a' + patches.size())) + ".mat")));
}

TEST(WheelRailMat, LeftWheelRowsRunTheOtherWayAlongY) {
  REQUIRE_EXAMPLES();
  const test_support::ScratchDir scratch("rollcontact_wheelrail_mat_left");
  const fs::path& dir = scratch.path();
  RunOptions options;
  const RunResult r = run_input_file(write_case(dir / "left", 0), options);
  ASSERT_TRUE(r.cases.at(0).solved) << r.cases[0].error;
  const Solution& s = r.cases[0].wheelrail.patches.at(0).solution;
  const auto rows = rows_of(dir / "left" / "case.0001a.mat", nullptr);
  ASSERT_EQ(rows.size(), s.grid.size());
  // Row iy of the file is row MY+1-iy of the (mirrored) computation; PY changes sign.
  const Grid& g = s.grid;
  for (int iy = 0; iy < g.my; iy += 3)
    for (int ix = 0; ix < g.mx; ix += 5) {
      const auto& row = rows[g.index(ix, iy)];
      const std::size_t source = g.index(ix, g.my - 1 - iy);
      EXPECT_NEAR(row[4], s.pn[source], 1e-5 * (1.0 + s.pn[source]));
      EXPECT_NEAR(row[6], -s.py[source], 1e-5 * (1.0 + std::abs(s.py[source])));
    }
}

/// M=3 (Fastsim): the header's FLX1–3 are the effective flexibilities the solver used (they
/// derive from the patch's ellipse; the input has none), not zeros.
TEST(WheelRailMat, FastsimHeaderHoldsTheEffectiveFlexibilities) {
  REQUIRE_EXAMPLES();
  const test_support::ScratchDir scratch("rollcontact_wheelrail_mat_flx");
  const fs::path& dir = scratch.path();
  for (const char* name : {"mbench_a22_kpec.inp", "MBench_UIC60_v3.prr", "MBench_S1002_v3.prw"})
    fs::copy_file(examples_dir / name, dir / name);
  RunOptions options;
  options.solve_unvalidated = true;
  const RunResult r = run_input_file(dir / "mbench_a22_kpec.inp", options);
  ASSERT_GE(r.cases.size(), 4U);
  const CaseOutcome& c4 = r.cases[3];  // ANALYN with Fastsim
  ASSERT_TRUE(c4.solved) << c4.error;
  const SimplifiedReport& simp = c4.wheelrail.patches.at(0).solution.simplified;
  ASSERT_TRUE(simp.present);
  EXPECT_GT(simp.flx1, 0.0);
  std::vector<std::string> header;
  rows_of(dir / "mbench_a22_kpec.0004a.mat", &header);
  ASSERT_GE(header.size(), 5U);
  std::istringstream line(header[4]);  // T M GG1 GG2 POISS1 FLX1 FLX2 FLX3 K0_MF ALFAMF BETAMF
  std::vector<double> v;
  for (double x; line >> x;) v.push_back(x);
  ASSERT_GE(v.size(), 11U);
  EXPECT_NEAR(v[5], simp.flx1, 5e-6 * simp.flx1);  // g14.6: 6 digits
  EXPECT_NEAR(v[6], simp.flx2, 5e-6 * simp.flx2);
  EXPECT_NEAR(v[7], simp.flx3, 5e-6 * simp.flx3);
  EXPECT_EQ(v[8], 1.0);  // K0_MF as read
}

}  // namespace
}  // namespace rollcontact::batch
