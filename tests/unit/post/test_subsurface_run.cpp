// End to end: `rollcontact run subsurf.inp` writes the report summaries of subsurf.ref_out and
// the .subs file of subsurf.ref_subs (spec/outputs.md §3.7, §6).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "subs_table.hpp"
#include "support/files.hpp"

namespace rollcontact::post {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> lines_of(const fs::path& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  std::string l;
  while (std::getline(in, l)) lines.push_back(l);
  return lines;
}

/// The ` SUBSURFACE STRESSES BLOCK` paragraphs (title, blank, eight maxima).
std::vector<std::string> summaries(const std::vector<std::string>& lines) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (lines[i].rfind(" SUBSURFACE STRESSES BLOCK", 0) != 0) continue;
    for (std::size_t k = i; k < i + 10 && k < lines.size(); ++k) out.push_back(lines[k]);
  }
  return out;
}

TEST(SubsurfaceRun, SubsurfReportAndSubsFileMatchReference) {
  const fs::path examples = ROLLCONTACT_EXAMPLES_DIR;
  if (!fs::is_regular_file(examples / "subsurf.inp")) GTEST_SKIP();
  const test_support::ScratchDir scratch("rc_post_subsurf");
  const fs::path& out = scratch.path();
  const std::string cmd = std::string(ROLLCONTACT_CLI) + " run \"" +
                          (examples / "subsurf.inp").string() + "\" -o \"" + out.string() + "\" -q";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;

  const std::vector<std::string> ours = summaries(lines_of(out / "subsurf.out"));
  const std::vector<std::string> ref = summaries(lines_of(examples / "subsurf.ref_out"));
  ASSERT_EQ(ours.size(), 40u);
  EXPECT_EQ(ours, ref);

  // Case 2 has MATFIL_S = 2: header lines verbatim, values as in test_subsurface.cpp.
  const std::vector<std::string> subs = lines_of(out / "subsurf.0002.subs");
  const std::vector<std::string> ref_subs = lines_of(examples / "subsurf.ref_subs");
  ASSERT_EQ(subs.size(), ref_subs.size());
  for (std::size_t i : {0u, 1u, 2u, 18u, 19u, 20u}) EXPECT_EQ(subs[i], ref_subs[i]) << i;
  const auto a = testing::read_subs((out / "subsurf.0002.subs").string());
  const auto b = testing::read_subs((examples / "subsurf.ref_subs").string());
  ASSERT_EQ(a.size(), 2u);
  ASSERT_EQ(b.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    ASSERT_EQ(a[k].rows.size(), b[k].rows.size());
    for (std::size_t r = 0; r < a[k].rows.size(); ++r) {
      for (std::size_t c = 0; c < 14; ++c) {
        const double x = a[k].rows[r][c], y = b[k].rows[r][c];
        EXPECT_LE(std::abs(x - y), 1e-3 * std::abs(y) + 5e-6) << k << " " << r << " " << c;
      }
    }
  }
  // Case 1 (S = 3, MATFIL_S = 2) writes its own file.
  EXPECT_TRUE(fs::exists(out / "subsurf.0001.subs"));
}

}  // namespace
}  // namespace rollcontact::post
