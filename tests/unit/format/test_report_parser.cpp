// Reading CONTACT-style reports (spec/validation.md §2): number tokens, synthetic reports, and
// every .ref_out of the CONTACT examples with spot checks against validation.md §1.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include "format/report/report_parser.hpp"
#include "support/examples.hpp"

namespace rollcontact::format {
namespace {

using test_support::kExamples;

Report parse_text(const std::string& text) {
  std::istringstream in(text);
  return parse_report(in);
}

double value_of(const Report& r, int case_number, const std::string& name) {
  const ReportCase* c = r.find(case_number);
  if (c == nullptr) {
    ADD_FAILURE() << "case " << case_number << " missing";
    return std::nan("");
  }
  const auto v = c->value(name);
  if (!v) {
    ADD_FAILURE() << "case " << case_number << ": no " << name;
    return std::nan("");
  }
  return *v;
}

// Relative closeness for printed 4-digit values.
void expect_close(double actual, double expected, double rel = 1e-9) {
  EXPECT_NEAR(actual, expected, rel * std::abs(expected) + 1e-300) << "expected " << expected;
}

TEST(ReportParser, NumberTokens) {
  EXPECT_EQ(parse_report_real("10000."), 10000.0);
  EXPECT_EQ(parse_report_real("1.000E+04"), 10000.0);
  EXPECT_DOUBLE_EQ(*parse_report_real("0.1000E-03"), 1e-4);
  EXPECT_DOUBLE_EQ(*parse_report_real("-3.218"), -3.218);
  const auto negative_zero = parse_report_real("-0.000");
  ASSERT_TRUE(negative_zero);
  EXPECT_EQ(*negative_zero, 0.0);
  EXPECT_DOUBLE_EQ(*parse_report_real("1.5D+02"), 150.0);
  EXPECT_DOUBLE_EQ(*parse_report_real("0.1000-100"), 1e-101);
  EXPECT_DOUBLE_EQ(*parse_report_real("+2.5"), 2.5);
  EXPECT_DOUBLE_EQ(*parse_report_real("  7  "), 7.0);
  EXPECT_FALSE(parse_report_real("***"));
  EXPECT_FALSE(parse_report_real("nan"));
  EXPECT_FALSE(parse_report_real("inf"));
  EXPECT_FALSE(parse_report_real("FN"));
  EXPECT_FALSE(parse_report_real("."));
  EXPECT_FALSE(parse_report_real(""));
  EXPECT_FALSE(parse_report_real("1.0.0"));
}

// Two module-3 cases: labels decide what the X/Y value is; trace lines that look like labels
// are ignored; an overflowed field is NaN; reading stops at the timing table.
constexpr const char* kSynthetic =
    R"(   ------------------------------------------------------------------------
   |  banner                                                              |
   ------------------------------------------------------------------------

 Case     1
      Norm: final element division: C, E=    177    184  ItCG=     4
         0, NR_Fy,    Cksi, Fxk:    1.000E-06  -1.356E-04

 TOTAL FORCES, TORSIONAL MOMENT, ELASTIC ENERGY, FRICTIONAL POWER
     FN          FX          FY          MZ         ELAST.EN.   FRIC.WORK
         9.195      -3.218       0.000   ************   8.525E-05  -2.750E-06
     FN/G       SHIFT X      SHIFT Y     APPROACH     PMAX    
     4.598E-02   8.155E-03      -0.000   1.998E-02       4.393

 CONTACT STATISTICS
    NPOT   NCON   NADH  NSLIP  INORM  ITANG
     361    177     45    132      1      1

 Case     2, result element   1
     FN          FX          FY          MZ         ELAST.EN.   FRIC.POWER
     8.200E+04      0.000  -1.494E+04  -4.821E+04       3.231      -540.4
     FN/G       CREEP X     FY/FSTAT/FN  APPROACH     PMAX      MAX(T1,T2)
         1.000   1.378E-02     -0.6074   9.266E-02       1223.       166.8
    NPOT   NCON   NADH  NSLIP  NPLAST INORM  ITANG
     900    500    400     90     10      3      4

