// The module-1 report is laid out as CONTACT's (spec/outputs.md §3.8), so that scripts reading
// CONTACT's wheel/rail reports read ours: for every case of mbench_a22_kpec (KPEC, ANALYN,
// Fastsim, the exact solvers; profiles and track read in case 1) and mbench_a22_varfric (friction
// varying with the rail angle and along the track, conformal patches), from the problem echo up to
// the first patch's statistics, every title line equals the reference's and every value line has
// its fields ending in the same columns (diagnostic lines: the same text, numbers of the same
// widths). The numbers are validate's business, not this test's.

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
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

std::string rtrim(std::string s) {
  while (!s.empty() && (s.back() == ' ' || s.back() == '\r')) s.pop_back();
  return s;
}

/// Per case number, the lines from " WHEEL-RAIL CONTACT" up to the first " CONTACT STATISTICS"
/// (trailing blanks removed: CONTACT's g12.4 pads numbers with blanks, its lines end anywhere).
std::map<int, std::vector<std::string>> echo_blocks(const fs::path& report) {
  std::ifstream in(report);
  std::map<int, std::vector<std::string>> out;
  std::string l;
  int current = 0;
  bool inside = false;
  while (std::getline(in, l)) {
    l = rtrim(l);
    if (l.rfind(" Case", 0) == 0) {
      current = std::stoi(l.substr(5));
      inside = false;
      continue;
    }
    if (l.rfind(" WHEEL-RAIL CONTACT", 0) == 0) inside = true;
    if (l.rfind(" CONTACT STATISTICS", 0) == 0) inside = false;
    if (inside && current > 0) out[current].push_back(l);
  }
  return out;
}

/// A value line starts with a number; its shape is the column where each field ends.
bool is_value_line(const std::string& l) {
  std::istringstream s(l);
  std::string first;
  if (!(s >> first)) return false;
  const char c = first[0];
  return std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '.';
}

/// A title or diagnostic line with its digits masked: the text and the numbers' widths count.
std::string masked(std::string l) {
  for (char& c : l)
    if (std::isdigit(static_cast<unsigned char>(c))) c = '9';
  return l;
}

std::vector<std::size_t> field_ends(const std::string& l) {
  std::vector<std::size_t> ends;
  for (std::size_t i = 0; i < l.size(); ++i)
    if (l[i] != ' ' && (i + 1 == l.size() || l[i + 1] == ' ')) ends.push_back(i + 1);
  return ends;
}

void expect_same_layout(const std::string& example) {
  const test_support::ScratchDir scratch("rollcontact_layout_" + example);
  const fs::path& dir = scratch.path();
  for (const std::string& name :
       {example + ".inp", std::string("MBench_UIC60_v3.prr"), std::string("MBench_S1002_v3.prw")})
    fs::copy_file(examples_dir / name, dir / name);
  RunOptions options;
  options.solve_unvalidated = true;  // the layout of every case, validated numbers or not
  const RunResult r = run_input_file(dir / (example + ".inp"), options);
  for (const CaseOutcome& c : r.cases) ASSERT_TRUE(c.solved) << example << ": " << c.error;

  const auto ref = echo_blocks(examples_dir / (example + ".ref_out"));
  const auto ours = echo_blocks(dir / (example + ".out"));
  ASSERT_FALSE(ref.empty());
  ASSERT_EQ(ours.size(), ref.size()) << example;
  for (const auto& [number, ref_lines] : ref) {
    const std::vector<std::string>& our_lines = ours.at(number);
    ASSERT_EQ(our_lines.size(), ref_lines.size())
        << example << " case " << number << ": a block too many or too few";
    for (std::size_t i = 0; i < ref_lines.size(); ++i) {
      const std::string& a = ref_lines[i];
      const std::string& b = our_lines[i];
      if (is_value_line(a)) {
        EXPECT_EQ(field_ends(b), field_ends(a)) << example << " case " << number << " line " << i
                                                << "\n  ref:  '" << a << "'\n  ours: '" << b << "'";
      } else {
        EXPECT_EQ(masked(b), masked(a)) << example << " case " << number << " line " << i;
      }
    }
  }
}

TEST(WheelRailReportLayout, ApproximateMethodsAndFastsimAsContactPrintsThem) {
  REQUIRE_EXAMPLES();
  expect_same_layout("mbench_a22_kpec");
}

TEST(WheelRailReportLayout, VariableFrictionAndConformalPatchesAsContactPrintsThem) {
  REQUIRE_EXAMPLES();
  expect_same_layout("mbench_a22_varfric");
}

TEST(WheelRailReportLayout, RightAndLeftWheelsAsContactPrintsThem) {
  REQUIRE_EXAMPLES();
  expect_same_layout("mbench_a22_right");
  expect_same_layout("mbench_a22_left");
}

