#include <gtest/gtest.h>

#include "format/report/number_format.hpp"

namespace rollcontact::format {
namespace {

TEST(NumberFormat, SignificantDigitsFixed) {
  EXPECT_EQ(fmt_sig(12, 4, 4, 9.1954), "       9.195");
  EXPECT_EQ(fmt_sig(12, 4, 4, -36.2389), "      -36.24");
  EXPECT_EQ(fmt_sig(12, 4, 4, 0.12191), "      0.1219");
  EXPECT_EQ(fmt_sig(12, 4, 4, 1223.4), "       1223.");
  EXPECT_EQ(fmt_sig(12, 4, 4, 0.0), "       0.000");
}

TEST(NumberFormat, NegativeZeroPrintsAsZero) {
  // A zero mirrored for the left wheel is −0.0; CONTACT's report has 0.000 there.
  EXPECT_EQ(fmt_sig(12, 4, 4, -0.0), fmt_sig(12, 4, 4, 0.0));
  EXPECT_EQ(fmt_sig(12, 4, 4, -0.0).find('-'), std::string::npos);
}

TEST(NumberFormat, SignificantDigitsDecidedBeforeRounding) {
  // lg is taken from the unrounded value: 9999.7 keeps the fixed form and rounds to "10000.",
  // 0.99999 prints with four decimals.
  EXPECT_EQ(fmt_sig(12, 4, 4, 9999.7), "      10000.");
  EXPECT_EQ(fmt_sig(12, 4, 4, 0.99999), "      1.0000");
  EXPECT_EQ(fmt_sig(12, 4, 4, 1.0), "       1.000");
  EXPECT_EQ(fmt_sig(12, 4, 4, 10000.0), "   1.000E+04");
}

TEST(NumberFormat, SignificantDigitsScientific) {
  EXPECT_EQ(fmt_sig(12, 4, 4, 0.019984), "   1.998E-02");
  EXPECT_EQ(fmt_sig(12, 4, 4, 0.045977), "   4.598E-02");
  EXPECT_EQ(fmt_sig(12, 4, 4, 82000.0), "   8.200E+04");
  EXPECT_EQ(fmt_sig(12, 4, 4, -2.75e-6), "  -2.750E-06");
  EXPECT_EQ(fmt_sig(12, 3, 3, -30300.0), "   -3.03E+04");
}

TEST(NumberFormat, SignificantDigitsApproachAndSensitivities) {
  EXPECT_EQ(fmt_sig(12, 6, 4, 0.8079841), "    0.807984");
  EXPECT_EQ(fmt_sig(12, 6, 4, 2.508451), "     2.50845");
  EXPECT_EQ(fmt_sig(12, 3, 3, 0.0), "        0.00");
  EXPECT_EQ(fmt_sig(12, 3, 3, -67.61), "       -67.6");
  EXPECT_EQ(fmt_sig(12, 3, 3, -117.2), "       -117.");
}

TEST(NumberFormat, FortranG) {
  EXPECT_EQ(fortran_g(0.42, 12, 4), "  0.4200    ");
  EXPECT_EQ(fortran_g(200.0, 12, 4), "   200.0    ");
  EXPECT_EQ(fortran_g(1e-4, 12, 4), "  0.1000E-03");
  EXPECT_EQ(fortran_g(82000.0, 12, 4), "  0.8200E+05");
  EXPECT_EQ(fortran_g(0.0, 12, 4), "   0.000    ");
  EXPECT_EQ(fortran_g(-0.9333, 12, 4), " -0.9333    ");
  EXPECT_EQ(fortran_g(-3.5e-5, 12, 4), " -0.3500E-04");
  EXPECT_EQ(fortran_g(9999.7, 12, 4), "  0.1000E+05");    // rounds up out of the fixed range
  EXPECT_EQ(fortran_g(0.099996, 12, 4), "  0.1000    ");  // rounds up into the fixed range
  EXPECT_EQ(fortran_g(10.0, 12, 4), "   10.00    ");
}

TEST(NumberFormat, FortranG11) {
  EXPECT_EQ(fortran_g(-0.00555, 11, 3), " -0.555E-02");
  EXPECT_EQ(fortran_g(28.2258, 11, 3), "   28.2    ");
  EXPECT_EQ(fortran_g(101.72, 11, 3), "   102.    ");
  EXPECT_EQ(fortran_g(0.0, 11, 3), "   0.00    ");
  EXPECT_EQ(fortran_g(0.901, 11, 3), "  0.901    ");
}

TEST(NumberFormat, FortranFAndE) {
  EXPECT_EQ(fortran_f(176.44, 10, 1), "     176.4");
  EXPECT_EQ(fortran_f(-180.0, 10, 1), "    -180.0");
  EXPECT_EQ(fortran_f(-1e-5, 10, 1), "      -0.0");
  EXPECT_EQ(fortran_f(1.0, 8, 3), "   1.000");
  EXPECT_EQ(fortran_f(0.5, 4, 3), ".500");  // leading zero dropped to fit
  EXPECT_EQ(fortran_f(12345.0, 6, 2), "******");
  EXPECT_EQ(fortran_e(-3.5e-5, 12, 4), " -0.3500E-04");
  EXPECT_EQ(fortran_e(0.0, 12, 4), "  0.0000E+00");
  EXPECT_EQ(fortran_e(1.5e120, 12, 4), "  0.1500+121");
  EXPECT_EQ(fortran_e(0.5, 9, 4), ".5000E+00");
}

TEST(NumberFormat, IntegersAndFilter) {
  EXPECT_EQ(fortran_i(361, 7), "    361");
  EXPECT_EQ(fortran_i(-5, 2), "-5");
  EXPECT_EQ(fortran_i(1234, 3), "***");
  EXPECT_EQ(filter_small(1e-9, 1e-6), 0.0);
  EXPECT_EQ(filter_small(-2e-6, 1e-6), -2e-6);
}

}  // namespace
}  // namespace rollcontact::format
