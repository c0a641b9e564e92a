#pragma once
// Kalker's creepage coefficients C11, C22, C23 of the linear theory of rolling for an elliptic
// contact (spec/physics.md §11.1): Kalker's table for a/b = 0.1 … 10 and ν = 0, 0.25, 0.5,
// interpolated linearly in g = min(a/b, b/a) and quadratically in 1/C over ν; asymptotic
// formulas for very slender ellipses (g < 0.101).

namespace rollcontact::simplified {

/// Dimensionless creepage coefficients: F_x = −G c² C11 ξ, F_y = −G c² (C22 η + c C23 φ).
struct KalkerCoefficients {
  double c11 = 0.0, c22 = 0.0, c23 = 0.0;
};

/// C11, C22, C23 for semi-axis ratio a/b (a along the rolling direction x) and combined Poisson
/// ratio ν ∈ [0, 0.5]. Throws ProblemError for a/b not positive and finite or ν outside [0, 0.5].
KalkerCoefficients kalker_coefficients(double a_over_b, double nu);

/// Tabulated values (no interpolation in ν) at table row `row` (0: a/b = 0.1, …, 9: a/b = 1,
/// …, 18: a/b = 1/0.1) and column `nu_column` (0: ν = 0, 1: ν = 0.25, 2: ν = 0.5). For tests.
KalkerCoefficients kalker_table_entry(int row, int nu_column);

}  // namespace rollcontact::simplified
