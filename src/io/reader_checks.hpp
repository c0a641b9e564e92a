#pragma once
// Small pure checks shared by the case readers (.inp module 3 and TOML).

#include <algorithm>
#include <cmath>

#include "rollcontact/problem.hpp"

namespace rollcontact::io {

/// True when a and b differ by more than `rel` relative to their size.
inline bool differs(double a, double b, double rel) {
  return std::abs(a - b) > rel * std::max(std::abs(a), std::abs(b));
}

/// True when x is an integer multiple of h (within 1e-6 of one element).
inline bool is_multiple(double x, double h) {
  const double k = x / h;
  return std::abs(k - std::round(k)) <= 1e-6 * std::max(1.0, std::abs(k));
}

/// Kalker's material difference parameter K as the readers test it for the MAXOUT override
/// (0 for quasi-identical bodies).
inline double material_k(const Materials& m) {
  const double a = (1.0 - 2.0 * m.poiss1) / m.gg1 - (1.0 - 2.0 * m.poiss2) / m.gg2;
  const double b = (1.0 - m.poiss1) / m.gg1 + (1.0 - m.poiss2) / m.gg2;
  return 0.25 * a / b;
}

}  // namespace rollcontact::io
