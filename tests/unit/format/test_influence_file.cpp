// Influence coefficients from a file (C=9, spec/inp-format.md §8.5): our own closed-form (C=2)
// coefficients written in the file format and read back solve every problem as C=2 does.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "elastic/influence.hpp"
#include "elastic/material.hpp"
#include "format/inp/influence_file.hpp"
#include "format/inp/inp_reader.hpp"
#include "format/inp/to_model.hpp"
#include "rollcontact/errors.hpp"
#include "rollcontact/grid.hpp"
#include "rollcontact/solve.hpp"
#include "support/files.hpp"

namespace rollcontact::format {
namespace {

namespace fs = std::filesystem;
using Table = model::InfluenceTable;
using elastic::Component;

/// The C=2 coefficients (physics.md §3.2, without 1/G) of an mx × my grid as a table.
Table closed_form_table(int mx, int my, double dx, double dy, double nu, double k) {
  Table t;
  t.mx = mx;
  t.my = my;
  t.dx_mm = dx;
  t.dy_mm = dy;
  t.coupled = std::abs(k) >= elastic::kCouplingThreshold;
  const std::array<Component, Table::count> of{Component::nn, Component::nx, Component::ny,
                                               Component::xn, Component::xx, Component::xy,
                                               Component::yn, Component::yx, Component::yy};
  for (std::size_t c = 0; c < Table::count; ++c) {
    t.values[c].assign(static_cast<std::size_t>((2 * mx - 1) * (2 * my - 1)), 0.0);
    for (int iy = -(my - 1); iy < my; ++iy)
      for (int ix = -(mx - 1); ix < mx; ++ix)
        t.values[c][t.index(ix, iy)] =
            elastic::influence_coefficient(of[c], ix * dx, iy * dy, dx, dy, nu, k);
  }
  return t;
}

void write(const fs::path& path, const std::string& text) {
  std::ofstream(path) << text;
}

struct Case {
  std::string digits1;    ///< P-B-T-N-F-S
  std::string load;       ///< line 7
  std::string rolling;    ///< line 10 (T = 2, 3), else empty
  std::string materials;  ///< POISS1 POISS2 GG1 GG2
  int mx = 30, my = 20;
  double dx = 0.2, dy = 0.25;  ///< [mm]
};

Case make_case(std::string digits1, std::string load, std::string rolling, std::string materials) {
  Case c;
  c.digits1 = std::move(digits1);
  c.load = std::move(load);
  c.rolling = std::move(rolling);
  c.materials = std::move(materials);
  return c;
}

/// A module-3 case on a rectangular grid with h = 0.002 x² + 0.004 y², C=2 or C=9.
std::string inp_text(const Case& c, bool from_file) {
  std::string s = " 3 MODULE\n " + c.digits1 + "\n " + (from_file ? "029020" : "022020") +
                  "\n 0000301\n 999 100 30 1 1e-9\n " + c.load + "\n 0.3 0.3\n";
  if (!c.rolling.empty()) s += " " + c.rolling + "\n";
  if (from_file) s += " 'coefficients.txt'\n";
  s += " " + c.materials + "\n 1\n " +
       fmt::format("{} {} {} {} {} {}\n", c.mx, c.my, -0.5 * c.mx * c.dx, -0.5 * c.my * c.dy, c.dx,
                   c.dy) +
       " 1 1\n 0.002 0.0 0.004 0.0 0.0 0.0\n 0 MODULE\n";
  return s;
}

double relative_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double diff = 0.0, size = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    diff = std::max(diff, std::abs(a[i] - b[i]));
    size = std::max(size, std::abs(a[i]));
  }
  return size > 0.0 ? diff / size : diff;
}

/// Solves the case with C=2 and with C=9 reading the C=2 coefficients (a table `grow` elements
/// larger or smaller than the grid: truncated or zero-padded); returns the largest relative
/// difference of pn, px, py and the forces.
double c9_against_c2(const std::string& name, const Case& c, int grow = 0) {
  const test_support::ScratchDir scratch("rollcontact_inflcf_" + name);
  const fs::path& dir = scratch.path();
  const std::vector<CaseRecord> plain = read_inp_string(inp_text(c, false), "plain.inp", dir);
  const model::PatchProblem p2 = to_patch_problem(plain.at(0));
  const CombinedMaterial m = elastic::combine_bodies(p2.bodies, 1.0);
  write(dir / "coefficients.txt",
        format_influence_file(closed_form_table(c.mx + grow, c.my + grow, c.dx, c.dy, m.nu, m.k)));
  const std::vector<CaseRecord> filed = read_inp_string(inp_text(c, true), "file.inp", dir);
  const model::PatchProblem p9 = to_patch_problem(filed.at(0));
  EXPECT_TRUE(p9.bodies.influence_table != nullptr);
  PatchSolver s2, s9;
  const Solution a = s2.solve(p2), b = s9.solve(p9);
  EXPECT_TRUE(a.solver.converged);
  EXPECT_TRUE(b.solver.converged);
  EXPECT_GT(a.totals.fn, 0.0);
  if (p2.tangential.kind != model::TangentialKind::None) {
    EXPECT_NE(a.totals.fx, 0.0);
  }
  double worst = std::max({relative_difference(a.pn, b.pn), relative_difference(a.px, b.px),
                           relative_difference(a.py, b.py)});
  for (auto [x, y] : {std::pair{a.totals.fn, b.totals.fn}, std::pair{a.totals.fx, b.totals.fx},
                      std::pair{a.totals.fy, b.totals.fy}})
    worst = std::max(worst, std::abs(x - y) / std::max(std::abs(a.totals.fn), 1e-300));
  return worst;
}

