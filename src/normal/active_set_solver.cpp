#include "normal/active_set_solver.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/krylov.hpp"

namespace rollcontact::normal {

namespace {

constexpr double kExcluded = 1e29;  // h ≥ this: element outside the planform

/// GMRES tolerance on the set equations: far below what decides the set (signs of p and of the
/// gap) and below the printed digits, yet reachable in double precision for any grid.
constexpr double kKrylovTolerance = 1e-11;
constexpr int kKrylovRestart = 80;

}  // namespace

bool ActiveSetNormalSolver::solve_on_set(const std::vector<double>& h, const std::vector<int>& set,
                                         bool force_given, double value, std::vector<double>& p,
                                         double& pen, NormalResult& res) {
  const std::size_t n = grid_.size(), m = set.size();
  std::vector<double> full(n, 0.0), out(n, 0.0);
  const core::LinearMap a_cc = [&](const std::vector<double>& x, std::vector<double>& y) {
    std::fill(full.begin(), full.end(), 0.0);
    for (std::size_t k = 0; k < m; ++k) full[static_cast<std::size_t>(set[k])] = x[k];
    a_.apply(full.data(), out.data());
    y.resize(m);
    for (std::size_t k = 0; k < m; ++k) y[k] = out[static_cast<std::size_t>(set[k])];
  };
  const core::LinearMap identity = [](const std::vector<double>& x, std::vector<double>& y) {
    y = x;
  };
  const int max_it = 20 * static_cast<int>(m) + 100;
  auto solve = [&](const std::vector<double>& b, std::vector<double>& x) {
    const core::KrylovResult k =
        core::solve_gmres(a_cc, identity, b, x, kKrylovTolerance, max_it, kKrylovRestart);
    res.iterations += k.iterations;
    res.products += k.iterations;
    res.residual = std::max(res.residual, k.relative_residual);
    return k.converged;
  };
  // Approach given: A_CC·p = PEN − h_C at once. Force given: p = r + PEN·q with A_CC·r = −h_C,
  // A_CC·q = 1, and the PEN that meets δxδy·Σp = FN.
  std::vector<double> b(m), r, q;
  const double rhs_pen = force_given ? 0.0 : value;
  for (std::size_t k = 0; k < m; ++k) b[k] = rhs_pen - h[static_cast<std::size_t>(set[k])];
  bool ok = solve(b, r);
  pen = value;
  if (force_given) {
    ok = solve(std::vector<double>(m, 1.0), q) && ok;
    double sum_r = 0.0, sum_q = 0.0;
    for (std::size_t k = 0; k < m; ++k) {
      sum_r += r[k];
      sum_q += q[k];
    }
    if (!(sum_q > 0.0)) return false;
    pen = (value / grid_.element_area() - sum_r) / sum_q;
  }
  std::fill(p.begin(), p.end(), 0.0);
  for (std::size_t k = 0; k < m; ++k)
    p[static_cast<std::size_t>(set[k])] = r[k] + (q.empty() ? 0.0 : pen * q[k]);
  return ok;
}

NormalResult ActiveSetNormalSolver::solve(const std::vector<double>& h, NormalLoad load,
                                          double value, const NormalSettings& settings,
                                          const std::vector<double>* initial, double poisson,
                                          double modulus) {
  const std::size_t n = grid_.size();
  const bool force_given = load == NormalLoad::Force;
  const auto t0 = std::chrono::steady_clock::now();
  NormalResult res;
  res.pn = initial ? *initial : initial_pressure(grid_, h, load, value, poisson, modulus);
  std::vector<char> in_set(n, 0);
  for (std::size_t i = 0; i < n; ++i) in_set[i] = h[i] < kExcluded && res.pn[i] > 0.0;
  if (std::none_of(in_set.begin(), in_set.end(), [](char c) { return c != 0; })) {
    // No contact in the estimate: the lowest element, unless nothing penetrates at all.
    const auto it = std::min_element(h.begin(), h.end());
    if (it == h.end() || *it >= kExcluded || (!force_given && *it - value >= 0.0)) {
      res.pn.assign(n, 0.0);
      res.un.assign(n, 0.0);
      res.pen = force_given ? 0.0 : value;
      res.converged = !force_given;
      if (!res.converged) res.message = "no element can carry the normal force";
      return res;
    }
    in_set[static_cast<std::size_t>(it - h.begin())] = 1;
  }

  std::vector<double>& p = res.pn;
  std::vector<double>& u = res.un;
  p.assign(n, 0.0);
  u.assign(n, 0.0);
  std::vector<int> set;
  for (int pass = 1; pass <= std::max(1, settings.max_iterations); ++pass) {
    res.set_changes = pass;
    set.clear();
    for (std::size_t i = 0; i < n; ++i)
      if (in_set[i]) set.push_back(static_cast<int>(i));
    if (set.empty() || !solve_on_set(h, set, force_given, value, p, res.pen, res)) {
      res.message =
          fmt::format("active-set normal solver: GMRES failed on a set of {} elements", set.size());
      break;
    }
    // Tension first: the elements with p < 0 leave the set.
    bool changed = false;
    for (int i : set)
      if (p[static_cast<std::size_t>(i)] < 0.0) {
        in_set[static_cast<std::size_t>(i)] = 0;
        changed = true;
      }
    if (changed) continue;
    // Then penetration: exterior elements with a negative gap enter.
    a_.apply(p.data(), u.data());
    ++res.products;
    for (std::size_t i = 0; i < n; ++i)
      if (!in_set[i] && h[i] < kExcluded && h[i] + u[i] - res.pen < 0.0) {
        in_set[i] = 1;
        changed = true;
      }
    if (!changed) {
      res.converged = true;
      break;
    }
  }
  if (!res.converged && res.message.empty())
    res.message = fmt::format("active-set normal solver: contact set not settled in {} passes",
                              res.set_changes);
  for (double& v : p) v = std::max(v, 0.0);
  a_.apply(p.data(), u.data());
  ++res.products;
  double fsum = 0.0;
  for (std::size_t i = 0; i < n; ++i)
    if (p[i] > 0.0) {
      ++res.contact_elements;
      fsum += p[i];
    }
  res.fn = fsum * grid_.element_area();
  if (!force_given) res.pen = value;
  res.iteration_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return res;
}

}  // namespace rollcontact::normal
