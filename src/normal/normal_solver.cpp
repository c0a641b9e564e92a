#include "normal/normal_solver.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>

namespace rollcontact::normal {

namespace {

constexpr double excluded_threshold = 1e29;  // h ≥ this: element outside the planform

bool is_excluded(double h) {
  return h >= excluded_threshold;
}

double rms(const std::vector<double>& v) {
  double s = 0.0;
  for (double x : v) s += x * x;
  return std::sqrt(s / static_cast<double>(std::max<std::size_t>(v.size(), 1)));
}

}  // namespace

std::vector<double> initial_pressure(const Grid& grid, const std::vector<double>& h,
                                     NormalLoad load, double value, double poisson,
                                     double modulus) {
  const std::size_t n = grid.size();
  std::vector<double> p(n, 0.0);
  double h_min = std::numeric_limits<double>::infinity();
  for (double v : h)
    if (!is_excluded(v)) h_min = std::min(h_min, v);
  if (!std::isfinite(h_min)) return p;

  // Area of {h − h_min < t} [mm²].
  auto area_below = [&](double t) {
    std::size_t count = 0;
    for (double v : h)
      if (!is_excluded(v) && v - h_min < t) ++count;
    return static_cast<double>(count) * grid.element_area();
  };
  // Force of a 3-D contact with approach `pen` over `area`: FN/G = pen·√area / (0.75√π(1−ν)).
  auto force_estimate = [&](double pen) {
    return modulus * pen * std::sqrt(area_below(pen)) /
           (0.75 * std::sqrt(std::numbers::pi) * (1.0 - poisson));
  };

  double pen_est = 0.0;
  double force = 0.0;
  if (load == NormalLoad::Approach) {
    pen_est = value - h_min;
    if (pen_est <= 0.0) return p;
    force = force_estimate(pen_est);
  } else {
    force = value;
    if (force <= 0.0) return p;
    // Bisection on the approach measured from h_min; the bracket grows until it holds FN.
    double lo = 0.0, hi = 1e-6;
    for (int k = 0; k < 200 && force_estimate(hi) < force; ++k) hi *= 2.0;
    for (int k = 0; k < 60; ++k) {
      const double mid = 0.5 * (lo + hi);
      (force_estimate(mid) < force ? lo : hi) = mid;
    }
    pen_est = hi;
  }

  const double width = 0.6 * pen_est;
  double sum = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    if (is_excluded(h[i])) continue;
    const double t = 1.0 - (h[i] - h_min) / width;
    if (t > 0.0) {
      p[i] = std::sqrt(t);
      sum += p[i];
    }
  }
  if (sum <= 0.0) {  // a grid too coarse to resolve the estimate: load the lowest element
    const auto it = std::min_element(h.begin(), h.end());
    p[static_cast<std::size_t>(it - h.begin())] = 1.0;
    sum = 1.0;
  }
  const double scale = force / (sum * grid.element_area());
  for (double& v : p) v *= scale;
  return p;
}

NormalSolver::NormalSolver(const Grid& grid, elastic::LinearOperator& a,
                           const elastic::Kernel& kernel, Preconditioner& m,
                           const elastic::Interaction* interaction)
    : grid_(grid), a_(a), kernel_(kernel), m_(m), interaction_(interaction) {}

void NormalSolver::apply_sparse_correction(const std::vector<int>& changed,
                                           const std::vector<double>& delta,
                                           std::vector<double>& u) {
  // u_I += Σ_k K(I − J_k)·δ_k, row by row of u with all columns inside: the row of u stays in L1
  // while the kernel rows stream past it, instead of a pass over all of u per column. Each u_I
  // still receives the terms in the order of `changed`, so the sums are unchanged.
  const int mx = grid_.mx, my = grid_.my;
  const std::size_t kx = static_cast<std::size_t>(2 * mx - 1);
  // Column k reads kernel row iy − jy from offset −jx: kernel + first[k] + kx·iy.
  first_.resize(changed.size());
  for (std::size_t k = 0; k < changed.size(); ++k) {
    const int jx = changed[k] % mx, jy = changed[k] / mx;
    first_[k] = kernel_.data().data() + static_cast<std::size_t>(mx - 1 - jx) +
                kx * static_cast<std::size_t>(my - 1 - jy);
  }
  for (int iy = 0; iy < my; ++iy) {
    const std::size_t row_start = static_cast<std::size_t>(mx) * static_cast<std::size_t>(iy);
    double* row = u.data() + row_start;
    const std::size_t shift = kx * static_cast<std::size_t>(iy);
    for (std::size_t k = 0; k < changed.size(); ++k) {
      const double* krow = first_[k] + shift;
      const double dp = delta[k];
      if (interaction_ == nullptr) {
        for (int ix = 0; ix < mx; ++ix) row[ix] += krow[ix] * dp;
      } else {
        const auto j = static_cast<std::size_t>(changed[k]);
        for (int ix = 0; ix < mx; ++ix)
          row[ix] += interaction_->f(row_start + static_cast<std::size_t>(ix), j) * krow[ix] * dp;
      }
    }
  }
}

