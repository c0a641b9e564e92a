// Gauss–Legendre rules: see the header.

#include "core/gauss_legendre.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace rollcontact::core {

GaussRule gauss_legendre(int n) {
  if (n < 1) throw std::invalid_argument("gauss_legendre: at least one node");
  GaussRule r;
  r.u.resize(static_cast<std::size_t>(n));
  r.w.resize(r.u.size());
  for (int i = 0; i < n; ++i) {
    double x = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5));
    double dp = 1.0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = x;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (x * p1 - p0) / (x * x - 1.0);
      const double dx = p1 / dp;
      x -= dx;
      if (std::abs(dx) < 1e-16) break;
    }
    // x runs from near +1 downwards, so u = (1 − x)/2 ascends.
    r.u[static_cast<std::size_t>(i)] = 0.5 * (1.0 - x);
    r.w[static_cast<std::size_t>(i)] = 1.0 / ((1.0 - x * x) * dp * dp);  // (2/((1−x²)P′²))/2
  }
  return r;
}

}  // namespace rollcontact::core
