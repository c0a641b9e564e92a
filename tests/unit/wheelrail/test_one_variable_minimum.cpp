// The one-variable minimisers of the contact searches (golden_section.hpp): golden sections and
// Brent's method find the minimum of a smooth function, of one with a kink and of one whose
// minimum lies at the bracket's end, to their tolerance; Brent's needs far fewer evaluations on
// the smooth one (the sliced wheel's deepest point: a circle near its lowest point).

#include <gtest/gtest.h>

#include <cmath>

#include "wheelrail/golden_section.hpp"

namespace rollcontact::wheelrail {
namespace {

TEST(OneVariableMinimum, BrentOnASmoothMinimumIsQuick) {
  // The depth of a 460 mm wheel near its lowest point, offset by 0.7 mrad.
  int calls = 0;
  const auto f = [&](double phi) {
    ++calls;
    return -460.0 * std::cos(phi - 7e-4);
  };
  double fx = 0.0;
  const double x = brent_minimum(f, -2e-3, 2e-3, 1e-7, 100, fx);
  EXPECT_NEAR(x, 7e-4, 1e-7);
  EXPECT_DOUBLE_EQ(fx, f(x));
  const int brent_calls = calls - 1;
  calls = 0;
  const GoldenBracket g = golden_section_minimum(f, -2e-3, 2e-3, 1e-7, 1000);
  EXPECT_NEAR(0.5 * (g.a + g.b), 7e-4, 1e-7);
  EXPECT_LE(brent_calls, 12);
  EXPECT_GE(calls, 20);
}

TEST(OneVariableMinimum, BrentOnAKinkAndAtTheEnd) {
  double fx = 0.0;
  EXPECT_NEAR(brent_minimum([](double x) { return std::abs(x - 0.3); }, 0.0, 1.0, 1e-8, 200, fx),
              0.3, 1e-7);
  EXPECT_NEAR(brent_minimum([](double x) { return x; }, 0.0, 1.0, 1e-8, 200, fx), 0.0, 1e-7);
}

}  // namespace
}  // namespace rollcontact::wheelrail