namespace {

/// The free set F (loaded elements and unloaded ones that penetrate) and the residual r = −gap
/// on F, zero elsewhere; with prescribed force r has zero mean on F (the force constraint).
/// Returns |F|; `set_changed` tells whether F differs from `in_contact` before the call.
std::size_t free_set_residual(const std::vector<double>& h, const std::vector<double>& p,
                              const std::vector<double>& u, double pen, bool force_given,
                              std::vector<double>& r, std::vector<char>& in_contact,
                              bool& set_changed) {
  const std::size_t n = h.size();
  std::size_t nfree = 0;
  double r_mean = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double gap = h[i] + u[i] - pen;
    const char free = p[i] > 0.0 || (gap < 0.0 && !is_excluded(h[i]));
    set_changed |= free != in_contact[i];
    in_contact[i] = free;
    if (free) {
      ++nfree;
      r[i] = -gap;
      r_mean += r[i];
    } else {
      r[i] = 0.0;
    }
  }
  if (force_given && nfree) {
    r_mean /= static_cast<double>(nfree);
    for (std::size_t i = 0; i < n; ++i)
      if (in_contact[i]) r[i] -= r_mean;
  }
  return nfree;
}

}  // namespace

bool NormalSolver::start(const std::vector<double>& h, NormalLoad load, double value,
                         const std::vector<double>* initial, const std::vector<double>* initial_un,
                         double poisson, double modulus, NormalResult& res) {
  const std::size_t n = grid_.size();
  const bool force_given = load == NormalLoad::Force;
  const double target_sum = force_given ? value / grid_.element_area() : 0.0;
  res.pn = initial ? *initial : initial_pressure(grid_, h, load, value, poisson, modulus);
  std::vector<double>& p = res.pn;
  // A·p given with the pressure holds while the clipping below changes nothing.
  bool known_un = initial != nullptr && initial_un != nullptr && initial_un->size() == n &&
                  initial->size() == n && interaction_ == nullptr;
  for (std::size_t i = 0; i < n; ++i)
    if (is_excluded(h[i]) || p[i] < 0.0) {
      known_un = known_un && p[i] == 0.0;
      p[i] = 0.0;
    }
  res.un.assign(n, 0.0);

  bool any = std::any_of(p.begin(), p.end(), [](double v) { return v > 0.0; });
  if (!any) {
    // No contact according to the estimate. With prescribed approach that is the answer when no
    // element penetrates; with prescribed force put the load on the lowest element and iterate.
    const auto it = std::min_element(h.begin(), h.end());
    if (force_given && it != h.end() && !is_excluded(*it)) {
      p[static_cast<std::size_t>(it - h.begin())] = target_sum;
      any = true;
      known_un = false;
    } else if (!force_given && (it == h.end() || *it - value >= 0.0)) {
      res.pen = value;
      res.converged = true;
      return false;
    }
  }
  double scale = 1.0;
  if (force_given) {
    double s = 0.0;
    for (double v : p) s += v;
    scale = target_sum / s;
    for (double& v : p) v *= scale;
  }
  if (known_un && any) {
    for (std::size_t i = 0; i < n; ++i) res.un[i] = scale * (*initial_un)[i];
    return true;
  }
  a_.apply(p.data(), res.un.data());
  ++res.products;
  return true;
}

