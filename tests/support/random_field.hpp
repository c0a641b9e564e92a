#pragma once
// Reproducible random test fields for the elastic-operator tests.

#include <cstddef>
#include <random>
#include <vector>

namespace rollcontact::test_support {

/// n values uniform in [−1, 1), from a Mersenne twister seeded with `seed`.
inline std::vector<double> random_field(std::size_t n, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> dist(-1.0, 1.0);
  std::vector<double> v(n);
  for (double& x : v) x = dist(gen);
  return v;
}

}  // namespace rollcontact::test_support
