// Kalker's creepage coefficients: table points, monotonicity, the switch to the asymptotic
// formulas at g = 0.101 and the reciprocal (1/C quadratic) interpolation in ν.

#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "rollcontact/errors.hpp"
#include "simplified/kalker_coefficients.hpp"

namespace rollcontact::simplified {
namespace {

constexpr std::array<double, 3> nus{0.0, 0.25, 0.5};

/// a/b of table row r (0: 0.1 … 9: 1.0 … 18: 1/0.1).
double row_ratio(int r) {
  return r <= 9 ? (r + 1) / 10.0 : 1.0 / ((19 - r) / 10.0);
}

std::array<double, 3> as_array(const KalkerCoefficients& c) {
  return {c.c11, c.c22, c.c23};
}

TEST(KalkerCoefficients, ReproducesTheTableAtItsPoints) {
  // Rows with g = 0.1 (a/b = 0.1 and 10) lie below g = 0.101 and use the asymptotic formulas.
  for (int r = 1; r <= 17; ++r) {
    for (int j = 0; j < 3; ++j) {
      const auto expected = as_array(kalker_table_entry(r, j));
      const auto got =
          as_array(kalker_coefficients(row_ratio(r), nus[static_cast<std::size_t>(j)]));
      for (std::size_t k = 0; k < 3; ++k)
        EXPECT_NEAR(got[k], expected[k], 1e-12 * expected[k]) << "row " << r << " nu col " << j;
    }
  }
}

TEST(KalkerCoefficients, CorrectedEntryAtAOverB08) {
  EXPECT_DOUBLE_EQ(kalker_table_entry(7, 1).c23, 1.25);
  EXPECT_NEAR(kalker_coefficients(0.8, 0.25).c23, 1.25, 1e-12);
}

TEST(KalkerCoefficients, LinearInGBetweenRows) {
  // Upper half: g = a/b; halfway between rows 0.5 and 0.6 at ν = 0.
  EXPECT_NEAR(kalker_coefficients(0.55, 0.0).c11, 0.5 * (2.88 + 2.98), 1e-12);
  // Lower half: g = b/a = 0.55, i.e. a/b = 1/0.55 (not halfway in a/b).
  EXPECT_NEAR(kalker_coefficients(1.0 / 0.55, 0.0).c22, 0.5 * (4.37 + 4.06), 1e-12);
}

TEST(KalkerCoefficients, ReciprocalsAreQuadraticInNu) {
  // The third difference of 1/C over equally spaced ν vanishes for a quadratic.
  for (double aob : {0.15, 0.37, 1.0, 1.7, 6.3}) {
    std::array<std::array<double, 3>, 4> inv{};
    for (std::size_t k = 0; k < 4; ++k) {
      const auto c = as_array(kalker_coefficients(aob, 0.05 + 0.13 * static_cast<double>(k)));
      for (std::size_t m = 0; m < 3; ++m) inv[k][m] = 1.0 / c[m];
    }
    for (std::size_t m = 0; m < 3; ++m) {
      const double third = inv[3][m] - 3.0 * inv[2][m] + 3.0 * inv[1][m] - inv[0][m];
      EXPECT_NEAR(third, 0.0, 1e-12) << "a/b " << aob << " column " << m;
    }
  }
}

TEST(KalkerCoefficients, MonotoneInAOverBWithinTheTable) {
  // Kalker's values grow with a/b, except C11 at ν = 0.5 for slender ellipses a/b < 0.4
  // (4.85, 4.81, 4.80, 4.82 in the table itself).
  for (double nu : {0.0, 0.1, 0.25, 0.4, 0.5}) {
    KalkerCoefficients prev = kalker_coefficients(0.102, nu);
    double prev_aob = 0.102;
    for (int k = 1; k <= 400; ++k) {
      const double aob = 0.102 * std::pow(9.8 / 0.102, k / 400.0);
      const KalkerCoefficients c = kalker_coefficients(aob, nu);
      if (nu < 0.45 || prev_aob >= 0.4) {
        EXPECT_GE(c.c11, prev.c11 - 1e-12) << aob << " " << nu;
      }
      EXPECT_GE(c.c22, prev.c22 - 1e-12) << aob << " " << nu;
      EXPECT_GE(c.c23, prev.c23 - 1e-12) << aob << " " << nu;
      prev = c;
      prev_aob = aob;
    }
  }
}

TEST(KalkerCoefficients, MonotoneInTheAsymptoticRanges) {
  for (double nu : {0.0, 0.25, 0.5}) {
    // a ≪ b: C11, C22 constant, C23 ∝ √g (1 + ν(ln(16/g) − 5)) grows with g.
    EXPECT_LT(kalker_coefficients(0.01, nu).c23, kalker_coefficients(0.1, nu).c23);
    EXPECT_DOUBLE_EQ(kalker_coefficients(0.01, nu).c11, kalker_coefficients(0.1, nu).c11);
    // a ≫ b: all grow with a/b.
    const KalkerCoefficients lo = kalker_coefficients(10.0, nu), hi = kalker_coefficients(50.0, nu);
    EXPECT_LT(lo.c11, hi.c11);
    EXPECT_LT(lo.c22, hi.c22);
    EXPECT_LT(lo.c23, hi.c23);
  }
}

TEST(KalkerCoefficients, NearlyContinuousAtTheAsymptoticSwitch) {
  // The table row g = 0.1 and the asymptotic expansions agree to a few per cent (Kalker's own
  // accuracy); the largest gap is C23 at ν = 0.5 for a ≪ b (0.687 against 0.731).
  for (double nu : {0.0, 0.1, 0.25, 0.4, 0.5}) {
    for (bool upper : {true, false}) {
      const double below = upper ? 0.1009 : 1.0 / 0.1009;
      const double above = upper ? 0.1011 : 1.0 / 0.1011;
      const auto a = as_array(kalker_coefficients(below, nu));
      const auto b = as_array(kalker_coefficients(above, nu));
      for (std::size_t m = 0; m < 3; ++m)
        EXPECT_NEAR(a[m], b[m], 0.07 * b[m]) << "nu " << nu << " upper " << upper << " col " << m;
    }
  }
}

TEST(KalkerCoefficients, SymmetricAtACircle) {
  const KalkerCoefficients c = kalker_coefficients(1.0, 0.28);
  EXPECT_NEAR(kalker_coefficients(1.0 - 1e-12, 0.28).c11, c.c11, 1e-9);
  EXPECT_NEAR(kalker_coefficients(1.0 + 1e-12, 0.28).c11, c.c11, 1e-9);
}

TEST(KalkerCoefficients, RejectsInadmissibleInput) {
  EXPECT_THROW(kalker_coefficients(0.0, 0.25), ProblemError);
  EXPECT_THROW(kalker_coefficients(-1.0, 0.25), ProblemError);
  EXPECT_THROW(kalker_coefficients(std::nan(""), 0.25), ProblemError);
  EXPECT_THROW(kalker_coefficients(1.0, 0.6), ProblemError);
  EXPECT_THROW(kalker_coefficients(1.0, -0.1), ProblemError);
}

}  // namespace
}  // namespace rollcontact::simplified
