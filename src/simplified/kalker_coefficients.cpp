// Kalker's creepage coefficients (spec/physics.md §11.1).

#include "simplified/kalker_coefficients.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include "rollcontact/errors.hpp"

namespace rollcontact::simplified {

namespace {

constexpr double pi = std::numbers::pi;

/// One row of Kalker's table: C11, C22, C23 at ν = 0, 0.25, 0.5.
struct Row {
  std::array<double, 3> c11, c22, c23;
};

// Rows 0–9: a/b = 0.1 … 1.0; rows 10–18: a/b = 1/0.9 … 1/0.1. The entry C23(a/b = 0.8,
// ν = 0.25) is 1.25: a widely copied version of the table has a typo there.
constexpr std::array<Row, 19> table{{
    {{2.51, 3.31, 4.85}, {2.51, 2.52, 2.53}, {0.334, 0.473, 0.731}},
    {{2.59, 3.37, 4.81}, {2.59, 2.63, 2.66}, {0.483, 0.603, 0.809}},
    {{2.68, 3.44, 4.80}, {2.68, 2.75, 2.81}, {0.607, 0.715, 0.889}},
    {{2.78, 3.53, 4.82}, {2.78, 2.88, 2.98}, {0.720, 0.823, 0.977}},
    {{2.88, 3.62, 4.83}, {2.88, 3.01, 3.14}, {0.827, 0.929, 1.07}},
    {{2.98, 3.72, 4.91}, {2.98, 3.14, 3.31}, {0.930, 1.03, 1.18}},
    {{3.09, 3.81, 4.97}, {3.09, 3.28, 3.48}, {1.03, 1.14, 1.29}},
    {{3.19, 3.91, 5.05}, {3.19, 3.41, 3.65}, {1.13, 1.25, 1.40}},
    {{3.29, 4.01, 5.12}, {3.29, 3.54, 3.82}, {1.23, 1.36, 1.51}},
    {{3.40, 4.12, 5.20}, {3.40, 3.67, 3.98}, {1.33, 1.47, 1.63}},
    {{3.51, 4.22, 5.30}, {3.51, 3.81, 4.16}, {1.44, 1.59, 1.77}},
    {{3.65, 4.36, 5.42}, {3.65, 3.99, 4.39}, {1.58, 1.75, 1.94}},
    {{3.82, 4.54, 5.58}, {3.82, 4.21, 4.67}, {1.76, 1.95, 2.18}},
    {{4.06, 4.78, 5.80}, {4.06, 4.50, 5.04}, {2.01, 2.23, 2.50}},
    {{4.37, 5.10, 6.11}, {4.37, 4.90, 5.56}, {2.35, 2.62, 2.96}},
    {{4.84, 5.57, 6.57}, {4.84, 5.48, 6.31}, {2.88, 3.24, 3.70}},
    {{5.57, 6.34, 7.34}, {5.57, 6.40, 7.51}, {3.79, 4.32, 5.01}},
    {{6.96, 7.78, 8.82}, {6.96, 8.14, 9.79}, {5.72, 6.63, 7.89}},
    {{10.7, 11.7, 12.9}, {10.7, 12.8, 16.0}, {12.2, 14.6, 18.0}},
}};

/// Table row holding g = k/10 (k = 1 … 10) in the upper (a ≤ b) or lower (a > b) half.
const Row& row_for(int k, bool upper) {
  return upper ? table[static_cast<std::size_t>(k - 1)] : table[static_cast<std::size_t>(19 - k)];
}

/// 1/C is closer to quadratic in ν than C itself: Lagrange interpolation of the reciprocals
/// through ν = 0, 1/4, 1/2.
double interpolate_nu(const std::array<double, 3>& c, double nu) {
  const double l0 = 8.0 * (nu - 0.25) * (nu - 0.5);
  const double l1 = -16.0 * nu * (nu - 0.5);
  const double l2 = 8.0 * nu * (nu - 0.25);
  return 1.0 / (l0 / c[0] + l1 / c[1] + l2 / c[2]);
}

/// Asymptotic coefficients of a very slender ellipse (g < 0.101), Kalker's expansions.
KalkerCoefficients asymptotic(double g, double nu, bool upper) {
  KalkerCoefficients c;
  if (upper) {  // a ≪ b: the strip (2-D) limit in x
    c.c11 = pi * pi / (4.0 * (1.0 - nu));
    c.c22 = pi * pi / 4.0;
    c.c23 = pi * std::sqrt(g) * (1.0 + nu * (std::log(16.0 / g) - 5.0)) / (3.0 * (1.0 - nu));
    return c;
  }
  const double lam = std::log(16.0 / (g * g));
  const double c3 = 3.0 - std::log(4.0);
  c.c11 = 2.0 * pi * (1.0 + c3 / (lam - 2.0 * nu)) / ((lam - 2.0 * nu) * g);
  const double d22 = (1.0 - nu) * lam + 2.0 * nu;
  c.c22 = 2.0 * pi * (1.0 + (1.0 - nu) * c3 / d22) / (g * d22);
  c.c23 = 2.0 * pi / (3.0 * std::pow(g, 1.5) * ((1.0 - nu) * lam - 2.0 + 4.0 * nu));
  return c;
}

}  // namespace

KalkerCoefficients kalker_table_entry(int row, int nu_column) {
  if (row < 0 || row >= 19 || nu_column < 0 || nu_column > 2)
    throw ProblemError("Kalker table entry out of range");
  const Row& r = table[static_cast<std::size_t>(row)];
  const auto j = static_cast<std::size_t>(nu_column);
  return {r.c11[j], r.c22[j], r.c23[j]};
}

KalkerCoefficients kalker_coefficients(double a_over_b, double nu) {
  if (!(a_over_b > 0.0) || !std::isfinite(a_over_b))
    throw ProblemError("Kalker coefficients: a/b must be positive and finite (got " +
                       std::to_string(a_over_b) + ")");
  if (!(nu >= 0.0 && nu <= 0.5))
    throw ProblemError("Kalker coefficients: Poisson ratio must lie in [0, 0.5] (got " +
                       std::to_string(nu) + ")");
  const bool upper = a_over_b <= 1.0;
  const double g = upper ? a_over_b : 1.0 / a_over_b;
  if (g < 0.101) return asymptotic(g, nu, upper);

  // Linear in g between the rows g = k/10 and (k+1)/10; the 0.005 keeps g = 1 in row k = 9.
  const int k = static_cast<int>(std::floor(10.0 * g - 0.005));
  const double f = 10.0 * g - k;
  const Row& lo = row_for(k, upper);
  const Row& hi = row_for(k + 1, upper);
  std::array<double, 3> c11{}, c22{}, c23{};
  for (std::size_t j = 0; j < 3; ++j) {
    c11[j] = f * hi.c11[j] + (1.0 - f) * lo.c11[j];
    c22[j] = f * hi.c22[j] + (1.0 - f) * lo.c22[j];
    c23[j] = f * hi.c23[j] + (1.0 - f) * lo.c23[j];
  }
  return {interpolate_nu(c11, nu), interpolate_nu(c22, nu), interpolate_nu(c23, nu)};
}

}  // namespace rollcontact::simplified