 Case     3
 ERROR: /x/y.inp:35: not supported yet: tangential problem T=1
        second line of the message

|--------------------------------------------------------------------------|
 Case     4
     FN          FX          FY          MZ         ELAST.EN.   FRIC.POWER
         1.000       0.000       0.000       0.000       0.000       0.000
)";

TEST(ReportParser, SyntheticModule3) {
  const Report r = parse_text(kSynthetic);
  ASSERT_EQ(r.cases.size(), 3u);  // case 4 is after the timing table

  const ReportCase& c1 = r.cases[0];
  EXPECT_EQ(c1.number, 1);
  EXPECT_TRUE(c1.error.empty());
  expect_close(value_of(r, 1, "FN"), 9.195);
  expect_close(value_of(r, 1, "FX"), -3.218);
  EXPECT_TRUE(std::isnan(value_of(r, 1, "MZ")));
  expect_close(value_of(r, 1, "ELEN"), 8.525e-5);  // position is kept after the asterisks
  expect_close(value_of(r, 1, "FRIC"), -2.750e-6);
  expect_close(value_of(r, 1, "SHIFT X"), 8.155e-3);
  EXPECT_EQ(value_of(r, 1, "SHIFT Y"), 0.0);
  EXPECT_FALSE(c1.value("FX/FSTAT/FN"));
  EXPECT_FALSE(c1.value("CREEP X"));
  expect_close(value_of(r, 1, "APPROACH"), 1.998e-2);
  expect_close(value_of(r, 1, "PMAX"), 4.393);
  EXPECT_EQ(value_of(r, 1, "NCON"), 177);
  EXPECT_EQ(value_of(r, 1, "NADH"), 45);
  EXPECT_EQ(value_of(r, 1, "NSLIP"), 132);
  EXPECT_EQ(value_of(r, 1, "ITANG"), 1);

  EXPECT_EQ(r.cases[1].number, 2);
  expect_close(value_of(r, 2, "CREEP X"), 1.378e-2);
  expect_close(value_of(r, 2, "FY/FSTAT/FN"), -0.6074);
  expect_close(value_of(r, 2, "MAX(T1,T2)"), 166.8);
  expect_close(value_of(r, 2, "PMAX"), 1223.0);
  EXPECT_EQ(value_of(r, 2, "NPLAST"), 10);
  EXPECT_EQ(value_of(r, 2, "INORM"), 3);

  const ReportCase& c3 = r.cases[2];
  EXPECT_EQ(c3.number, 3);
  EXPECT_EQ(c3.error,
            "/x/y.inp:35: not supported yet: tangential problem T=1 second line of the message");
  EXPECT_TRUE(c3.values.empty());
}

TEST(ReportParser, ModulePatchesArePrefixed) {
  const Report r = parse_text(R"(
 Case     1
 TOTAL FORCES ON RAIL
     FX(TR)      FY(TR)      FZ(TR)      FX(WS)      FY(WS)      FZ(WS)
      0.2783       36.24      10000.      0.2783       36.24      10000.

 ----- DATA FOR CONTACT PATCH  1 -----
     FN          FX          FS          MN         ELAST.EN.   FRIC.POWER
         9997.      0.2783      -253.6      -4605.   6.042E-02     -0.4677
     FN/G      FX/FSTAT/FN FS/FSTAT/FN   APPROACH     PMAX    
        0.1219   9.281E-05  -8.458E-02   1.596E-02       338.3
    NPOT   NCON   NADH  NSLIP  INORM  ITANG
   3999   1291    943    348      1      1

 ----- DATA FOR CONTACT PATCH  2 -----
     BAR_FN      BAR_FX      BAR_FS      MN         ELAST.EN.   FRIC.POWER
         9897.      -613.9      -1991.       45.39      0.1240      -60.81
     TILDE_FN    FX/FN       FS/FN       APPROACH     PMAX    
         9903.  -6.199E-02     -0.1999   2.980E-02       1499.
)");
  ASSERT_EQ(r.cases.size(), 1u);
  expect_close(value_of(r, 1, "FX(TR)"), 0.2783);
  expect_close(value_of(r, 1, "FZ(WS)"), 10000.0);
  expect_close(value_of(r, 1, "patch 1/FN"), 9997.0);
  expect_close(value_of(r, 1, "patch 1/FS"), -253.6);
  expect_close(value_of(r, 1, "patch 1/MN"), -4605.0);
  expect_close(value_of(r, 1, "patch 1/FS/FSTAT/FN"), -8.458e-2);
  expect_close(value_of(r, 1, "patch 1/PMAX"), 338.3);
  EXPECT_EQ(value_of(r, 1, "patch 1/NCON"), 1291);
  expect_close(value_of(r, 1, "patch 2/BAR_FN"), 9897.0);
  expect_close(value_of(r, 1, "patch 2/TILDE_FN"), 9903.0);
  expect_close(value_of(r, 1, "patch 2/FS/FN"), -0.1999);
  expect_close(value_of(r, 1, "patch 2/PMAX"), 1499.0);
  EXPECT_FALSE(r.cases[0].value("FN"));
}

TEST(ReportParser, SubsurfaceExtremesPerBlockAndPatch) {
  // mbench_a22_varfric.ref_out case 1 (module 1, patch 1) and a module-3 block 2: the extremes
  // by name, their locations dropped; lines of other blocks are not taken for them.
  const Report r = parse_text(R"(
 Case     1
 ----- DATA FOR CONTACT PATCH  1 -----
 SUBSURFACE STRESSES BLOCK  1:
 
 ABSMAX SIGHYD =  -295.685 AT (X,Y,Z) = (   0.000,   2.000,   0.000)
 MAX     SIGVM =   210.509 AT (X,Y,Z) = (   0.200,   2.000,   1.500)
 MIN    SIGMA3 =  -386.841 AT (X,Y,Z) = (  -0.200,  -9.800,   0.000)

 Case     2
 SUBSURFACE STRESSES BLOCK  2:
 
 ABSMAX SIGHYD = -1353.161 AT (X,Y,Z) = (  -0.200,  -0.200,   0.000)
 MAX    SIGMA1 =     0.000 AT (X,Y,Z) = (   0.200,   0.600,   0.000)
)");
  ASSERT_EQ(r.cases.size(), 2u);
  expect_close(value_of(r, 1, "patch 1/SUBS 1/SIGHYD"), -295.685);
  expect_close(value_of(r, 1, "patch 1/SUBS 1/SIGVM"), 210.509);
  expect_close(value_of(r, 1, "patch 1/SUBS 1/SIGMA3"), -386.841);
  expect_close(value_of(r, 2, "SUBS 2/SIGHYD"), -1353.161);
  EXPECT_EQ(value_of(r, 2, "SUBS 2/SIGMA1"), 0.0);
  EXPECT_FALSE(r.cases[1].value("SUBS 1/SIGHYD"));
}

// Case headers counted independently of the parser: `^ Case\s+(\d+)` before the timing table.
std::size_t count_case_headers(const std::filesystem::path& file) {
  std::ifstream in(file);
  const std::regex header(R"(^ Case\s+(\d+).*)");
  std::size_t n = 0;
  std::string line;
  while (std::getline(in, line) && (line.empty() || line[0] != '|'))
    if (std::regex_match(line, header)) ++n;
  return n;
}

TEST(ReportParser, EveryReferenceReport) {
  REQUIRE_EXAMPLES();
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kExamples)) {
    if (entry.path().extension() != ".ref_out") continue;
    ++files;
    SCOPED_TRACE(entry.path().filename().string());
    const Report r = parse_report_file(entry.path());
    EXPECT_EQ(r.cases.size(), count_case_headers(entry.path()));
    for (const auto& c : r.cases) {
      EXPECT_TRUE(c.error.empty());
      for (const auto& [key, v] : c.values) EXPECT_FALSE(std::isnan(v)) << "c" << c.number << key;
    }
  }
  EXPECT_EQ(files, 18);
}

