// The creep-force table of Vollebregt et al. (VSD 2012): case enumeration and order, creepages,
// problems, CSV, case selection, and output that does not depend on the number of threads.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "batch/creep_table.hpp"
#include "rollcontact/errors.hpp"
#include "support/files.hpp"

namespace rollcontact::batch {
namespace {

TEST(CreepTable, EnumeratesTheCasesMagnitudeFastest) {
  const auto cases = table_cases();
  ASSERT_EQ(cases.size(), 3220u);
  for (std::size_t i = 0; i < cases.size(); ++i) EXPECT_EQ(cases[i].number, int(i) + 1);
  const TableCase& c1 = cases[0];
  EXPECT_EQ(c1.a_over_b, 0.2);
  EXPECT_EQ(c1.a, 4.0);
  EXPECT_DOUBLE_EQ(c1.b, 20.0);
  EXPECT_EQ(c1.spin, 0.0);
  EXPECT_EQ(c1.angle_deg, -90.0);
  EXPECT_EQ(c1.magnitude, 0.0);
  EXPECT_EQ(cases[1].magnitude, 0.1);
  EXPECT_EQ(cases[22].magnitude, 12.0);
  EXPECT_EQ(cases[23].angle_deg, -60.0);  // direction next
  EXPECT_EQ(cases[23].magnitude, 0.0);
  EXPECT_EQ(cases[161].spin, 0.5);  // then spin after 7·23 cases
  EXPECT_EQ(cases[161].angle_deg, -90.0);
  EXPECT_EQ(cases[644].a_over_b, 0.5);  // then ellipticity after 4·7·23 cases
  EXPECT_EQ(cases[644].a, 6.0);
  EXPECT_DOUBLE_EQ(cases[644].b, 12.0);
  EXPECT_EQ(cases[3219].a_over_b, 5.0);
  EXPECT_EQ(cases[3219].a, 20.0);
  EXPECT_DOUBLE_EQ(cases[3219].b, 4.0);
  EXPECT_EQ(cases[3219].spin, 2.0);
  EXPECT_EQ(cases[3219].angle_deg, 90.0);
  EXPECT_EQ(cases[3219].magnitude, 12.0);
}

TEST(CreepTable, CreepagesFollowTheNonDimensionalDefinition) {
  const auto cases = table_cases();
  // a = b = 9 mm: circular Hertz, ρ = 8E*c³/(3FN) with E* = G/(1−ν) (physics.md §8).
  const double estar = table_g / (1.0 - table_nu);
  const double rho = 8.0 * estar * 729.0 / (3.0 * table_fn);
  // Case in block a/b = 1 (index 2), spin 1 (index 2), angle 30° (index 4), magnitude 0.7 (6).
  const std::size_t i = 2 * 644 + 2 * 161 + 4 * 23 + 6;
  const TableCase& tc = cases[i];
  ASSERT_EQ(tc.a_over_b, 1.0);
  ASSERT_EQ(tc.spin, 1.0);
  ASSERT_EQ(tc.angle_deg, 30.0);
  ASSERT_EQ(tc.magnitude, 0.7);
  const TableCreepages cr = table_creepages(tc);
  EXPECT_NEAR(cr.rho, rho, 1e-9 * rho);
  EXPECT_DOUBLE_EQ(cr.c, 9.0);
  EXPECT_NEAR(cr.cksi, 0.7 * 0.3 * std::cos(std::numbers::pi / 6) * 9.0 / rho, 1e-15);
  EXPECT_NEAR(cr.ceta, 0.7 * 0.3 * 0.5 * 9.0 / rho, 1e-15);
  EXPECT_NEAR(cr.cphi, 0.3 * 1.0 / rho, 1e-15);
  // Pure lateral and pure longitudinal directions have exactly zero other component.
  const TableCreepages lat = table_creepages(cases[i - 4 * 23 + 5]);  // θ = −90°, m = 0.5
  EXPECT_EQ(lat.cksi, 0.0);
  EXPECT_LT(lat.ceta, 0.0);
  const TableCreepages lon = table_creepages(cases[i - 1 * 23]);  // θ = 0°
  EXPECT_EQ(lon.ceta, 0.0);
  EXPECT_GT(lon.cksi, 0.0);
  // a/b = 0.2, spin 2: ρ from the Hertz solution of the slender ellipse, c = √(4·20).
  const TableCreepages s = table_creepages(cases[3 * 161]);
  EXPECT_DOUBLE_EQ(s.c, std::sqrt(80.0));
  EXPECT_NEAR(s.cphi, 0.3 * 2.0 / s.rho, 1e-15);
}

TEST(CreepTable, ProblemsUseTheMethod) {
  using model::TangentialCompliance;
  const TableCase tc = table_cases()[1000];
  TableSettings s;
  model::PatchProblem p = table_problem(tc, s);
  EXPECT_EQ(p.tangential.kind, model::TangentialKind::SteadyRolling);
  EXPECT_EQ(p.normal.kind, model::NormalLoadKind::Force);
  EXPECT_FALSE(p.sequence.continue_previous);
  EXPECT_EQ(p.normal.pressure, model::PressureModel::ExactHalfSpace);
  EXPECT_EQ(p.bodies.compliance, TangentialCompliance::ExactHalfSpace);
  EXPECT_EQ(p.potential.ipotcn, -3);
  EXPECT_EQ(p.potential.mx, 11);
  EXPECT_EQ(p.potential.my, 11);
  EXPECT_DOUBLE_EQ(p.potential.values[2], 11.0 / 7.0);
  EXPECT_EQ(p.normal.force_N, 82000.0);
  EXPECT_EQ(p.rolling.velocity_mm_per_s, 10000.0);
  s.method = TableMethod::Fastsim1;
  p = table_problem(tc, s);
  EXPECT_EQ(p.bodies.compliance, TangentialCompliance::FastsimOneFlexibility);
  EXPECT_EQ(p.normal.pressure, model::PressureModel::EllipticHertzian);
  EXPECT_GT(p.bodies.simplified.flexibility_mm3_N, 0.0);
  s.method = TableMethod::FaStrip;
  s.bound = 3;
  p = table_problem(tc, s);
  EXPECT_EQ(p.bodies.compliance, TangentialCompliance::FaStrip);
  EXPECT_EQ(p.normal.pressure, model::PressureModel::ParabolicHertzian);
  EXPECT_EQ(parse_table_method("fastsim3"), TableMethod::Fastsim3);
  EXPECT_THROW(parse_table_method("fastsim"), InputError);
}

TEST(CreepTable, CaseSelection) {
  EXPECT_EQ(parse_case_selection("", 3).size(), 3u);
  EXPECT_EQ(parse_case_selection("5,1-3,2", 10), (std::vector<int>{1, 2, 3, 5}));
  EXPECT_THROW(parse_case_selection("0-3", 10), InputError);
  EXPECT_THROW(parse_case_selection("4-2", 10), InputError);
  EXPECT_THROW(parse_case_selection("x", 10), InputError);
  EXPECT_THROW(parse_case_selection("11", 10), InputError);
}

TEST(CreepTable, CsvHeaderAndRoundTrip) {
  EXPECT_EQ(table_csv_header(),
            "case,a_over_b,spin,angle_deg,magnitude,fx_rel,fy_rel,mz_rel,slip_percent,converged");
  TableRow r;
  r.tc = table_cases()[100];
  r.fx_rel = -0.123456789;
  r.fy_rel = 0.5;
  r.mz_rel = 1e-3;
  r.slip_percent = 42.5;
  r.converged = false;
  std::ostringstream out;
  write_table_csv(out, std::vector<TableRow>{r});
  std::istringstream in(out.str());
  const auto back = read_table_csv(in, "t.csv");
  ASSERT_EQ(back.size(), 1u);
  EXPECT_EQ(back[0].tc.number, 101);
  EXPECT_EQ(back[0].tc.magnitude, r.tc.magnitude);
  EXPECT_NEAR(back[0].fx_rel, r.fx_rel, 1e-8);
  EXPECT_EQ(back[0].slip_percent, 42.5);
  EXPECT_FALSE(back[0].converged);
  std::istringstream bad("case,a\n");
  EXPECT_THROW(read_table_csv(bad, "bad.csv"), InputError);
}

std::string table_text(const std::vector<TableCase>& cases, const TableSettings& s, int threads) {
  std::ostringstream out;
  write_table_csv(out, run_table(cases, s, threads));
  return out.str();
}

TEST(CreepTable, SameBytesForOneAndTwoThreads) {
  const auto all = table_cases();
  std::vector<TableCase> subset;
  for (std::size_t i = 5; i < all.size(); i += 230) subset.push_back(all[i]);  // 14 cases
  for (TableMethod m : {TableMethod::Exact, TableMethod::Fastsim3, TableMethod::FaStrip}) {
    TableSettings s;
    s.method = m;
    const std::string one = table_text(subset, s, 1), two = table_text(subset, s, 2);
    EXPECT_EQ(one, two) << table_method_name(m);
    std::istringstream in(one);
    const auto rows = read_table_csv(in, "x");
    ASSERT_EQ(rows.size(), subset.size());
    for (const auto& r : rows) EXPECT_TRUE(r.converged) << "case " << r.tc.number;
  }
}

TEST(CreepTable, SolvesWithTheExpectedSigns) {
  // Pure positive longitudinal creepage, full slip: Fx = −μFN, no lateral force.
  const auto all = table_cases();
  const TableCase tc = all[2 * 644 + 3 * 23 + 22];  // a/b = 1, spin 0, θ = 0°, m = 12
  PatchSolver state;
  for (TableMethod m : {TableMethod::Exact, TableMethod::Fastsim1, TableMethod::Fastsim3}) {
    TableSettings s;
    s.method = m;
    const TableRow r = solve_table_case(tc, s, state);
    ASSERT_TRUE(r.converged) << r.message;
    EXPECT_LT(r.fx_rel, -0.9) << table_method_name(m);
    EXPECT_NEAR(r.fy_rel, 0.0, 1e-9);
    EXPECT_GT(r.slip_percent, 50.0);
  }
}

TEST(CreepTable, CommandLineWritesTheCsv) {
  const test_support::ScratchDir scratch("rc_creep_table");
  const std::filesystem::path& dir = scratch.path();
  const std::string cli = ROLLCONTACT_CLI;
  const std::string ref = (dir / "ref.csv").string(), fs = (dir / "fs.csv").string();
  const std::string md = (dir / "stats.md").string();
  ASSERT_EQ(std::system((cli + " table --cases 1-30 -q --threads 2 -o " + ref).c_str()), 0);
  ASSERT_EQ(std::system((cli + " table --method fastsim3 --cases 1-30 -q -o " + fs +
                         " --reference " + ref + " --stats " + md)
                            .c_str()),
            0);
  std::ifstream in(fs);
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header, table_csv_header());
  EXPECT_TRUE(std::filesystem::is_regular_file(md));
  // A symbolic link (like /dev/stdout) is written through, not replaced by a regular file.
  const auto link = dir / "link.csv", target = dir / "target.csv";
  std::ofstream(target).put('x');
  std::filesystem::create_symlink(target, link);
  ASSERT_EQ(
      std::system((cli + " table --method fastsim1 --cases 1-2 -q -o " + link.string()).c_str()),
      0);
  EXPECT_TRUE(std::filesystem::is_symlink(link));
  std::ifstream tin(target);
  std::getline(tin, header);
  EXPECT_EQ(header, table_csv_header());
}

}  // namespace
}  // namespace rollcontact::batch