void NormalSolver::finish(const std::vector<double>& h, bool force_given, double value,
                          const NormalSettings& settings, NormalResult& res) {
  const std::size_t n = grid_.size();
  std::vector<double>& p = res.pn;
  std::vector<double>& u = res.un;
  // Final consistent displacement, approach, force and contact count.
  a_.apply(p.data(), u.data());
  ++res.products;
  double fsum = 0.0, gap_sum = 0.0;
  int ncon = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (p[i] > 0.0) {
      ++ncon;
      fsum += p[i];
      gap_sum += h[i] + u[i];
    }
  }
  res.contact_elements = ncon;
  res.fn = fsum * grid_.element_area();
  res.pen = force_given ? (ncon ? gap_sum / ncon : 0.0) : value;
  // Independent check of the contact conditions, so that a wrong answer can never be reported as
  // converged: gap ≈ 0 where loaded, no penetration elsewhere, finite values. The tolerance is
  // generous (the CG stop is on the pressure change, not on the gap) but far below any error that
  // would show in the printed results.
  if (res.converged) {
    double scale = 0.0, worst = 0.0;
    bool finite = true;
    for (std::size_t i = 0; i < n; ++i) {
      if (is_excluded(h[i])) continue;
      finite = finite && std::isfinite(p[i]) && std::isfinite(u[i]);
      const double gap = h[i] + u[i] - res.pen;
      scale = std::max(scale, std::abs(u[i]));
      worst = std::max(worst, p[i] > 0.0 ? std::abs(gap) : std::max(0.0, -gap));
    }
    const double tolerance = std::max(100.0 * settings.eps, 1e-10) * std::max(scale, 1e-300);
    if (!finite || worst > tolerance) {
      res.converged = false;
      res.message = fmt::format(
          "NormCG stopped after {} iterations but the contact conditions are violated by {:.3e} mm "
          "(tolerance {:.3e} mm)",
          res.iterations, worst, tolerance);
    }
  }
  if (!res.converged && res.message.empty())
    res.message = fmt::format(
        "NormCG did not converge in {} iterations (relative change {:.3e} > EPS {:.3e})",
        res.iterations, res.residual, settings.eps);
}

