// `rollcontact dynamic`: the history CSV of a short run on the Manchester S1002/UIC60 profiles
// (a wheel dropped onto the rail from first contact), and clear refusals that write nothing.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "support/files.hpp"

namespace {

namespace fs = std::filesystem;

int run_cli(const std::string& arguments) {
  const std::string command = std::string(ROLLCONTACT_CLI) + " " + arguments + " >/dev/null 2>&1";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

class CliDynamic : public ::testing::Test {
 protected:
  void SetUp() override {
    scratch_.emplace("rc_cli_dynamic_" +
                     std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    dir_ = scratch_->path();
    const fs::path profiles =
        fs::path(ROLLCONTACT_TEST_DATA_DIR) / ".." / ".." / "examples" / "profiles";
    std::ofstream(dir_ / "wheel.inp") << "  1 MODULE\n"
                                         " 1203100\n 0022033\n 0000321\n"
                                         "    999     100    30    1     1e-5\n"
                                         "  0.500   0.500\n"
                                         "  0.300   0.300   80769.2  80769.2\n"
                                         "  0.500   0.500   1.000   90d   8.0   4.0\n"
                                         "   14.0     0    1435.0   0.000\n"
                                         "  '"
                                      << (profiles / "MBench_UIC60_v3.prr").string()
                                      << "'   0  1.0 0.0\n"
                                         "     0.0    0.0   0.000   0.0   0.0   0.000\n"
                                         "  1360.0  -70.0   460.0\n"
                                         "  '"
                                      << (profiles / "MBench_S1002_v3.prw").string()
                                      << "'   0  1.0 0.0\n"
                                         "  0.0  0.0  100000.  0.0 0.0  0.0\n"
                                         " 38888.9 0.0    0.0   0.0   0.0  -84.5411\n"
                                         "  0 MODULE\n";
  }
  std::optional<rollcontact::test_support::ScratchDir> scratch_;
  fs::path dir_;
};

std::vector<std::vector<double>> read_rows(const fs::path& csv, std::string& header) {
  std::ifstream f(csv);
  std::string line;
  std::getline(f, line);  // the summary comment
  std::getline(f, header);
  std::vector<std::vector<double>> rows;
  while (std::getline(f, line)) {
    std::vector<double> row;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) row.push_back(std::stod(cell));
    rows.push_back(row);
  }
  return rows;
}

TEST_F(CliDynamic, DroppedWheelWritesItsHistory) {
  const fs::path csv = dir_ / "run.csv";
  ASSERT_EQ(run_cli("dynamic " + (dir_ / "wheel.inp").string() + " -o " + csv.string() +
                    " --start contact --distance-mm 60 -q"),
            0);
  std::string header;
  const auto rows = read_rows(csv, header);
  EXPECT_EQ(header.rfind("t_s,s_mm,z_ws_mm,z_sprung_mm,vz_wheel_mm_s,rail_dz_mm,fx_N,fy_N,fz_N", 0),
            0U);
  // 60 mm at 38.9 m/s in steps of 2e-5 s: 78 steps and the start.
  ASSERT_EQ(rows.size(), 79U);
  const double static_load = (10000.0 + 350.0) * 9.81;
  EXPECT_NEAR(rows.front()[8], 0.0, 1e-6 * static_load);  // just touching
  double peak = 0.0;
  for (const auto& r : rows) peak = std::max(peak, r[8]);
  // A Hertzian contact dropped from rest overshoots to about 2.5 × the static load (2/5·C·δ^2.5
  // = W·δ), the suspension barely moving in 2 ms.
  EXPECT_NEAR(peak / static_load, 2.5, 0.15);
  EXPECT_FALSE(fs::exists(dir_ / "run.csv.partial"));
}

TEST_F(CliDynamic, RefusalsWriteNothing) {
  const fs::path csv = dir_ / "run.csv";
  const std::string input = (dir_ / "wheel.inp").string();
  EXPECT_EQ(run_cli("dynamic " + input + " -o " + csv.string() + " --dt-s 0"), 2);
  EXPECT_EQ(run_cli("dynamic " + input + " -o " + csv.string() + " --start sideways"), 2);
  const fs::path module3 =
      fs::path(ROLLCONTACT_TEST_DATA_DIR) / ".." / ".." / "examples" / "hertz_normal.inp";
  EXPECT_EQ(run_cli("dynamic " + module3.string() + " -o " + csv.string()), 2);
  EXPECT_FALSE(fs::exists(csv));
}

}  // namespace
