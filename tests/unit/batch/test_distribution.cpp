// The process abstraction of distributed batch runs (batch/distribution.hpp): the one-process
// distribution, the row encoding that carries table results between processes bit-exact, and
// the distributed table on one process equal to the threaded one. (Several processes: the ctest
// mpi_table_equals_serial, under mpirun.)

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "batch/creep_table.hpp"
#include "batch/distribution.hpp"
#include "rollcontact/errors.hpp"

namespace rollcontact::batch {
namespace {

TEST(Distribution, SerialMapGatherKeepsIndexOrder) {
  SerialDistribution d;
  EXPECT_TRUE(d.is_root());
  EXPECT_EQ(d.size(), 1);
  const auto out = d.map_gather(5, 2, [](std::size_t i) { return std::to_string(i * i); });
  EXPECT_EQ(out, (std::vector<std::string>{"0", "1", "4", "9", "16"}));
  EXPECT_EQ(d.max_over_processes(7), 7);
}

TEST(Distribution, ChunksAreAboutSixteenPerProcess) {
  EXPECT_EQ(default_chunk(3220, 4), 50u);
  EXPECT_EQ(default_chunk(10, 4), 1u);
  EXPECT_EQ(default_chunk(0, 1), 1u);
}

TEST(Distribution, TableRowsTravelBitExact) {
  TableRow row;
  row.tc = table_cases()[41];
  row.fx_rel = -0.1234567890123456789;
  row.fy_rel = std::nextafter(0.3, 1.0);
  row.mz_rel = -std::numeric_limits<double>::denorm_min();
  row.slip_percent = 37.5;
  row.converged = false;
  row.message = "no convergence, with, commas\nand a newline";
  const TableRow back = decode_table_row(encode_table_row(row), row.tc);
  EXPECT_EQ(back.tc.number, row.tc.number);
  EXPECT_EQ(back.fx_rel, row.fx_rel);
  EXPECT_EQ(back.fy_rel, row.fy_rel);
  EXPECT_EQ(back.mz_rel, row.mz_rel);
  EXPECT_EQ(back.slip_percent, row.slip_percent);
  EXPECT_EQ(back.converged, row.converged);
  EXPECT_EQ(back.message, row.message);
  EXPECT_THROW((void)decode_table_row("short", row.tc), rollcontact::Error);
}

TEST(Distribution, DistributedTableOnOneProcessEqualsTheThreadedOne) {
  const std::vector<TableCase> cases = select_table_cases("1-40,700-720,3200-3220");
  TableSettings s;
  SerialDistribution d;
  const std::vector<TableRow> a = run_table(cases, s, 2);
  const std::vector<TableRow> b = run_table_distributed(cases, s, d);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].tc.number, b[i].tc.number);
    EXPECT_EQ(a[i].fx_rel, b[i].fx_rel);
    EXPECT_EQ(a[i].fy_rel, b[i].fy_rel);
    EXPECT_EQ(a[i].mz_rel, b[i].mz_rel);
  }
}

}  // namespace
}  // namespace rollcontact::batch
