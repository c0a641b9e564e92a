// Gauss–Legendre rules on [0, 1]: exact to degree 2n − 1, not beyond; symmetric; positive.

#include <gtest/gtest.h>

#include <cmath>

#include "core/gauss_legendre.hpp"

namespace rollcontact::core {
namespace {

/// Σ w_k u_k^d against ∫₀¹ u^d du = 1/(d + 1).
double moment_error(const GaussRule& r, int d) {
  double sum = 0.0;
  for (std::size_t k = 0; k < r.u.size(); ++k) sum += r.w[k] * std::pow(r.u[k], d);
  return sum - 1.0 / (d + 1);
}

TEST(GaussLegendre, ExactToDegreeTwoNMinusOneAndNotBeyond) {
  for (int n : {1, 2, 4, 6, 10, 16, 30}) {
    const GaussRule r = gauss_legendre(n);
    ASSERT_EQ(r.u.size(), static_cast<std::size_t>(n));
    for (int d = 0; d < 2 * n; ++d) EXPECT_NEAR(moment_error(r, d), 0.0, 1e-14) << n << " " << d;
    // Degree 2n: the rule misses ∫₀¹ u^{2n} by (n!)⁴/((2n+1)((2n)!)²) (resolvable up to n = 6).
    if (n <= 6) {
      const double f = std::tgamma(n + 1.0), f2 = std::tgamma(2.0 * n + 1.0);
      EXPECT_NEAR(-moment_error(r, 2 * n), f * f * f * f / ((2 * n + 1) * f2 * f2), 1e-13) << n;
    }
  }
}

TEST(GaussLegendre, NodesAscendSymmetricallyWithPositiveWeights) {
  const GaussRule r = gauss_legendre(7);
  for (std::size_t k = 0; k < r.u.size(); ++k) {
    EXPECT_GT(r.w[k], 0.0);
    EXPECT_NEAR(r.u[k] + r.u[r.u.size() - 1 - k], 1.0, 1e-15);
    EXPECT_NEAR(r.w[k], r.w[r.u.size() - 1 - k], 1e-15);
    if (k > 0) {
      EXPECT_GT(r.u[k], r.u[k - 1]);
    }
  }
  EXPECT_DOUBLE_EQ(gauss_legendre(1).u.front(), 0.5);
  EXPECT_THROW(gauss_legendre(0), std::invalid_argument);
}

}  // namespace
}  // namespace rollcontact::core
