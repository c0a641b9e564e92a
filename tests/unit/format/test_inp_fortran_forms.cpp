// CONTACT's number forms in whole input files (issue 13 item 6): integral reals in integer
// fields, exponents without their letter, D exponents — the same case as the plain writing.

#include <gtest/gtest.h>

#include <string>

#include "format/inp/inp_reader.hpp"
#include "rollcontact/errors.hpp"

namespace rollcontact::format {
namespace {

std::string shift_case(const std::string& iteration_line, const std::string& load_line,
                       const std::string& ipotcn) {
  return " 3  MODULE\n  201100      P-B-T-N-F-S\n  022020      L-D-C-M-Z-E\n"
         " 0001341    H-G-I-A-O-W-R\n" +
         iteration_line + "\n" + load_line +
         "\n  0.4013      0.4013\n  0.280       0.280       1.000       1.000\n" + ipotcn +
         "\n   34   33   -4.125    -4.125    0.250   0.250\n       1           1\n"
         " 0.002963    0.000     0.002963    0.000     0.000     0.000\n 0  MODULE\n";
}

TEST(InpFortranForms, ReadTheSameCaseAsPlainNumbers) {
  const auto plain = read_inp_string(shift_case("   100   100    30     1      1e-7",
                                                "  0.4705     -0.0177   0.000  0.000", "    1"),
                                     "plain.inp");
  const auto fortran = read_inp_string(shift_case("   100.   1.0D2    30     1.0      .1-06",
                                                  "  4.705-1   -1.77D-2   0. 0.", "    1.0"),
                                       "fortran.inp");
  ASSERT_EQ(plain.size(), 1U);
  ASSERT_EQ(fortran.size(), 1U);
  const CaseRecord& a = plain[0];
  const CaseRecord& b = fortran[0];
  EXPECT_EQ(b.solver.maxgs, a.solver.maxgs);
  EXPECT_EQ(b.solver.maxin, a.solver.maxin);
  EXPECT_EQ(b.solver.maxout, a.solver.maxout);
  EXPECT_DOUBLE_EQ(b.solver.eps, a.solver.eps);
  EXPECT_DOUBLE_EQ(b.kinematics.fn, a.kinematics.fn);
  EXPECT_DOUBLE_EQ(b.kinematics.cksi, a.kinematics.cksi);
  EXPECT_EQ(b.potential.ipotcn, a.potential.ipotcn);
}

TEST(InpFortranForms, NonIntegralValuesInIntegerFieldsStayErrors) {
  try {
    (void)read_inp_string(
        shift_case("   100   100    30     1.5      1e-7", "  0.4705  -0.0177  0.0  0.0", "    1"),
        "bad.inp");
    FAIL() << "MAXOUT = 1.5 accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.inp:5"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("'1.5'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace rollcontact::format