/// Case 1 of mbench_a22_right alone, with its H-G-I-A-O-W-R line replaced by `digits`, run in an
/// empty folder `dir` (case.inp, case.out there).
RunResult run_right_case1(const fs::path& dir, const std::string& digits) {
  for (const char* name : {"MBench_UIC60_v3.prr", "MBench_S1002_v3.prw"})
    fs::copy_file(examples_dir / name, dir / name);
  std::ifstream in(examples_dir / "mbench_a22_right.inp");
  std::string text, l;
  for (int n = 1; std::getline(in, l) && n <= 26; ++n)
    text += (n == 15 ? " " + digits + "    H-G-I-A-O-W-R" : l) + "\n";
  std::ofstream(dir / "case.inp") << text << " 0 MODULE\n";
  return run_input_file(dir / "case.inp", RunOptions{});
}

/// O = 4 adds the total moments about the profiles' markers (spec/outputs.md §3.8): they are
/// the solution's, and about the rail marker the single patch's force acting at its reference
/// point gives them but for its own torsional moment MN.
TEST(WheelRailReportLayout, OutputFourPrintsTheMomentsAboutTheMarkers) {
  REQUIRE_EXAMPLES();
  const test_support::ScratchDir scratch("rollcontact_layout_moments");
  const fs::path& dir = scratch.path();
  const RunResult r = run_right_case1(dir, "0000421");
  ASSERT_EQ(r.cases.size(), 1U);
  ASSERT_TRUE(r.cases[0].solved) << r.cases[0].error;
  const WheelRailSolution& s = r.cases[0].wheelrail;
  ASSERT_EQ(s.patches.size(), 1U);

  std::ifstream out(dir / "case.out");
  std::vector<std::string> lines;
  for (std::string l; std::getline(out, l);) lines.push_back(l);
  std::vector<double> printed;
  for (std::size_t i = 0; i + 1 < lines.size(); ++i) {
    if (lines[i].rfind(" TOTAL FORCES ON RAIL", 0) == 0) ADD_FAILURE() << "no moments title";
    if (lines[i].find("MX@R(TR)") == std::string::npos) continue;
    std::istringstream values(lines[i + 1]);
    for (double v; values >> v;) printed.push_back(v);
  }
  ASSERT_EQ(printed.size(), 6U);
  const Vector3 m[2] = {s.moment_tr, s.moment_ws};
  for (int k = 0; k < 6; ++k) {
    const Vector3& v = m[k / 3];
    const double expected = k % 3 == 0 ? v.x : k % 3 == 1 ? v.y : v.z;
    EXPECT_NEAR(printed[static_cast<std::size_t>(k)], expected, 5e-4 * std::abs(expected) + 1e-3);
  }
  // (p − m) × F about the rail marker, F the force on the rail at the reference point p.
  const WheelRailPatch& w = s.patches[0];
  const Vector3 d{w.reference_tr.x - s.rail_marker_tr.position.x,
                  w.reference_tr.y - s.rail_marker_tr.position.y,
                  w.reference_tr.z - s.rail_marker_tr.position.z};
  const Vector3& f = s.force_tr;
  const double mn = std::abs(w.solution.totals.mz);
  EXPECT_NEAR(s.moment_tr.x, d.y * f.z - d.z * f.y, mn + 1e-6 * std::abs(d.y * f.z));
  EXPECT_NEAR(s.moment_tr.z, d.x * f.y - d.y * f.x, mn + 1e-6 * std::abs(d.y * f.x));
}

