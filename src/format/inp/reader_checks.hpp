#pragma once
// Small pure checks shared by the case readers (.inp module 3 and TOML).

#include <algorithm>
#include <cmath>

#include "format/inp/case_record.hpp"
#include "rollcontact/model/bodies.hpp"

namespace rollcontact::format {

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
/// (0 for quasi-identical bodies); same definition as the solver's.
inline double material_k(const Materials& m) {
  return model::material_difference_k(m.poiss1, m.poiss2, m.gg1, m.gg2);
}

}  // namespace rollcontact::format
