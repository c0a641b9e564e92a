// The ASCII .mat element file (spec/outputs.md §5): layout of the header pairs, the column
// header and the element rows, read back as numbers; and the file written by `rollcontact run`.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "format/report/mat_writer.hpp"
#include "support/files.hpp"

namespace rollcontact::format {
namespace {

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

std::vector<std::string> words_of(const std::string& line) {
  std::vector<std::string> out;
  std::istringstream in(line);
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

std::vector<double> numbers_of(const std::string& line) {
  std::vector<double> out;
  for (const auto& w : words_of(line)) out.push_back(std::stod(w));
  return out;
}

/// A 3 x 2 grid with 4 elements in contact, T=3 steady rolling, Coulomb friction.
std::pair<format::CaseRecord, Solution> small_case(int a_digit) {
  format::CaseRecord p;
  p.case_number = 7;
  p.digits.t = 3;
  p.digits.a = a_digit;
  p.kinematics.veloc = 2000.0;
  p.kinematics.dq = 0.25;
  p.kinematics.chi = 0.0;
  p.kinematics.spinxo = 0.5;
  p.friction.fstat = p.friction.fkin = 0.3;
  p.materials.gg1 = p.materials.gg2 = 82000.0;
  p.materials.poiss1 = p.materials.poiss2 = 0.28;
  Solution s;
  s.grid = Grid{3, 2, -1.5, -1.0, 1.0, 1.0};
  const std::size_t n = s.grid.size();
  s.h.assign(n, 0.01);
  s.pn = {0.0, 100.0, 200.0, 0.0, 300.0, 1234567.0};
  s.px = {0.0, -10.0, 20.0, 0.0, 30.0, 40.0};
  s.py = {0.0, 1.0, -2.0, 0.0, 3.0, 4.0};
  s.un = {0.0, 1e-3, 2e-3, 0.0, 3e-3, 4e-3};
  s.ux = s.uy = std::vector<double>(n, 1e-5);
  s.sx = {0.0, 0.0, 3e-4, 0.0, 0.0, 0.0};
  s.sy = {0.0, 0.0, 4e-4, 0.0, 0.0, 0.0};
  using S = ElementState;
  s.state = {S::Exterior, S::Adhesion, S::Slip, S::Exterior, S::Adhesion, S::Adhesion};
  // As the solver reports them: steady rolling steps one element (DQ = DX = 1 mm).
  s.kinematics = {0.0, 1.0, 2000.0, 1.0 / 2000.0};
  return {p, s};
}

TEST(MatWriter, HeaderLayoutFollowsTheSpecLineByLine) {
  const auto [p, s] = small_case(1);
  const auto lines = lines_of(mat_file_text(p, s));
  ASSERT_GE(lines.size(), 13u);
  // Names per comment line, as in spec/outputs.md §5 (M=0, L=0, T=3).
  const std::vector<std::vector<std::string>> names{
      {"%", "TIM", "S_WS(FC)", "TH_WS(FC)", "Y_R(TR)", "Z_R(TR)", "ROLL_R(TR)", "RNOM_ROL", "-",
       "-", "-", "FMT"},
      {"%", "X_W(TR)", "Y_W(TR)", "Z_W(TR)", "ROLL_W(TR)", "YAW_W(TR)", "RNOM_WHL", "-", "-", "-",
       "-"},
      {"%", "X_CP(R)", "Y_CP(R)", "Z_CP(R)", "DELT_CP(R)", "X_CP(W)", "Y_CP(W)", "Z_CP(W)",
       "NPATCH", "IPATCH", "SPINXO", "SPINYO", "-", "-"},
      {"%", "MX", "MY", "XL", "YL", "DX", "DY", "CHI", "DQ", "C1", "D", "YNOM_WHL"},
      {"%", "T", "M", "GG1", "GG2", "POISS1", "POISS2", "-", "-", "-", "-", "-"},
      {"%", "L", "H", "VELOC", "FSTAT", "FKIN", "-", "-", "-", "-", "-", "-"},
  };
  for (std::size_t k = 0; k < names.size(); ++k) {
    SCOPED_TRACE(k);
    EXPECT_EQ(words_of(lines[2 * k]), names[k]) << lines[2 * k];
    // Every value line holds 11 numbers (Matlab's load needs equal rows); lines 8, 10, 12 put
    // two integers into the first 14-wide column.
    const std::string& values = lines[2 * k + 1];
    EXPECT_EQ(numbers_of(values).size(), 11u) << values;
    EXPECT_GE(values.size(), 10u * 14u) << values;
  }
  EXPECT_EQ(words_of(lines[12]), (std::vector<std::string>{"%", "I", "IGS", "H", "MU", "PN", "PX",
                                                           "PY", "UN", "UX", "UY", "SREL"}));
  // Names start at the 4th position of their 14-wide column.
  EXPECT_EQ(lines[0].find("S_WS(FC)"), 17u);
  EXPECT_EQ(lines[12].find("MU"), 31u);
  // Line 2: seven zeros of metadata, then the format version in the last column.
  const auto meta = numbers_of(lines[1]);
  ASSERT_EQ(meta.size(), 11u);
  EXPECT_EQ(meta.back(), kMatFormatVersion);
  EXPECT_EQ(lines[1].substr(lines[1].size() - 6), "  2410");
  // Spin centre on line 6; grid on line 8; materials and friction on lines 10, 12.
  EXPECT_DOUBLE_EQ(numbers_of(lines[5])[9], 0.5);
  const auto grid = numbers_of(lines[7]);
  ASSERT_EQ(grid.size(), 11u);
  EXPECT_EQ(grid[0], 3);
  EXPECT_EQ(grid[1], 2);
  EXPECT_DOUBLE_EQ(grid[2], -1.5);
  EXPECT_DOUBLE_EQ(grid[7], 1.0);  // DQ = DX for steady rolling (physics.md §14)
  EXPECT_EQ(lines[7].substr(0, 14), "      3    2  ");
  const auto mat = numbers_of(lines[9]);
  EXPECT_EQ(mat[0], 3);  // T
  EXPECT_DOUBLE_EQ(mat[2], 82000.0);
  const auto fric = numbers_of(lines[11]);
  EXPECT_DOUBLE_EQ(fric[2], 2000.0);  // VELOC
  EXPECT_DOUBLE_EQ(fric[4], 0.3);
}

TEST(MatWriter, RowsReadBack) {
  const auto [p, s] = small_case(1);
  const auto lines = lines_of(mat_file_text(p, s));
  ASSERT_EQ(lines.size(), 13u + 4u);  // A=1: elements in contact only
  const std::vector<int> index{2, 3, 5, 6};
  const std::vector<int> igs{1, 2, 1, 1};
  for (std::size_t r = 0; r < 4; ++r) {
    const auto v = numbers_of(lines[13 + r]);
    ASSERT_EQ(v.size(), 11u) << lines[13 + r];
    EXPECT_EQ(v[0], index[r]);
    EXPECT_EQ(v[1], igs[r]);
    EXPECT_DOUBLE_EQ(v[3], 0.3);  // MU
    const std::size_t i = static_cast<std::size_t>(index[r] - 1);
    EXPECT_NEAR(v[4], s.pn[i], 5e-6 * std::abs(s.pn[i]));  // 6 digits
    EXPECT_DOUBLE_EQ(v[5], s.px[i]);
    EXPECT_DOUBLE_EQ(v[6], s.py[i]);
    EXPECT_DOUBLE_EQ(v[7], s.un[i]);
  }
  EXPECT_DOUBLE_EQ(numbers_of(lines[14])[10], 5e-4);  // SREL = |(3e-4, 4e-4)|
  EXPECT_NE(lines[16].find("0.123457E+07"), std::string::npos) << lines[16];
  // A=2: every element of the potential contact area.
  const auto [p2, s2] = small_case(2);
  EXPECT_EQ(lines_of(mat_file_text(p2, s2)).size(), 13u + 6u);
}

TEST(MatWriter, ShiftColumnAndFileName) {
  auto [p, s] = small_case(1);
  p.digits.t = 1;
  const auto lines = lines_of(mat_file_text(p, s));
  EXPECT_EQ(words_of(lines[12]).back(), "SHFT");
  EXPECT_EQ(mat_file_path("/a/b/cattaneo", 2).string(), "/a/b/cattaneo.0002.mat");
  EXPECT_EQ(mat_file_path("x", 12345).string(), "x.12345.mat");
}

TEST(MatWriter, RunWritesCattaneoMat) {
  const std::filesystem::path examples = ROLLCONTACT_EXAMPLES_DIR;
  if (!std::filesystem::is_regular_file(examples / "cattaneo.inp")) GTEST_SKIP();
  const test_support::ScratchDir scratch("rc_mat_cattaneo");
  const std::filesystem::path& out = scratch.path();
  const std::string cmd = std::string(ROLLCONTACT_CLI) + " run \"" +
                          (examples / "cattaneo.inp").string() + "\" -o \"" + out.string() +
                          "\" -q";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  EXPECT_FALSE(std::filesystem::exists(out / "cattaneo.0001.mat"));  // case 1 has A=0
  std::ifstream mat(out / "cattaneo.0002.mat");
  ASSERT_TRUE(mat) << "cattaneo.0002.mat not written";
  std::stringstream text;
  text << mat.rdbuf();
  const auto lines = lines_of(text.str());
  ASSERT_EQ(lines.size(), 13u + 177u);
  for (std::size_t k = 13; k < lines.size(); ++k) {
    const auto v = numbers_of(lines[k]);
    ASSERT_EQ(v.size(), 11u) << lines[k];
    EXPECT_GE(v[1], 1);  // in contact
  }
}

}  // namespace
}  // namespace rollcontact::format