Report reference(const std::string& name) {
  return parse_report_file(kExamples / (name + ".ref_out"));
}

TEST(ReportParser, ReferenceSpotValues) {
  REQUIRE_EXAMPLES();
  const Report cattaneo = reference("cattaneo");
  ASSERT_EQ(cattaneo.cases.size(), 2u);
  expect_close(value_of(cattaneo, 1, "FN"), 9.195);
  expect_close(value_of(cattaneo, 1, "APPROACH"), 1.998e-2);
  expect_close(value_of(cattaneo, 1, "PMAX"), 4.393);
  expect_close(value_of(cattaneo, 1, "ELEN"), 7.350e-5);
  EXPECT_EQ(value_of(cattaneo, 1, "NCON"), 177);
  expect_close(value_of(cattaneo, 2, "FX"), -3.218);
  expect_close(value_of(cattaneo, 2, "SHIFT X"), 8.155e-3);
  expect_close(value_of(cattaneo, 2, "FRIC"), -2.750e-6);
  EXPECT_EQ(value_of(cattaneo, 2, "NADH"), 45);
  EXPECT_EQ(value_of(cattaneo, 2, "NSLIP"), 132);

  const Report tractcurv = reference("tractcurv");
  ASSERT_EQ(tractcurv.cases.size(), 120u);
  expect_close(value_of(tractcurv, 1, "FX"), -247.0);
  expect_close(value_of(tractcurv, 30, "FX"), -3.521e4);
  expect_close(value_of(tractcurv, 61, "FX"), -250.9);
  expect_close(value_of(tractcurv, 120, "FX"), -1.874e4);

  const Report bentall = reference("bentall");
  ASSERT_EQ(bentall.cases.size(), 6u);
  EXPECT_TRUE(bentall.cases[0].values.empty());  // c1: O=0
  const double creep[] = {5.260e-4, 3.591e-4, 4.294e-4, 2.108e-4, 5.392e-4};
  for (int k = 2; k <= 6; ++k) expect_close(value_of(bentall, k, "CREEP X"), creep[k - 2]);
  expect_close(value_of(bentall, 5, "FX"), 607.6);
  EXPECT_EQ(value_of(bentall, 6, "NCON"), 201);

  const Report carter = reference("carter2d");
  ASSERT_EQ(carter.cases.size(), 1u);
  expect_close(value_of(carter, 1, "FN"), 3.578e4);
  expect_close(value_of(carter, 1, "FX"), 6955.0);
  expect_close(value_of(carter, 1, "FX/FSTAT/FN"), 0.6480);
  expect_close(value_of(carter, 1, "APPROACH"), 6.492e-3);
  expect_close(value_of(carter, 1, "PMAX"), 113.9);
  EXPECT_EQ(value_of(carter, 1, "NPOT"), 55);
  EXPECT_EQ(value_of(carter, 1, "NCON"), 50);
  EXPECT_EQ(value_of(carter, 1, "NADH"), 30);
  EXPECT_EQ(value_of(carter, 1, "NSLIP"), 20);

  const Report temperature = reference("ertz_temperature");
  expect_close(value_of(temperature, 1, "MAX(T1,T2)"), 166.8);
  expect_close(value_of(temperature, 4, "FY"), -4476.0);

  const Report spence = reference("spence35");
  expect_close(value_of(spence, 35, "APPROACH"), 9.874e-2);
  EXPECT_EQ(value_of(spence, 35, "NPOT"), 2025);
  EXPECT_EQ(value_of(spence, 35, "NSLIP"), 696);
}

