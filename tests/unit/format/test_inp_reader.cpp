// Case-level semantics of the module-3 reader: module lines and R digits, case numbering per
// result element, "keep" digits, consistency overrides, and the less common input blocks.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include "format/inp/inp_reader.hpp"
#include "rollcontact/errors.hpp"
#include "support/files.hpp"

namespace rollcontact::format {
namespace {

// A complete first case (T=1 shift, IPOTCN=1, quadratic geometry) without its module line; the
// last digit of word 3 is R.
std::string first_case(int r = 1, const std::string& word1 = "201120",
                       const std::string& word2 = "022020") {
  return "  " + word1 + "\n  " + word2 + "\n 000054" + std::to_string(r) +
         "\n   100 100 30 1 1e-4\n  9.0 -0.5 0.0 0.0\n  0.4 0.4\n  0.42 0.42 200. 200.\n"
         "    1\n   19 19 -1.26667 -1.26667 .13333 .13333\n    1 1\n"
         "  0.01 0 0.01 0 0 0\n";
}

// A follow-up case keeping friction, grid, materials and geometry (L=1 D=0 C=0 Z=0, G=1).
std::string keep_case(int r = 1, double fx = -0.25) {
  return "  001120\n  100000\n 010054" + std::to_string(r) + "\n  9.0 " + std::to_string(fx) +
         " 0.0 0.0\n";
}

std::vector<format::CaseRecord> read(const std::string& text) {
  return read_inp_string(text, "t.inp");
}

TEST(InpReader, ModuleLinesAndCaseNumbers) {
  const auto p = read(" 3 MODULE\n" + first_case() + " 3 module % comment\n" + keep_case() +
                      " 0 MODULE\n this is ignored\n");
  ASSERT_EQ(p.size(), 2u);
  EXPECT_EQ(p[0].case_number, 1);
  EXPECT_EQ(p[1].case_number, 2);
  EXPECT_EQ(p[0].source.module_line, 1);
  EXPECT_EQ(p[1].source.module_line, 13);
  EXPECT_EQ(p[1].source.first_line, 14);
  EXPECT_EQ(p[1].source.file, "t.inp");
}

TEST(InpReader, EndOfFileAfterR1EndsTheInput) {
  EXPECT_EQ(read(" 3 MODULE\n" + first_case()).size(), 1u);
}

TEST(InpReader, R0AndR2ContinueWithoutModuleLine) {
  const auto p = read(" 3 MODULE\n" + first_case(0) + keep_case(2) + keep_case(3) + " 0 MODULE\n");
  ASSERT_EQ(p.size(), 3u);
  EXPECT_EQ(p[0].digits.r, 0);
  EXPECT_EQ(p[1].digits.r, 2);
  EXPECT_EQ(p[2].digits.r, 3);
  EXPECT_EQ(p[1].source.module_line, 0);
  EXPECT_EQ(p[2].case_number, 3);  // skipped cases (R=2,3) consume case numbers
}

TEST(InpReader, CaseNumbersAndStatePerResultElement) {
  const auto p = read(" 3 MODULE\n" + first_case() + " 3 7 MODULE\n" + first_case() +
                      " 3 MODULE\n" + keep_case() + " 3 7 2 MODULE\n" + first_case() +
                      " 3 7 MODULE\n" + keep_case() + " 0 MODULE\n");
  ASSERT_EQ(p.size(), 5u);
  EXPECT_EQ(p[0].result_element, 0);
  EXPECT_EQ(p[1].result_element, 7);
  EXPECT_EQ(p[1].case_number, 1);
  EXPECT_EQ(p[2].case_number, 2);
  EXPECT_EQ(p[3].result_element, 7);
  EXPECT_EQ(p[3].contact_problem, 2);
  EXPECT_EQ(p[3].case_number, 2);
  EXPECT_EQ(p[4].case_number, 3);
  EXPECT_EQ(p[4].contact_problem, 1);
}

TEST(InpReader, KeepCaseInAnotherElementIsAFirstCaseError) {
  EXPECT_THROW(read(" 3 MODULE\n" + first_case() + " 3 2 MODULE\n" + keep_case()), InputError);
}

TEST(InpReader, FirstCaseOverridesPAndIWithWarnings) {
  std::string text = " 3 MODULE\n" + first_case(1, "001120");
  text.replace(text.find(" 0000541"), 8, " 0010541");  // I=1
  const auto p = read(text);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_EQ(p[0].digits.p, 2);
  EXPECT_EQ(p[0].digits.i, 0);
  ASSERT_EQ(p[0].source.warnings.size(), 2u);
  EXPECT_NE(p[0].source.warnings[0].find("P=0 overridden to 2"), std::string::npos);
  EXPECT_NE(p[0].source.warnings[1].find("I=1 overridden to 0"), std::string::npos);
}

TEST(InpReader, KeepDigitsReuseStoredValues) {
  const auto p = read(" 3 MODULE\n" + first_case() + " 3 MODULE\n" + keep_case(1, -0.125));
  const format::CaseRecord& k = p[1];
  EXPECT_EQ(k.digits.g, 1);
  EXPECT_EQ(k.solver.maxgs, 100);
  EXPECT_DOUBLE_EQ(k.solver.eps, 1e-4);
  EXPECT_EQ(k.friction.law, 0);
  EXPECT_DOUBLE_EQ(k.friction.fkin, 0.4);
  EXPECT_DOUBLE_EQ(k.materials.gg1, 200.0);
  EXPECT_EQ(k.potential.mx, 19);
  EXPECT_DOUBLE_EQ(k.geometry.coeffs[0], 0.01);
  EXPECT_DOUBLE_EQ(k.kinematics.fx_rel, -0.125);
  EXPECT_EQ(k.digits.p, 0);
}

TEST(InpReader, DampingOnKeepOff) {
  std::string c1 = first_case(1, "201120", "022020  2");
  c1.replace(c1.find("    1\n   19"), 0, "  0.1 0.2 1000. 2000.\n");
  std::string c2 = keep_case();  // M2 absent = keep
  std::string c3 = keep_case();
  c3.replace(c3.find("100000"), 6, "100000 0");  // M2=0: off
  const auto p = read(" 3 MODULE\n" + c1 + " 3 MODULE\n" + c2 + " 3 MODULE\n" + c3);
  ASSERT_EQ(p.size(), 3u);
  EXPECT_TRUE(p[0].damping.enabled);
  EXPECT_DOUBLE_EQ(p[0].damping.dftmax, 2000.0);
  EXPECT_TRUE(p[1].damping.enabled);
  EXPECT_EQ(p[1].digits.m2, 1);
  EXPECT_FALSE(p[2].damping.enabled);
  EXPECT_EQ(p[2].digits.m2, 0);
}

TEST(InpReader, SpinCentreNeedsBothValuesAndFacphiIsOptional) {
  const std::string text =
      " 3 MODULE\n 203100\n 022020\n 0000541\n 100 100 30 1 1e-4\n"
      " 9.0 0.001 0.0 0.0 2.5  FN\n 0.3 0.3\n 0.0 0.1 30000. 0.25\n 0.28 0.28 82000 82000\n"
      " -3\n 20 20 1.0 1.0 1.1\n"
      " 3 MODULE\n 003100\n 100000\n 0100541\n 9.0 0.001 0.0 0.0 2.5 -1.5\n";
  const auto p = read(text);
  EXPECT_DOUBLE_EQ(p[0].kinematics.spinxo, 0.0);  // SPINXO alone is ignored
  EXPECT_DOUBLE_EQ(p[0].kinematics.facphi, 0.25);
  EXPECT_DOUBLE_EQ(p[1].kinematics.spinxo, 2.5);
  EXPECT_DOUBLE_EQ(p[1].kinematics.spinyo, -1.5);
  EXPECT_DOUBLE_EQ(p[1].kinematics.facphi, 0.25);  // kept with the rolling line
}

TEST(InpReader, MaxoutOverriddenForIdenticalMaterials) {
  std::string c = first_case();
  c.replace(c.find("100 100 30 1 1e-4"), 17, "100 100 30 9 1e-4");
  const auto p = read(" 3 MODULE\n" + c);
  EXPECT_EQ(p[0].solver.maxout, 1);
  ASSERT_EQ(p[0].source.warnings.size(), 1u);
  EXPECT_NE(p[0].source.warnings[0].find("MAXOUT = 9 overridden to 1"), std::string::npos);
}

TEST(InpReader, GdSteadyLineAndVariableFrictionPerRow) {
  const std::string text =
      " 3 MODULE\n 203100\n 3222020\n 0500541\n 100 100 30 1 1e-4\n"
      " 0.9 0.5 2 0.1 0.2 0.3 0.4 1.5  G=5 line\n"
      " 9.0 0.001 0.0 0.0\n 0.0 0.1 30000.\n 0.28 0.28 82000 82000\n"
      " 1\n 4 3 -2 -1.5 1 1\n 1 1\n 0.01 0 0.01 0 0 0\n"
      " 0.30 0.10 100. 0.0 1.0\n 0.31 0.10 100. 0.0 1.0\n 0.32 0.10 100. 0.0 1.0\n 0.5 10.\n";
  const auto p = read(text);
  const format::CaseRecord& c = p.at(0);
  EXPECT_EQ(c.solver.method, 5);
  EXPECT_DOUBLE_EQ(c.solver.gd.fdecay, 0.9);
  EXPECT_EQ(c.solver.gd.kdowfb, 2);
  EXPECT_DOUBLE_EQ(c.solver.gd.pow_s, 1.5);
  EXPECT_EQ(c.digits.v, 3);
  EXPECT_EQ(c.friction.law, 2);
  ASSERT_EQ(c.friction.rows.size(), 3u);
  EXPECT_DOUBLE_EQ(c.friction.rows[2].fkin, 0.32);
  EXPECT_DOUBLE_EQ(c.friction.rows[2].fstat, 0.42);
  EXPECT_DOUBLE_EQ(c.friction.fkin, 0.30);
  EXPECT_DOUBLE_EQ(c.friction.memdst, 0.5);
  EXPECT_DOUBLE_EQ(c.friction.mem_s0, 10.0);
}

TEST(InpReader, ConformalC4IbaseIplanVariants) {
  const std::string text =
      " 3 MODULE\n 201120\n 024020\n 0000541\n 100 100 30 1 1e-4\n 9.0 0.1 0.0 0.0\n 0.3 0.3\n"
      " 1 2 2  IF_METH VARIANT NN\n -1.0 10d\n 1.0 -10d\n 0.28 0.28 82000 82000\n"
      " 2\n 10 10 -1 -1 1 1\n 3 3\n 1 2 3 4\n 5 6 7 8\n -1 1 -1 1 -0.5 0.5 -0.5 0.5\n"
      " 3 MODULE\n 001120\n 100020\n 0100541\n 9.0 0.1 0.0 0.0\n"
      " 1 4\n 0.01 0 0.01 0 0 0\n 2\n -1 0 -1 1\n 0 1 -1 1\n 0.5\n";
  const auto p = read(text);
  const format::CaseRecord& c = p.at(0);
  EXPECT_EQ(c.materials.influence_type, 4);
  EXPECT_EQ(c.materials.conformal.variant, 2);
  ASSERT_EQ(c.materials.conformal.alpha.size(), 2u);
  EXPECT_DOUBLE_EQ(c.materials.conformal.alpha[1], -10.0 * std::numbers::pi / 180.0);
  EXPECT_EQ(c.potential.ipotcn, 2);
  EXPECT_EQ(c.geometry.ibase, 3);
  EXPECT_EQ(c.geometry.coeffs.size(), 8u);
  EXPECT_EQ(c.geometry.planform.size(), 8u);
  const format::CaseRecord& c2 = p.at(1);
  EXPECT_EQ(c2.materials.influence_type, 4);  // C=0 keeps the coefficient type
  EXPECT_EQ(c2.geometry.iplan, 4);
  EXPECT_EQ(c2.geometry.npatch, 2);
  EXPECT_EQ(c2.geometry.planform.size(), 8u);
  ASSERT_EQ(c2.geometry.patch_factors.size(), 1u);
  EXPECT_DOUBLE_EQ(c2.geometry.patch_factors[0], 0.5);
}

TEST(InpReader, C9FileResolvedAgainstBaseDir) {
  const test_support::ScratchDir scratch("rollcontact_inp_reader_test");
  const std::filesystem::path& dir = scratch.path();
  { std::ofstream(dir / "coef.txt") << "1 0\n"; }
  const std::string text =
      " 3 MODULE\n 201120\n 029020\n 0000541\n 100 100 30 1 1e-4\n 9.0 0.1 0.0 0.0\n 0.3 0.3\n"
      " 'coef.txt'\n 0.28 0.28 82000 82000\n 1\n 10 10 -1 -1 .2 .2\n 1 1\n 0.01 0 0.01 0 0 0\n";
  const auto ok = read_inp_string(text, "t.inp", dir);
  EXPECT_TRUE(ok.at(0).source.case_error.empty());
  EXPECT_EQ(ok.at(0).materials.influence_file, (dir / "coef.txt").lexically_normal().string());
  const auto missing = read_inp_string(text, "t.inp", dir / "elsewhere");
  EXPECT_NE(missing.at(0).source.case_error.find("t.inp:8: influence coefficient file 'coef.txt' "
                                                 "not found"),
            std::string::npos);
}

TEST(InpReader, SubsurfaceColumnListsAreSortedAndUnique) {
  const std::string text = " 3 MODULE\n" + first_case(1, "201123") +
                           " 9 9\n 7\n 3 2\n 5 1 5\n 2 1\n 2\n 0.5 0.1\n 1\n 1 0.0 0.1\n 0\n";
  const auto p = read(text);
  const Subsurface& s = p.at(0).subsurface;
  EXPECT_EQ(s.matfil, 2);  // clamped, with a warning
  EXPECT_EQ(s.output, 4);
  EXPECT_EQ(p[0].source.warnings.size(), 2u);
  ASSERT_EQ(s.blocks.size(), 2u);
  EXPECT_EQ(s.blocks[0].ix, (std::vector<int>{1, 5}));
  EXPECT_EQ(s.blocks[0].iy, (std::vector<int>{1, 2}));
  EXPECT_EQ(s.blocks[0].z, (std::vector<double>{0.1, 0.5}));
  EXPECT_EQ(s.blocks[1].isubs, 1);
  EXPECT_EQ(s.blocks[1].z.size(), 1u);
}

TEST(InpReader, ReadFileErrors) {
  EXPECT_THROW(read_inp_file("/nonexistent/dir/none.inp"), InputError);
  EXPECT_THROW(read(""), InputError);
  EXPECT_TRUE(read(" 0 MODULE\n").empty());
}

}  // namespace
}  // namespace rollcontact::format
