// Error statistics of creep-force tables on synthetic rows with known errors.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "batch/creep_table_stats.hpp"
#include "rollcontact/errors.hpp"

namespace rollcontact::batch {
namespace {

TEST(CreepTableStats, MeanRmsMaxOverallAndPerClass) {
  const auto cases = table_cases();
  std::vector<TableRow> ref, approx;
  // Four cases: two with a/b = 0.2 (spin 0), two with a/b = 0.5 (spin 0 and 0.5).
  for (std::size_t i : {0u, 1u, 644u, 644u + 161u}) {
    TableRow r;
    r.tc = cases[i];
    r.fx_rel = -0.5;
    r.fy_rel = 0.2;
    r.mz_rel = 0.01;
    ref.push_back(r);
    approx.push_back(r);
  }
  approx[0].fx_rel += 0.03;  // |Δf| = 0.05 (3-4-5)
  approx[0].fy_rel += 0.04;
  approx[1].fy_rel -= 0.01;  // 0.01
  approx[2].mz_rel += 0.02;  // force exact, moment 0.02
  approx[3].fx_rel += 0.1;   // 0.1, moment −0.01
  approx[3].mz_rel -= 0.01;
  const TableStatistics s = compare_tables(approx, ref);
  EXPECT_EQ(s.overall.count, 4);
  EXPECT_NEAR(s.overall.mean_f, (0.05 + 0.01 + 0.0 + 0.1) / 4, 1e-12);
  EXPECT_NEAR(s.overall.rms_f, std::sqrt((0.0025 + 0.0001 + 0.01) / 4), 1e-12);
  EXPECT_NEAR(s.overall.max_f, 0.1, 1e-12);
  EXPECT_EQ(s.overall.worst_f, 644 + 161 + 1);
  EXPECT_NEAR(s.overall.max_mz, 0.02, 1e-12);
  EXPECT_EQ(s.overall.worst_mz, 645);
  EXPECT_NEAR(s.overall.mean_mz, 0.03 / 4, 1e-12);
  ASSERT_EQ(s.aob_values, (std::vector<double>{0.2, 0.5}));
  EXPECT_EQ(s.per_aob[0].count, 2);
  EXPECT_NEAR(s.per_aob[0].mean_f, 0.03, 1e-12);
  EXPECT_NEAR(s.per_aob[1].max_f, 0.1, 1e-12);
  ASSERT_EQ(s.spin_values, (std::vector<double>{0.0, 0.5}));
  EXPECT_EQ(s.per_spin[0].count, 3);
  EXPECT_NEAR(s.per_spin[1].mean_f, 0.1, 1e-12);
  EXPECT_NE(format_statistics_text(s, "t").find("a/b=0.5"), std::string::npos);
  EXPECT_NE(format_statistics_markdown(s, "t").find("| spin = 0.5 |"), std::string::npos);
}

TEST(CreepTableStats, NotConvergedCasesAreCountedNotAveraged) {
  const auto cases = table_cases();
  std::vector<TableRow> ref(2), approx(2);
  for (std::size_t i = 0; i < 2; ++i) ref[i].tc = approx[i].tc = cases[i];
  approx[0].fx_rel = 1.0;
  ref[0].converged = false;
  const TableStatistics s = compare_tables(approx, ref);
  EXPECT_EQ(s.overall.count, 1);
  EXPECT_EQ(s.overall.skipped, 1);
  EXPECT_EQ(s.overall.max_f, 0.0);
}

TEST(CreepTableStats, MismatchedReferenceIsAnError) {
  const auto cases = table_cases();
  std::vector<TableRow> ref(1), approx(1);
  ref[0].tc = cases[0];
  approx[0].tc = cases[1];
  EXPECT_THROW(compare_tables(approx, ref), InputError);  // case 2 missing
  ref[0].tc = cases[1];
  ref[0].tc.magnitude = 99.0;
  EXPECT_THROW(compare_tables(approx, ref), InputError);  // parameters differ
}

}  // namespace
}  // namespace rollcontact::batch
