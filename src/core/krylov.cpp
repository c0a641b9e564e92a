#include "core/krylov.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace rollcontact::core {

namespace {

double dot(const std::vector<double>& a, const std::vector<double>& b) {
  double s = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) s += a[k] * b[k];
  return s;
}

}  // namespace

KrylovResult solve_pcg(const LinearMap& a, const LinearMap& m, const std::vector<double>& b,
                       std::vector<double>& x, double rtol, int max_it,
                       const StepObserver& on_step) {
  const std::size_t n = b.size();
  KrylovResult res;
  x.assign(n, 0.0);
  std::vector<double> r = b, z(n), d(n), q(n);
  m(r, z);
  double rz = dot(r, z);
  const double rz0 = rz;
  if (!(rz0 > 0.0)) {
    res.converged = true;
    return res;
  }
  d = z;
  while (res.iterations < max_it) {
    a(d, q);
    ++res.iterations;
    const double dq = dot(d, q);
    if (!(dq > 0.0)) break;  // lost positive definiteness (rounding): keep what we have
    const double alpha = rz / dq;
    for (std::size_t k = 0; k < n; ++k) {
      x[k] += alpha * d[k];
      r[k] -= alpha * q[k];
    }
    if (on_step) on_step(alpha);
    m(r, z);
    const double rz_new = dot(r, z);
    res.relative_residual = std::sqrt(std::max(rz_new, 0.0) / rz0);
    if (res.relative_residual <= rtol) {
      res.converged = true;
      break;
    }
    const double beta = rz_new / rz;
    rz = rz_new;
    for (std::size_t k = 0; k < n; ++k) d[k] = z[k] + beta * d[k];
  }
  return res;
}

KrylovResult solve_gmres(const LinearMap& a, const LinearMap& m, const std::vector<double>& b,
                         std::vector<double>& x, double rtol, int max_it, int restart,
                         const GmresObserver* observer) {
  const std::size_t n = b.size();
  KrylovResult res;
  x.assign(n, 0.0);
  const double bnorm = std::sqrt(dot(b, b));
  if (!(bnorm > 0.0)) {
    res.converged = true;
    return res;
  }
  const std::size_t mr = static_cast<std::size_t>(restart);
  // The basis and the Hessenberg columns grow with the iteration: the Newton systems converge
  // in a few steps, and a basis of `restart` + 1 vectors allocated and cleared up front cost
  // more than the steps themselves (docs/benchmarks.md).
  std::vector<std::vector<double>> v(1, std::vector<double>(n));
  std::vector<std::vector<double>> h;  // h[j]: column j, rows 0..j+1
  std::vector<double> cs(mr), sn(mr), g(mr + 1), w(n), z(n), y(mr);
  std::vector<double> r = b;  // residual of the current x
  while (true) {
    double beta = std::sqrt(dot(r, r));
    res.relative_residual = beta / bnorm;
    if (res.relative_residual <= rtol) {
      res.converged = true;
      return res;
    }
    if (res.iterations >= max_it) return res;
    for (std::size_t k = 0; k < n; ++k) v[0][k] = r[k] / beta;
    std::fill(g.begin(), g.end(), 0.0);
    g[0] = beta;
    std::size_t j = 0;
    for (; j < mr && res.iterations < max_it; ++j) {
      m(v[j], z);
      a(z, w);
      ++res.iterations;
      if (observer != nullptr && observer->applied) observer->applied(j);
      if (h.size() <= j) h.emplace_back(j + 2, 0.0);
      std::vector<double>& hj = h[j];
      for (std::size_t i = 0; i <= j; ++i) {  // modified Gram–Schmidt
        hj[i] = dot(w, v[i]);
        for (std::size_t k = 0; k < n; ++k) w[k] -= hj[i] * v[i][k];
      }
      hj[j + 1] = std::sqrt(dot(w, w));
      if (v.size() <= j + 1) v.emplace_back(n);
      if (hj[j + 1] > 0.0)
        for (std::size_t k = 0; k < n; ++k) v[j + 1][k] = w[k] / hj[j + 1];
      else
        std::fill(v[j + 1].begin(), v[j + 1].end(), 0.0);
      for (std::size_t i = 0; i < j; ++i) {  // previous Givens rotations
        const double t = cs[i] * hj[i] + sn[i] * hj[i + 1];
        hj[i + 1] = -sn[i] * hj[i] + cs[i] * hj[i + 1];
        hj[i] = t;
      }
      const double den = std::hypot(hj[j], hj[j + 1]);
      cs[j] = den > 0.0 ? hj[j] / den : 1.0;
      sn[j] = den > 0.0 ? hj[j + 1] / den : 0.0;
      hj[j] = den;
      hj[j + 1] = 0.0;
      g[j + 1] = -sn[j] * g[j];
      g[j] = cs[j] * g[j];
      res.relative_residual = std::abs(g[j + 1]) / bnorm;
      if (res.relative_residual <= rtol || !(den > 0.0)) {
        ++j;
        break;
      }
    }
    // x += M⁻¹ V y with H y = g (upper triangular, j columns).
    for (std::size_t i = j; i-- > 0;) {
      double s = g[i];
      for (std::size_t l = i + 1; l < j; ++l) s -= h[l][i] * y[l];
      y[i] = h[i][i] != 0.0 ? s / h[i][i] : 0.0;
    }
    std::fill(w.begin(), w.end(), 0.0);
    for (std::size_t i = 0; i < j; ++i)
      for (std::size_t k = 0; k < n; ++k) w[k] += y[i] * v[i][k];
    m(w, z);
    for (std::size_t k = 0; k < n; ++k) x[k] += z[k];
    if (observer != nullptr && observer->combined) observer->combined(y, j);
    if (res.relative_residual <= rtol) {
      res.converged = true;
      return res;
    }
    if (res.iterations >= max_it) return res;
    // Restart: the true residual (one more product).
    a(x, w);
    for (std::size_t k = 0; k < n; ++k) r[k] = b[k] - w[k];
  }
}

}  // namespace rollcontact::core