TEST(ReportParser, ReferenceModule1) {
  REQUIRE_EXAMPLES();
  const Report right = reference("mbench_a22_right");
  ASSERT_EQ(right.cases.size(), 21u);
  expect_close(value_of(right, 1, "FX(TR)"), 0.2783);
  expect_close(value_of(right, 1, "FY(TR)"), 36.24);
  expect_close(value_of(right, 1, "FZ(TR)"), 10000.0);
  expect_close(value_of(right, 1, "patch 1/FN"), 9997.0);
  expect_close(value_of(right, 1, "patch 1/FS"), -253.6);
  expect_close(value_of(right, 1, "patch 1/PMAX"), 338.3);
  EXPECT_EQ(value_of(right, 1, "patch 1/NCON"), 1291);
  expect_close(value_of(right, 14, "FX(TR)"), -1987.0);

  const Report varfric = reference("mbench_a22_varfric");
  expect_close(value_of(varfric, 3, "FX(TR)"), -637.4);
  EXPECT_TRUE(varfric.find(3)->value("patch 2/FN").has_value());
  expect_close(value_of(varfric, 5, "patch 1/BAR_FN"), 9897.0);
  expect_close(value_of(varfric, 5, "patch 1/TILDE_FN"), 9903.0);
}

}  // namespace
}  // namespace rollcontact::format