NormalResult NormalSolver::solve(const std::vector<double>& h, NormalLoad load, double value,
                                 const NormalSettings& settings, const std::vector<double>* initial,
                                 double poisson, double modulus,
                                 const std::vector<double>* initial_un) {
  const std::size_t n = grid_.size();
  const bool force_given = load == NormalLoad::Force;
  NormalResult res;
  if (!start(h, load, value, initial, initial_un, poisson, modulus, res)) return res;
  std::vector<double>& p = res.pn;
  std::vector<double>& u = res.un;
  const double target_sum = force_given ? value / grid_.element_area() : 0.0;

  auto rescale_to_force = [&]() {
    double s = 0.0;
    for (double v : p) s += v;
    if (s > 0.0) {
      const double f = target_sum / s;
      for (double& v : p) v *= f;
      for (double& v : u) v *= f;
    }
  };

  std::vector<double> r(n, 0.0), z(n, 0.0), d(n, 0.0), q(n, 0.0);
  std::vector<char> in_contact(n, 0);
  std::vector<int> changed;
  std::vector<double> delta;
  changed.reserve(64);
  delta.reserve(64);
  // Above this many changed elements one FFT product is cheaper than the sparse correction.
  // Measured on the wheel/rail benchmark (bench/normal_problem): a column of A costs about
  // 1/110 of a product from 71×81 to 575×647 (one memory-bound multiply-add per element against
  // a padded FFT pair), so the break-even lies near 100–120 columns; 6·log2(n) gives 75 … 111.
  const std::size_t sparse_limit = std::max<std::size_t>(
      4, static_cast<std::size_t>(6.0 * std::log2(static_cast<double>(n) + 2.0)));

  bool restart = true;
  double rz_old = 1.0;
  double pen = force_given ? 0.0 : value;

  // The iteration is a projected, preconditioned CG for the bound-constrained quadratic program
  // min ½pᵀAp + pᵀ(h − PEN), p ≥ 0, whose gradient is the gap. The free set F holds the loaded
  // elements and the unloaded ones that penetrate (negative gradient); CG runs on F and restarts
  // whenever F changes. New elements thus enter with the line-searched step α·z rather than a
  // local guess, which keeps large active-set changes stable.
  const auto loop_start = std::chrono::steady_clock::now();
  for (int it = 1; it <= settings.max_iterations; ++it) {
    // Gap (gradient) and free set. With prescribed force the approach is the mean of h + u over
    // the loaded elements (the multiplier of the force constraint).
    if (force_given) {
      std::size_t nload = 0;
      double gap_sum = 0.0;
      for (std::size_t i = 0; i < n; ++i)
        if (p[i] > 0.0) {
          ++nload;
          gap_sum += h[i] + u[i];
        }
      if (nload) pen = gap_sum / static_cast<double>(nload);
    }
    bool set_changed = false;
    const std::size_t nfree =
        free_set_residual(h, p, u, pen, force_given, r, in_contact, set_changed);

    // z = M·r is used on the free set only (masked in the update of d). As r vanishes outside
    // it, r·z summed over the whole grid equals the masked sum term by term (the other terms are
    // ±0), so the preconditioner returns it from its last pass; likewise d·A·d below.
    double rz = m_.apply_dot(r.data(), z.data());
    double z_mean = 0.0;
    if (force_given) {
      for (std::size_t i = 0; i < n; ++i)
        if (in_contact[i]) z_mean += z[i];
      z_mean /= static_cast<double>(std::max<std::size_t>(nfree, 1));
      rz = 0.0;
      for (std::size_t i = 0; i < n; ++i)
        if (in_contact[i]) rz += r[i] * (z[i] - z_mean);
    }
    restart = restart || set_changed;
    const double beta = restart || rz_old == 0.0 ? 0.0 : rz / rz_old;
    rz_old = rz;
    restart = false;
    for (std::size_t i = 0; i < n; ++i) d[i] = in_contact[i] ? (z[i] - z_mean) + beta * d[i] : 0.0;

    const double dq = a_.apply_dot(d.data(), q.data());
    ++res.products;
    res.iterations = it;
    if (!(dq > 0.0)) {
      // Zero residual (exact solution) or a breakdown: either way no further progress.
      if (rz == 0.0) {
        res.converged = true;
      } else {
        res.message = "NormCG: breakdown (non-positive curvature d·A·d)";
      }
      break;
    }
    const double alpha = rz / dq;

    // Step and truncation of negative pressures (projection onto p ≥ 0).
    changed.clear();
    delta.clear();
    double step_sq = 0.0;
    double p_sq = 0.0;  // Σ p² of the new pressures (rms(p) without another pass)
    for (std::size_t i = 0; i < n; ++i) {
      u[i] += alpha * q[i];
      if (!in_contact[i]) continue;
      const double trial = p[i] + alpha * d[i];
      if (trial < 0.0) {
        changed.push_back(static_cast<int>(i));
        delta.push_back(-trial);
        step_sq += p[i] * p[i];
        p[i] = 0.0;
      } else {
        step_sq += alpha * alpha * d[i] * d[i];
        p[i] = trial;
        p_sq += trial * trial;
      }
    }
    if (!changed.empty()) {
      restart = true;
      if (changed.size() <= sparse_limit)
        apply_sparse_correction(changed, delta, u);
      else {
        a_.apply(p.data(), u.data());
        ++res.products;
      }
    }
    if (force_given) rescale_to_force();

    if (set_changed || !changed.empty()) ++res.set_changes;
    // Outside the free set p = 0, so p_sq is Σ p² term by term; the rescaling for prescribed
    // force changes p afterwards.
    const double p_rms =
        force_given ? rms(p) : std::sqrt(p_sq / static_cast<double>(std::max<std::size_t>(n, 1)));
    res.residual = p_rms > 0.0 ? std::sqrt(step_sq / static_cast<double>(n)) / p_rms : 0.0;
    if (!set_changed && changed.empty() && res.residual <= settings.eps) {
      res.converged = true;
      break;
    }
  }

  res.iteration_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - loop_start).count();

  finish(h, force_given, value, settings, res);
  return res;
}

}  // namespace rollcontact::normal