const std::string kDissimilar = "0.3 0.25 80000. 70000.";  // K ≠ 0: coupled
const std::string kEqual = "0.28 0.28 82000. 82000.";

TEST(InfluenceFile, WritesAndReadsTheClosedFormsExactly) {
  const Table t = closed_form_table(7, 5, 0.2, 0.25, 0.3, 0.05);
  const Table r = parse_influence_file(format_influence_file(t), "t.txt");
  EXPECT_EQ(r.mx, 7);
  EXPECT_EQ(r.my, 5);
  EXPECT_TRUE(r.coupled);
  // The negative IXOFS come from the file's symmetry rule (sign change for xz, zx, xy, yx): the
  // closed forms of physics.md §3.2 obey it, to rounding (their corner sums at −IXOFS are
  // summed in another order).
  for (std::size_t c = 0; c < Table::count; ++c) {
    double size = 0.0;
    for (double v : t.values[c]) size = std::max(size, std::abs(v));
    for (int iy = -4; iy <= 4; ++iy)
      for (int ix = -6; ix <= 6; ++ix) {
        const double a = r.at(static_cast<Table::Component>(c), ix, iy);
        const double b = t.at(static_cast<Table::Component>(c), ix, iy);
        if (ix >= 0) {
          EXPECT_EQ(a, b) << c << " " << ix << " " << iy;
        }
        EXPECT_LE(std::abs(a - b), 1e-14 * size) << c << " " << ix << " " << iy;
      }
  }
}

TEST(InfluenceFile, NormalProblemEqualsC2) {
  const Case c = make_case("200100", "500.0 0.0 0.0 0.0", "", kEqual);
  const double d = c9_against_c2("normal", c);
  EXPECT_LE(d, 1e-12);
  RecordProperty("relative_difference", fmt::format("{:.3g}", d));
}

TEST(InfluenceFile, CoupledShiftEqualsC2) {
  const Case c = make_case("201100", "500.0 0.0003 -0.0002 0.0", "", kDissimilar);
  const double d = c9_against_c2("shift", c);
  EXPECT_LE(d, 1e-12);
  RecordProperty("relative_difference", fmt::format("{:.3g}", d));
}

TEST(InfluenceFile, SteadyRollingWithAStepOfOneElementEqualsC2) {
  const Case c = make_case("203100", "500.0 0.0005 -0.0003 0.001", "0.0 0.2 1000.0", kEqual);
  const double d = c9_against_c2("steady", c, 3);
  EXPECT_LE(d, 1e-12);
  RecordProperty("relative_difference",
                 fmt::format("{:.3g}", d));  // larger file: the shifted C′ needs it
}

TEST(InfluenceFile, TransientRollingCoupledEqualsC2) {
  const Case c = make_case("202100", "500.0 0.0005 -0.0003 0.0", "0.0 0.4 1000.0", kDissimilar);
  const double d = c9_against_c2("transient", c, 2);
  EXPECT_LE(d, 1e-12);
  RecordProperty("relative_difference", fmt::format("{:.3g}", d));
}

TEST(InfluenceFile, SmallerFilesAreZeroPaddedLargerOnesTruncated) {
  const Grid grid{30, 20, -3.0, -2.5, 0.2, 0.25};
  for (int grow : {-5, 0, 5}) {
    CombinedMaterial m{1000.0, 0.28, 0.0};
    const auto table = std::make_shared<const Table>(
        closed_form_table(grid.mx + grow, grid.my + grow, grid.dx, grid.dy, 0.28, 0.0));
    m.table = table;
    for (Component c : {Component::nn, Component::xy}) {
      const elastic::Kernel k = elastic::make_kernel(c, grid, m);
      const Table::Component tc = c == Component::nn ? Table::zz : Table::xy;
      for (int iy = -(grid.my - 1); iy < grid.my; ++iy)
        for (int ix = -(grid.mx - 1); ix < grid.mx; ++ix) {
          const bool inside = std::abs(ix) < table->mx && std::abs(iy) < table->my;
          ASSERT_EQ(k.at(ix, iy), inside ? table->at(tc, ix, iy) / 1000.0 : 0.0)
              << grow << " " << ix << " " << iy;
        }
    }
  }
}

