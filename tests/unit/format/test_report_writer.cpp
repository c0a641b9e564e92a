#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "format/report/report_writer.hpp"
#include "rollcontact/version.hpp"

namespace rollcontact::format {
namespace {

Solution small_solution(int mx, int my) {
  Solution s;
  s.grid = {mx, my, 0.0, 0.0, 1.0, 1.0};
  s.state.assign(s.grid.size(), ElementState::Exterior);
  s.material = {82000.0, 0.28, 0.0};
  s.totals.fn = 1000.0;
  return s;
}

std::string report(const format::CaseRecord& p, const Solution& s) {
  std::ostringstream os;
  write_case_report(os, p, s);
  return os.str();
}

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(ReportWriter, OutputLevelsSelectBlocks) {
  format::CaseRecord p;
  p.case_number = 7;
  const Solution s = small_solution(3, 3);
  p.digits.o = 0;
  EXPECT_EQ(report(p, s), "\n Case     7\n");
  p.digits.o = 1;
  std::string r = report(p, s);
  EXPECT_TRUE(
      has(r, "     FN          FX          FY          MZ         ELAST.EN.   FRIC.WORK\n"));
  EXPECT_FALSE(has(r, "TOTAL FORCES"));
  EXPECT_FALSE(has(r, "PBTNFS"));
  p.digits.o = 2;
  r = report(p, s);
  EXPECT_TRUE(has(r, " TOTAL FORCES, TORSIONAL MOMENT"));
  EXPECT_TRUE(has(r, " CONTACT STATISTICS"));
  EXPECT_FALSE(has(r, "FORM OF THE CONTACT"));
  p.digits.o = 3;
  EXPECT_TRUE(has(report(p, s), "FORM OF THE CONTACT"));
  p.digits.o = 5;
  EXPECT_TRUE(has(report(p, s), " QUANTITIES DISTRIBUTED OVER THE CONTACT AREA:"));
  p.digits.r = 2;
  EXPECT_EQ(report(p, s), "\n Case     7\n");
}

TEST(ReportWriter, DigitEchoVariantsAndDescriptions) {
  format::CaseRecord p;
  p.digits.o = 2;
  p.digits.v = 3;
  p.digits.t = 3;
  p.digits.f = 1;
  p.digits.b = 5;
  p.digits.n = 0;
  p.solver.maxout = 10;
  const std::string r = report(p, small_solution(3, 3));
  EXPECT_TRUE(has(
      r, "\n VLDCMZE.  VARFRC 3, FRCLAW 0, DISCNS 2, INFLCF 2, MATER  0, RZNORM 2, RZTANG 0\n"));
  EXPECT_TRUE(has(r, " NORMAL PROBLEM WITH PRESCRIBED APPROACH, APPROXIMATE KPEC SOLUTION\n"));
  EXPECT_TRUE(has(r, " STEADY STATE ROLLING\n X-FORCE,  Y-CREEPAGE PRESCRIBED\n"));
  EXPECT_TRUE(has(r, " PANAGIOTOPOULOS\" METHOD IS USED FOR THE FRICTIONAL STRESS. MAXOUT= 10\n"));
  EXPECT_TRUE(has(r, "     CHI         DQ          VELOC     FX/FSTAT/FN   CETA        CPHI\n"));
  EXPECT_TRUE(has(r, "     FN/G       CREEP X     FY/FSTAT/FN  APPROACH     PMAX"));
  EXPECT_TRUE(has(r, "FRIC.POWER\n"));
}

TEST(ReportWriter, FastsimAndLayerBlocks) {
  format::CaseRecord p;
  p.digits.o = 2;
  p.digits.t = 3;
  p.digits.m = 3;
  p.digits.b = 3;
  p.digits.l = 4;
  p.friction.law = 4;
  p.friction.fkin = 0.14;
  p.friction.params = {0.19, 1250.0, 0.0, 1e-4};
  p.materials.model_params = {0.54, 0.02, 0.62, 0.0};
  std::string r = report(p, small_solution(3, 3));
  EXPECT_TRUE(has(r, " NORMAL PROBLEM SKIPPED, PARABOLICAL TRACTION BOUND\n"));
  EXPECT_TRUE(has(r, " STEADY STATE ROLLING,  \"FASTSIM APPROACH\"\n"));
  EXPECT_TRUE(has(r,
                  " MODIFIED FASTSIM SLOPE REDUCTION PARAMETERS\n     K0_MF       ALFAMF      "
                  "BETAMF      K_EFF\n"
                  "    0.5400      0.2000E-01  0.6200"));
  EXPECT_TRUE(has(r,
                  "     FKIN        FEXP1       SABSH1      FEXP2       SABSH2\n"
                  "    0.1400      0.1900       1250.       0.000      0.1000E-03\n"));
  p.digits.m = 4;
  p.materials.model_params = {176.6, 0.02, 560.0, 0.0};
  Solution s = small_solution(3, 3);
  s.statistics.nplast = 1;
  r = report(p, s);
  EXPECT_TRUE(
      has(r, " INTERFACIAL LAYER PARAMETERS\n     GG3         LAYTHK      TAU_C0      K_TAU\n"));
  EXPECT_TRUE(has(r, "    NPOT   NCON   NADH  NSLIP  NPLAST INORM  ITANG\n"));
  p.digits.c = 0;
  p.digits.l = 1;
  r = report(p, s);
  EXPECT_FALSE(has(r, "MATERIAL CONSTANTS"));
  EXPECT_FALSE(has(r, "FRICTION LAW PARAMETERS"));
}

TEST(ReportWriter, VariableFrictionRowsAreElided) {
  format::CaseRecord p;
  p.digits.o = 2;
  p.digits.v = 3;
  for (int iy = 0; iy < 6; ++iy) p.friction.rows.push_back({0.1 * (iy + 1), 0.1 * (iy + 1), {}});
  const std::string r = report(p, small_solution(3, 6));
  // Layout of CONTACT's format (2x, 4x,'IY',6x, 3x,'FSTAT',...) / (2x, i8, 4x, 6g12.4).
  EXPECT_TRUE(has(r,
                  " FRICTION LAW PARAMETERS\n      IY         FSTAT       FKIN\n"
                  "         1      0.1000      0.1000    \n"
                  "         2      0.2000      0.2000    \n"
                  "                      ...\n"
                  "         5      0.5000      0.5000    \n"
                  "         6      0.6000      0.6000    \n"));
}

TEST(ReportWriter, ForceFilteringAndSolvedCreepage) {
  format::CaseRecord p;
  p.digits.o = 1;
  p.digits.t = 2;
  p.digits.f = 1;
  p.solver.eps = 1e-4;
  p.friction.fstat = 0.3;
  Solution s = small_solution(3, 3);
  s.totals.fx = 0.014;   // below 0.5 * 1e-4 * 0.3 * 1000 = 0.015
  s.totals.fy = -0.016;  // above
  s.totals.creep_x = 1.824e-3;
  const std::string r = report(p, s);
  EXPECT_TRUE(has(r, "       1000.       0.000  -1.600E-02       0.000       0.000       0.000\n"));
  EXPECT_TRUE(has(r, "   1.824E-03"));
  EXPECT_TRUE(has(r, "FRIC.POWER"));
}

TEST(ReportWriter, PictureWithoutBlanksAndChi) {
  Solution s = small_solution(55, 1);
  for (int ix = 3; ix <= 52; ++ix)
    s.state[static_cast<std::size_t>(ix - 1)] =
        ix <= 22 ? ElementState::Slip : ElementState::Adhesion;
  std::ostringstream os;
  write_element_division(os, s, 3, 0.0);
  EXPECT_EQ(os.str(),
            "     1  o.SSSSSSSSSSSSSSSSSSSS******************************..o\n"
            "                 1         2         3         4         5\n"
            "        1234567890123456789012345678901234567890123456789012345\n"
            "     X  -->        Chi=  0.00 degrees\n");
}

TEST(ReportWriter, PictureWindowAroundSmallContact) {
  Solution s = small_solution(30, 20);
  s.state[s.grid.index(14, 9)] = ElementState::Plastic;
  s.state[s.grid.index(15, 9)] = ElementState::Adhesion;
  std::ostringstream os;
  write_element_division(os, s, 1);
  EXPECT_EQ(os.str(),
            "    11   o . . o\n"
            "    10   . | * .\n"
            "     9   o . . o\n"
            "         4 5 6 7\n"  // fewer than 10 columns: no tens row
            "     X  -->\n");
}

TEST(ReportWriter, PictureOfEmptyContactShowsTheMiddle) {
  const Solution s = small_solution(30, 30);
  std::ostringstream os;
  write_element_division(os, s, 0);
  const std::string r = os.str();
  EXPECT_TRUE(has(r, "    20   o . . . . . . . . . o\n"));  // columns and rows 10..20
  EXPECT_TRUE(has(r, "    10   o . . . . . . . . . o\n"));
  EXPECT_TRUE(has(r, "\n         1                   2\n         0 1 2 3 4 5 6 7 8 9 0\n"));
}

TEST(ReportWriter, PictureHundredsRowForWideWindows) {
  Solution s = small_solution(250, 1);
  for (auto& st : s.state) st = ElementState::Slip;
  std::ostringstream os;
  write_element_division(os, s, 0);
  const std::string r = os.str();
  const auto first = r.find('\n');
  const std::string hundreds = r.substr(first + 1, r.find('\n', first + 1) - first - 1);
  EXPECT_EQ(hundreds, std::string(8 + 99, ' ') + "1" + std::string(99, ' ') + "2");
}

TEST(ReportWriter, FrameAndErrors) {
  std::ostringstream os;
  write_report_banner(os);
  const std::string banner = os.str();
  EXPECT_TRUE(has(banner, "rollcontact"));
  EXPECT_TRUE(has(banner, version_string));
  os.str("");
  format::CaseRecord p;
  p.case_number = 3;
  p.result_element = 2;
  write_case_error(os, p, "influence file missing\nsecond line");
  EXPECT_EQ(
      os.str(),
      "\n Case     3, result element   2\n ERROR: influence file missing\n        second line\n");
  os.str("");
  write_report_end(os);
  EXPECT_TRUE(has(os.str(), "\n|---"));
  EXPECT_TRUE(has(os.str(), " The rollcontact program ended successfully.\n"));
}

TEST(ReportWriter, NotConvergedAndWarningsAreReported) {
  format::CaseRecord p;
  p.digits.o = 1;
  Solution s = small_solution(2, 2);
  s.solver.converged = false;
  s.solver.message = "MAXIN reached";
  s.warnings.push_back("Using DQ = DX = 0.2889");
  const std::string r = report(p, s);
  EXPECT_TRUE(has(r, " WARNING: Using DQ = DX = 0.2889\n"));
  EXPECT_TRUE(has(r, " WARNING: the solver did not converge: MAXIN reached\n"));
}

}  // namespace
}  // namespace rollcontact::format