/// O = 5 prints each patch's element table as module 3 does (spec/outputs.md §3.6, §3.8): one
/// line per contact element, the pressures summing to FN, slip only where the element slides,
/// and the rigid slip W/δq of the patch's creepages: ξ − φ·y along a row's elements and η + φ·x
/// across them, so that its x- and y-differences give the spin.
TEST(WheelRailReportLayout, OutputFivePrintsEachPatchsElementTable) {
  REQUIRE_EXAMPLES();
  const test_support::ScratchDir scratch("rollcontact_layout_elements");
  const fs::path& dir = scratch.path();
  const RunResult r = run_right_case1(dir, "0000521");
  ASSERT_EQ(r.cases.size(), 1U);
  ASSERT_TRUE(r.cases[0].solved) << r.cases[0].error;
  ASSERT_EQ(r.cases[0].wheelrail.patches.size(), 1U);
  const WheelRailPatch& w = r.cases[0].wheelrail.patches[0];

  struct Row {
    double y, x, pn, trcbnd, pt, s, wx, wy;
  };
  std::vector<Row> rows;
  std::ifstream out(dir / "case.out");
  bool table = false;
  double y = 0.0;
  for (std::string l; std::getline(out, l);) {
    if (l.rfind(" QUANTITIES DISTRIBUTED OVER THE CONTACT AREA:", 0) == 0) table = true;
    if (!table) continue;
    if (l.rfind(" Y = ", 0) == 0) {
      y = std::stod(l.substr(5, 12));
      continue;
    }
    std::istringstream v(l);
    Row e{y, 0, 0, 0, 0, 0, 0, 0};
    double h_pen = 0.0, arg = 0.0;
    if (v >> e.x >> h_pen >> e.pn >> e.trcbnd >> e.pt >> arg >> e.s >> e.wx >> e.wy)
      rows.push_back(e);
  }
  const Statistics& st = w.solution.statistics;
  ASSERT_EQ(rows.size(), static_cast<std::size_t>(st.ncon));
  const double area = w.solution.grid.element_area();
  double fn = 0.0;
  int sliding = 0;
  for (const Row& e : rows) {
    fn += e.pn * area;
    if (e.s > 0.0) {
      ++sliding;
      EXPECT_NEAR(e.pt, e.trcbnd, 6e-3 * e.trcbnd + 1e-3);  // three digits printed
    } else {
      EXPECT_LE(e.pt, e.trcbnd * (1.0 + 6e-3) + 1e-3);
    }
  }
  EXPECT_EQ(sliding, st.nslip);
  EXPECT_NEAR(fn, w.solution.totals.fn, 2e-3 * w.solution.totals.fn);
  // The spin from the rigid slip's differences: −Δw_x/Δy between the first and last row and
  // Δw_y/Δx along the longest row.
  const Row& first = rows.front();
  const Row& last = rows.back();
  ASSERT_GT(last.y - first.y, 2.0);
  const double phi = w.phi_per_mm;
  ASSERT_GT(std::abs(phi), 1e-6);
  EXPECT_NEAR(-(last.wx - first.wx) / (last.y - first.y), phi, 0.02 * std::abs(phi));
  std::map<double, std::pair<Row, Row>> ends;  // per row: first and last element
  for (const Row& e : rows) {
    auto [it, fresh] = ends.try_emplace(e.y, e, e);
    if (!fresh) it->second.second = e;
  }
  const auto widest = std::max_element(ends.begin(), ends.end(), [](const auto& a, const auto& b) {
    return a.second.second.x - a.second.first.x < b.second.second.x - b.second.first.x;
  });
  const Row& a = widest->second.first;
  const Row& b = widest->second.second;
  ASSERT_GT(b.x - a.x, 1.0);
  EXPECT_NEAR((b.wy - a.wy) / (b.x - a.x), phi, 0.02 * std::abs(phi));
  EXPECT_NEAR(a.wx, b.wx, 1e-3 * std::abs(a.wx) + 1e-9);  // ξ − φ·y: the same along a row
}

/// F = 3: the massless rail's block in every case (spec/outputs.md §3.8), also in a case that
/// keeps the track (Z = 0) — there it was missing while the JSON carried the deflections.
TEST(WheelRailReportLayout, MasslessRailDeflectionInEveryCase) {
  const fs::path repo = fs::path(ROLLCONTACT_TEST_DATA_DIR) / ".." / ".." / "examples";
  const test_support::ScratchDir scratch("rollcontact_layout_massless");
  const fs::path& dir = scratch.path();
  fs::create_directories(dir / "profiles");
  for (const char* f : {"MBench_UIC60_v3.prr", "MBench_S1002_v3.prw"})
    fs::copy_file(repo / "profiles" / f, dir / "profiles" / f);
  std::ifstream in(repo / "massless_rail.inp");
  std::string text, line;
  while (std::getline(in, line)) {
    if (line.rfind("  0 MODULE", 0) == 0) break;
    text += line + "\n";
  }
  // A third case that keeps the track and the rail's springs.
  text +=
      "  1 MODULE\n 1203130\n 0111002\n 0100321\n"
      "  0.0  9.0  10000. -0.01010113 0.0216  0.0\n"
      " 2000. 0.0    0.0   0.0        0.0  -4.24775610\n  0 MODULE\n";
  std::ofstream(dir / "case.inp") << text;
  const RunResult r = run_input_file(dir / "case.inp", RunOptions{});
  ASSERT_EQ(r.cases.size(), 3U);
  std::ifstream out(dir / "case.out");
  int blocks = 0;
  for (std::string l; std::getline(out, l);) blocks += l == " MASSLESS RAIL DEFLECTION";
  EXPECT_EQ(blocks, 3);
  ASSERT_TRUE(r.cases[2].solved) << r.cases[2].error;
  EXPECT_GT(r.cases[2].wheelrail.rail_deflection.dz_mm, 0.05);
}

}  // namespace
}  // namespace rollcontact::batch
