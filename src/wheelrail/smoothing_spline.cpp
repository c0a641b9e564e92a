#include "wheelrail/smoothing_spline.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace rollcontact::wheelrail {

SplineNodes fit_smoothing_spline(const std::vector<double>& s, const std::vector<double>& f,
                                 const std::vector<double>& weights, double lambda) {
  const std::size_t n = s.size();
  SplineNodes out;
  out.value = f;
  out.second.assign(n, 0.0);
  if (n < 3) return out;
  const std::size_t m = n - 2;  // interior second derivatives γ_1..γ_{n-2}
  std::vector<double> h(n - 1);
  for (std::size_t i = 0; i + 1 < n; ++i) h[i] = s[i + 1] - s[i];
  auto w_inv = [&](std::size_t i) { return weights.empty() ? 1.0 : 1.0 / weights[i]; };
  // Q (n × m): column j (interior node j+1) has 1/h_j, −1/h_j − 1/h_{j+1}, 1/h_{j+1} in rows
  // j, j+1, j+2. R (m × m) tridiagonal: (h_j + h_{j+1})/3 on the diagonal, h_{j+1}/6 beside it.
  auto q = [&](std::size_t j, int k) {  // entry of column j in row j + k, k = 0, 1, 2
    if (k == 0) return 1.0 / h[j];
    if (k == 1) return -1.0 / h[j] - 1.0 / h[j + 1];
    return 1.0 / h[j + 1];
  };
  // A = R + λ Qᵀ W⁻¹ Q (pentadiagonal), rhs = Qᵀ f.
  std::vector<double> diag(m), off1(m > 1 ? m - 1 : 0), off2(m > 2 ? m - 2 : 0), rhs(m);
  for (std::size_t j = 0; j < m; ++j) {
    diag[j] = (h[j] + h[j + 1]) / 3.0;
    if (j + 1 < m) off1[j] = h[j + 1] / 6.0;
    rhs[j] = q(j, 0) * f[j] + q(j, 1) * f[j + 1] + q(j, 2) * f[j + 2];
    if (lambda > 0.0) {
      for (int k = 0; k < 3; ++k) diag[j] += lambda * q(j, k) * q(j, k) * w_inv(j + k);
      // Column j and column j+1 share rows j+1 and j+2; columns j and j+2 share row j+2.
      if (j + 1 < m)
        off1[j] +=
            lambda * (q(j, 1) * q(j + 1, 0) * w_inv(j + 1) + q(j, 2) * q(j + 1, 1) * w_inv(j + 2));
      if (j + 2 < m) off2[j] += lambda * q(j, 2) * q(j + 2, 0) * w_inv(j + 2);
    }
  }
  // Banded LDLᵀ (bandwidth 2): L(i, i-1) = l1[i], L(i, i-2) = l2[i].
  std::vector<double> dd(m), l1(m, 0.0), l2(m, 0.0);
  for (std::size_t i = 0; i < m; ++i) {
    if (i >= 2) l2[i] = off2[i - 2] / dd[i - 2];
    if (i >= 1) {
      double a = off1[i - 1];
      if (i >= 2) a -= l2[i] * dd[i - 2] * l1[i - 1];
      l1[i] = a / dd[i - 1];
    }
    double a = diag[i];
    if (i >= 1) a -= l1[i] * l1[i] * dd[i - 1];
    if (i >= 2) a -= l2[i] * l2[i] * dd[i - 2];
    dd[i] = a;
  }
  std::vector<double> g = rhs;
  for (std::size_t i = 0; i < m; ++i) {
    if (i >= 1) g[i] -= l1[i] * g[i - 1];
    if (i >= 2) g[i] -= l2[i] * g[i - 2];
  }
  for (std::size_t i = 0; i < m; ++i) g[i] /= dd[i];
  for (std::size_t i = m; i-- > 0;) {
    if (i + 1 < m) g[i] -= l1[i + 1] * g[i + 1];
    if (i + 2 < m) g[i] -= l2[i + 2] * g[i + 2];
  }
  for (std::size_t j = 0; j < m; ++j) out.second[j + 1] = g[j];
  if (lambda > 0.0) {
    // g(s_i) = f_i − λ W⁻¹ Q γ.
    for (std::size_t j = 0; j < m; ++j)
      for (int k = 0; k < 3; ++k) out.value[j + k] -= lambda * w_inv(j + k) * q(j, k) * g[j];
  }
  return out;
}

std::vector<double> smooth_third_order(const std::vector<double>& s, const std::vector<double>& f,
                                       const std::vector<double>& weights, double lambda) {
  const std::size_t n = s.size();
  if (n < 4 || !(lambda > 0.0)) return f;
  // D³ row j: coefficients of g_{j+k}, k = 0..3, in 3!·g[s_j, …, s_{j+3}] (the third
  // derivative of the cubic through the four nodes).
  std::vector<std::array<double, 4>> d(n - 3);
  for (std::size_t j = 0; j + 3 < n; ++j)
    for (std::size_t k = 0; k < 4; ++k) {
      double denom = 1.0;
      for (std::size_t m = 0; m < 4; ++m)
        if (m != k) denom *= s[j + k] - s[j + m];
      d[j][k] = 6.0 / denom;
    }
  // A = W + λ D³ᵀ H D³: symmetric, bandwidth 3, stored as band[i][b] = A(i, i + b).
  std::vector<std::array<double, 4>> band(n, {0.0, 0.0, 0.0, 0.0});
  std::vector<double> g(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double w = weights.empty() ? 1.0 : weights[i];
    band[i][0] = w;
    g[i] = w * f[i];
  }
  for (std::size_t j = 0; j + 3 < n; ++j) {
    const double hbar = (s[j + 3] - s[j]) / 3.0;
    for (std::size_t k = 0; k < 4; ++k)
      for (std::size_t m = k; m < 4; ++m) band[j + k][m - k] += lambda * hbar * d[j][k] * d[j][m];
  }
  // Banded Cholesky A = L·Lᵀ with L(i, i − b) = l[i][b].
  std::vector<std::array<double, 4>> l(n, {0.0, 0.0, 0.0, 0.0});
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t b = std::min<std::size_t>(3, i); b >= 1; --b) {
      const std::size_t c = i - b;  // the column
      double v = band[c][b];
      for (std::size_t m = 1; b + m <= 3 && m <= c; ++m) v -= l[i][b + m] * l[c][m];
      l[i][b] = v / l[c][0];
    }
    double v = band[i][0];
    for (std::size_t b = 1; b <= 3 && b <= i; ++b) v -= l[i][b] * l[i][b];
    l[i][0] = std::sqrt(v);
  }
  for (std::size_t i = 0; i < n; ++i) {  // L y = rhs
    for (std::size_t b = 1; b <= 3 && b <= i; ++b) g[i] -= l[i][b] * g[i - b];
    g[i] /= l[i][0];
  }
  for (std::size_t i = n; i-- > 0;) {  // Lᵀ g = y
    for (std::size_t b = 1; b <= 3 && i + b < n; ++b) g[i] -= l[i + b][b] * g[i + b];
    g[i] /= l[i][0];
  }
  return g;
}

}  // namespace rollcontact::wheelrail
