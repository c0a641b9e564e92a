// Flexibilities, blending, slope reduction and the equivalent ellipse.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "simplified/flexibility.hpp"
#include "simplified_fixture.hpp"

namespace rollcontact::simplified {
namespace {

constexpr double pi = std::numbers::pi;

TEST(Flexibility, KalkerFlexibilitiesOfTheFastsimExample) {
  // fastsim.inp: a = 8, b = 4, G = 82000, ν = 0.28. Before blending L1 = 8a/(3C11G) etc.
  const Ellipse e{8.0, 4.0};
  const KalkerCoefficients c = kalker_coefficients(2.0, 0.28);
  const Flexibilities l = kalker_flexibilities(e, c, 82000.0);
  EXPECT_NEAR(l.l1, 64.0 / (3.0 * c.c11 * 82000.0), 1e-18);
  EXPECT_NEAR(l.l3, pi * 8.0 * std::sqrt(2.0) / (4.0 * c.c23 * 82000.0), 1e-18);
  // Blended with the creepages of fastsim.inp case 2 (printed FLX1..3 4.937, 5.152, 4.090e-5).
  const Flexibilities b =
      blend_flexibilities(l, e, c, 82000.0, 0.3, 82000.0, {0.0, -6.25e-4, 6.25e-4});
  EXPECT_NEAR(b.l1, 4.937e-5, 0.0005e-5);
  EXPECT_NEAR(b.l2, 5.152e-5, 0.0005e-5);
  EXPECT_NEAR(b.l3, 4.090e-5, 0.0005e-5);
}

TEST(Flexibility, BlendingWeightsAndLimits) {
  const Ellipse e{5.0, 5.0};
  const KalkerCoefficients c = kalker_coefficients(1.0, 0.28);
  const Flexibilities l = kalker_flexibilities(e, c, 82000.0);
  // No creepage: the three flexibilities stay.
  const Flexibilities zero = blend_flexibilities(l, e, c, 82000.0, 0.3, 1e5, {});
  EXPECT_NEAR(zero.l1, l.l1, 1e-9 * l.l1);
  EXPECT_NEAR(zero.l3, l.l3, 1e-9 * l.l3);
  // Far beyond three times the characteristic creepage all become L_c; pure η gives L_c = L2.
  const Flexibilities big = blend_flexibilities(l, e, c, 82000.0, 0.3, 1e5, {0.0, 0.5, 0.0});
  EXPECT_NEAR(big.l1, l.l2, 1e-12 * l.l2);
  EXPECT_NEAR(big.l3, l.l2, 1e-12 * l.l2);
}

TEST(Flexibility, SlopeReductionFactor) {
  const Ellipse e{5.0, 5.0};
  const double c11 = kalker_coefficients(1.0, 0.28).c11;
  // Original Fastsim.
  EXPECT_DOUBLE_EQ(
      slope_reduction_factor({1.0, 1.0, 0.7}, e, c11, 82000.0, 0.3, 1e5, {1e-3, 0.0, 0.0}), 1.0);
  // No creepage: k = k0; huge creepage: k → k0·α∞.
  const SlopeReduction s{0.8, 0.3, 2.0};
  EXPECT_DOUBLE_EQ(slope_reduction_factor(s, e, c11, 82000.0, 0.3, 1e5, {}), 0.8);
  EXPECT_NEAR(slope_reduction_factor(s, e, c11, 82000.0, 0.3, 1e5, {1e4, 0.0, 0.0}), 0.8 * 0.3,
              1e-4);
  // ε = GπabK0C11ν/(4μFN) with ν_tot = √(ξ² + ν_φ²).
  const double ksi = 1e-3;
  const double eps = 82000.0 * pi * 25.0 * 0.8 * c11 * ksi / (4.0 * 0.3 * 1e5);
  EXPECT_NEAR(slope_reduction_factor(s, e, c11, 82000.0, 0.3, 1e5, {ksi, 0.0, 0.0}),
              0.8 * (0.3 + 0.7 / (1.0 + 2.0 * eps)), 1e-14);
  // Spin counts through ν_φ = η + φa unless that is smaller than η.
  EXPECT_DOUBLE_EQ(slope_reduction_factor(s, e, c11, 82000.0, 0.3, 1e5, {0.0, 1e-3, -4e-4}),
                   slope_reduction_factor(s, e, c11, 82000.0, 0.3, 1e5, {0.0, 1e-3, 0.0}));
  EXPECT_DOUBLE_EQ(slope_reduction_factor(s, e, c11, 82000.0, 0.3, 1e5, {0.0, 1e-3, 4e-4}),
                   slope_reduction_factor(s, e, c11, 82000.0, 0.3, 1e5, {0.0, 3e-3, 0.0}));
}

TEST(Flexibility, EquivalentEllipseOfAHertzPatch) {
  const test::Patch p = test::elliptic_patch(8.0, 4.0, 8.2e4, 88, 88);
  const Ellipse e = equivalent_ellipse(p.grid, p.pn);
  EXPECT_NEAR(e.a / e.b, 2.0, 0.03);
  EXPECT_NEAR(pi * e.a * e.b, pi * 32.0, 0.02 * pi * 32.0);
  EXPECT_EQ(equivalent_ellipse(p.grid, std::vector<double>(p.grid.size(), 0.0)).a, 0.0);
}

}  // namespace
}  // namespace rollcontact::simplified