TEST(InfluenceFile, RollingStepOfPartElementsIsRefused) {
  // T=2: steady rolling (T=3) takes δq = δx (physics.md §14), a whole element always.
  const Case c = make_case("202100", "500.0 0.0005 -0.0003 0.0", "0.0 0.15 1000.0", kEqual);
  const test_support::ScratchDir scratch("rollcontact_inflcf_part_step");
  const fs::path& dir = scratch.path();
  write(dir / "coefficients.txt",
        format_influence_file(closed_form_table(30, 20, 0.2, 0.25, 0.28, 0.0)));
  const model::PatchProblem p =
      to_patch_problem(read_inp_string(inp_text(c, true), "f.inp", dir).at(0));
  PatchSolver s;
  try {
    (void)s.solve(p);
    FAIL() << "accepted";
  } catch (const NotSupportedError& e) {
    EXPECT_NE(std::string(e.what()).find("whole number of elements"), std::string::npos)
        << e.what();
  }
}

TEST(InfluenceFile, MissingFileIsACaseErrorAndAnInputError) {
  const Case c = make_case("200100", "500.0 0.0 0.0 0.0", "", kEqual);
  const test_support::ScratchDir scratch("rollcontact_inflcf_missing");
  const fs::path& dir = scratch.path();
  const std::vector<CaseRecord> r = read_inp_string(inp_text(c, true), "f.inp", dir);
  EXPECT_NE(r.at(0).source.case_error.find("influence coefficient file 'coefficients.txt' not "
                                           "found"),
            std::string::npos)
      << r.at(0).source.case_error;
  EXPECT_THROW((void)read_influence_file(dir / "coefficients.txt"), InputError);
}

/// The InputError of parsing `text`, or "(accepted)".
std::string input_error(const std::string& text, std::optional<ElementSize> grid = {}) {
  try {
    (void)parse_influence_file(text, "c.txt", grid);
  } catch (const InputError& e) {
    return fmt::format("{}: {}", e.line(), e.message());
  }
  return "(accepted)";
}

TEST(InfluenceFile, WrongElementSizeNamesTheLine) {
  const std::string text = format_influence_file(closed_form_table(4, 3, 0.2, 0.25, 0.28, 0.0));
  EXPECT_EQ(input_error(text, ElementSize{0.2, 0.25}), "(accepted)");
  EXPECT_EQ(input_error(text, ElementSize{0.2, 0.25 + 2e-6}), "(accepted)");
  EXPECT_EQ(input_error(text, ElementSize{0.21, 0.25}),
            "4: DXFILE, DYFILE = 0.2, 0.25 mm differ from the grid's DX, DY = 0.21, 0.25 mm (by "
            "more than 1e-05 mm)");
  // Through the case: the grid's DX comes from the IPOTCN = 1 block.
  const Case c = make_case("200100", "500.0 0.0 0.0 0.0", "", kEqual);
  const test_support::ScratchDir scratch("rollcontact_inflcf_wrong_dx");
  const fs::path& dir = scratch.path();
  write(dir / "coefficients.txt",
        format_influence_file(closed_form_table(30, 20, 0.1, 0.25, 0.28, 0.0)));
  const CaseRecord r = read_inp_string(inp_text(c, true), "f.inp", dir).at(0);
  try {
    (void)to_patch_problem(r);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(e.file().find("coefficients.txt"), std::string::npos) << e.file();
    EXPECT_EQ(e.line(), 4);
  }
}

TEST(InfluenceFile, TruncatedEmptyOrMalformedFilesNameTheLine) {
  const std::string text = format_influence_file(closed_form_table(4, 3, 0.2, 0.25, 0.28, 0.0));
  // 4 header lines, 2 comments, 5 rows of 2 comments and 4 data lines: 36 lines.
  const std::string truncated = text.substr(0, text.rfind('\n', text.size() - 2) + 1);
  EXPECT_EQ(input_error(truncated),
            "35: the file ends after line 35: MXFILE = 4, MYFILE = 3 need 32 lines after the "
            "header (line 4), found 31");
  EXPECT_NE(input_error("").find("end of file while reading NMATRIX IACONVEX"), std::string::npos)
      << input_error("");
  // A data line out of order (one comment line too many before the first row).
  std::string shifted = text;
  shifted.insert(shifted.find("% IXOFS"), "% extra\n");
  EXPECT_EQ(input_error(shifted).substr(0, 40), "9: IYOFS = -2, IXOFS = 0: expected IXOFS");
  std::string bad = text;
  bad.replace(bad.rfind(" "), 1, " x");
  EXPECT_NE(input_error(bad).find("36: IYOFS = 2, IXOFS = 3: coefficient 9 of 9 is not a number"),
            std::string::npos)
      << input_error(bad);
  std::string order = text;
  order.replace(order.find("312"), 3, "123");
  EXPECT_EQ(input_error(order), "2: LQUASID, XYZORDER = 0, 123 must be 0 and 312");
}

TEST(InfluenceFile, OneMatrixPerRowIsRefused) {
  std::string text = format_influence_file(closed_form_table(4, 3, 0.2, 0.25, 0.28, 0.0));
  text.replace(text.find("     1"), 6, "     3");
  try {
    (void)parse_influence_file(text, "c.txt");
    FAIL() << "accepted";
  } catch (const NotSupportedError& e) {
    EXPECT_NE(std::string(e.what()).find("c.txt:1: NMATRIX = 3"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace rollcontact::format
