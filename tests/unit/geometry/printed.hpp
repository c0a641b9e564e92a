#pragma once
// Helper for comparing with numbers printed in CONTACT's reference outputs: the tolerance is half
// a unit in the last printed digit, derived from the printed text itself ("0.8464E-03" → 5e-8,
// "1849." → 0.5), so every assertion is exactly as strict as the reference allows.

#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <string>

namespace rollcontact::geometry::test {

/// Half a unit in the last place of a Fortran-formatted number such as "-1.267", "0.2406E-02".
inline double printed_half_unit(const std::string& text) {
  const auto epos = text.find_first_of("Ee");
  const std::string mantissa = text.substr(0, epos);
  const int exponent = epos == std::string::npos ? 0 : std::atoi(text.c_str() + epos + 1);
  const auto dot = mantissa.find('.');
  const int decimals = dot == std::string::npos ? 0 : static_cast<int>(mantissa.size() - dot - 1);
  return 0.5 * std::pow(10.0, exponent - decimals);
}

inline ::testing::AssertionResult matches_printed(double actual, const std::string& text) {
  const double printed = std::strtod(text.c_str(), nullptr);
  // 1e-9 relative slack only absorbs the binary representation of the printed decimal.
  const double tol = printed_half_unit(text) * (1.0 + 1e-9);
  if (std::abs(actual - printed) <= tol) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "value " << actual << " does not print as " << text
                                       << " (allowed deviation " << tol << ")";
}

}  // namespace rollcontact::geometry::test

#define EXPECT_PRINTED(actual, text) \
  EXPECT_TRUE(::rollcontact::geometry::test::matches_printed((actual), (text)))
