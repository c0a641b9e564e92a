// ConvexGS: Gauss–Seidel with exact element solutions and dense slip updates.

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/anderson.hpp"
#include "physics/friction_disk.hpp"
#include "tangential/element_problem.hpp"
#include "tangential/tangential_system.hpp"

namespace rollcontact::tangential {

void TangentialOperator::apply(const std::vector<double>& px, const std::vector<double>& py,
                               std::vector<double>& ux, std::vector<double>& uy) const {
  const double* in[2] = {px.data(), py.data()};
  double* out[2] = {ux.data(), uy.data()};
  product->apply(in, out);
}

void finalise(const TangentialSystem& sys, TangentialResult& res, const std::vector<double>* sx,
              const std::vector<double>* sy) {
  const std::size_t n = sys.grid.size();
  // S = b + A·p, by a product unless the caller carries it.
  const bool carried = sx != nullptr && sy != nullptr;
  std::vector<double> ux, uy;
  if (!carried) {
    ux.resize(n);
    uy.resize(n);
    sys.a.apply(res.px, res.py, ux, uy);
  }
  res.sx.assign(n, 0.0);
  res.sy.assign(n, 0.0);
  res.state.assign(n, ElementState::Exterior);
  for (std::size_t i = 0; i < n; ++i) {
    if (!sys.contact[i]) {
      res.px[i] = res.py[i] = 0.0;
      continue;
    }
    const bool slip = physics::slips(std::hypot(res.px[i], res.py[i]), sys.bound[i]);
    res.state[i] = slip ? ElementState::Slip : ElementState::Adhesion;
    if (slip) {
      res.sx[i] = carried ? (*sx)[i] : sys.bx[i] + ux[i];
      res.sy[i] = carried ? (*sy)[i] : sys.by[i] + uy[i];
    }
  }
}

namespace {

/// The elements in contact in sweep order and the Gauss–Seidel sweep over them. After each
/// element the slip of the elements within `band` rows is updated at once; the remaining
/// (weaker, longer-range) coupling is refreshed by one FFT product at the start of each sweep.
/// band ≥ my − 1 is the exact (dense) Gauss–Seidel sweep.
class GaussSeidelSweeper {
 public:
  GaussSeidelSweeper(const TangentialSystem& sys, int band)
      : sys_(sys), grid_(sys.grid), band_(band) {
    for (std::size_t i = 0; i < grid_.size(); ++i)
      if (sys.contact[i]) elements_.push_back(static_cast<int>(i));
    // Rolling: sweep each row from the trailing edge (χ = 0: low ix) towards the leading edge,
    // so that the strong coupling of an element to its downstream neighbours (the
    // steady-rolling operator C − C′ has a slowly decaying one-sided tail) is treated
    // implicitly. The opposite order diverges on carter2d; see docs/decisions.md.
    const bool backwards = std::cos(sys.chi) < 0.0;
    const int mx = grid_.mx;
    std::stable_sort(elements_.begin(), elements_.end(), [&](int a, int b) {
      const int ay = a / mx, by = b / mx;
      if (ay != by) return ay < by;
      return backwards ? a > b : a < b;
    });
    row_start_.assign(static_cast<std::size_t>(grid_.my) + 1, 0);
    for (int e : elements_) ++row_start_[static_cast<std::size_t>(e / mx) + 1];
    for (std::size_t r = 1; r < row_start_.size(); ++r) row_start_[r] += row_start_[r - 1];
    sx_.resize(grid_.size());
    sy_.resize(grid_.size());
  }

  /// One sweep starting from (px, py) (modified in place).
  void sweep(std::vector<double>& px, std::vector<double>& py, const TangentialSettings& set) {
    sys_.a.apply(px, py, sx_, sy_);
    for (std::size_t i = 0; i < grid_.size(); ++i) {
      sx_[i] += sys_.bx[i];
      sy_[i] += sys_.by[i];
    }
    const elastic::Kernel &kxx = *sys_.a.xx, &kxy = *sys_.a.xy, &kyx = *sys_.a.yx,
                          &kyy = *sys_.a.yy;
    const double d[4] = {kxx.at(0, 0), kxy.at(0, 0), kyx.at(0, 0), kyy.at(0, 0)};
    const elastic::Interaction* inter = sys_.a.interaction;
    const int mx = grid_.mx;
    for (int i : elements_) {
      const std::size_t ui = static_cast<std::size_t>(i);
      const double pxo = px[ui], pyo = py[ui];
      const double cx = sx_[ui] - (d[0] * pxo + d[1] * pyo);
      const double cy = sy_[ui] - (d[2] * pxo + d[3] * pyo);
      const ElementSolution e = solve_element(cx, cy, d, sys_.bound[ui]);
      const double omega = e.slip ? set.omega_s : set.omega_h;
      double pxn = pxo + omega * (e.px - pxo), pyn = pyo + omega * (e.py - pyo);
      physics::project_onto_disk(pxn, pyn, sys_.bound[ui]);
      const double dpx = pxn - pxo, dpy = pyn - pyo;
      px[ui] = pxn;
      py[ui] = pyn;
      if (dpx == 0.0 && dpy == 0.0) continue;
      const int ix = i % mx, iy = i / mx;
      const int row_lo = std::max(0, iy - band_), row_hi = std::min(grid_.my - 1, iy + band_);
      const std::size_t first = row_start_[static_cast<std::size_t>(row_lo)];
      const std::size_t last = row_start_[static_cast<std::size_t>(row_hi) + 1];
      for (std::size_t k = first; k < last; ++k) {
        const int j = elements_[k];
        const int dix = j % mx - ix, diy = j / mx - iy;
        const std::size_t uj = static_cast<std::size_t>(j);
        const double f = inter == nullptr ? 1.0 : inter->f(uj, ui);
        sx_[uj] += f * (kxx.at(dix, diy) * dpx + kxy.at(dix, diy) * dpy);
        sy_[uj] += f * (kyx.at(dix, diy) * dpx + kyy.at(dix, diy) * dpy);
      }
    }
  }

 private:
  const TangentialSystem& sys_;
  const Grid& grid_;
  int band_;
  std::vector<int> elements_;
  std::vector<std::size_t> row_start_;
  std::vector<double> sx_, sy_;
};

/// Up to this many contact elements the sweeps are exact (dense, O(N²) per sweep).
constexpr std::size_t dense_limit = 4000;

int sweep_band(const TangentialSystem& sys) {
  std::size_t ncon = 0;
  for (char c : sys.contact) ncon += c ? 1 : 0;
  return ncon <= dense_limit ? sys.grid.my : 2;
}

}  // namespace

TangentialResult solve_convex_gs(const TangentialSystem& sys, const TangentialSettings& settings,
                                 const std::vector<double>* px0, const std::vector<double>* py0) {
  const std::size_t n = sys.grid.size();
  TangentialResult res;
  res.px = px0 ? *px0 : std::vector<double>(n, 0.0);
  res.py = py0 ? *py0 : std::vector<double>(n, 0.0);
  GaussSeidelSweeper sweeper(sys, sweep_band(sys));
  iterate_with_acceleration(
      sys, settings, res,
      [&](std::vector<double>& px, std::vector<double>& py) { sweeper.sweep(px, py, settings); },
      sys.a.steady ? "SteadyGS" : "ConvexGS");
  finalise(sys, res);
  return res;
}

void iterate_with_acceleration(const TangentialSystem& sys, const TangentialSettings& settings,
                               TangentialResult& res, const SweepFunction& sweep,
                               const char* name) {
  const std::size_t n = sys.grid.size();
  std::vector<int> elements;
  for (std::size_t i = 0; i < n; ++i) {
    if (sys.contact[i]) {
      elements.push_back(static_cast<int>(i));
    } else {
      res.px[i] = res.py[i] = 0.0;
    }
  }
  auto project = [&](std::vector<double>& px, std::vector<double>& py) {
    for (int i : elements) {
      const std::size_t u = static_cast<std::size_t>(i);
      physics::project_onto_disk(px[u], py[u], sys.bound[u]);
    }
  };
  const std::size_t m = 2 * elements.size();
  auto pack = [&](const std::vector<double>& px, const std::vector<double>& py) {
    std::vector<double> v(m);
    for (std::size_t k = 0; k < elements.size(); ++k) {
      v[2 * k] = px[static_cast<std::size_t>(elements[k])];
      v[2 * k + 1] = py[static_cast<std::size_t>(elements[k])];
    }
    return v;
  };
  auto unpack = [&](const std::vector<double>& v, std::vector<double>& px,
                    std::vector<double>& py) {
    for (std::size_t k = 0; k < elements.size(); ++k) {
      px[static_cast<std::size_t>(elements[k])] = v[2 * k];
      py[static_cast<std::size_t>(elements[k])] = v[2 * k + 1];
    }
  };
  project(res.px, res.py);
  core::AndersonAccelerator anderson(m, settings.anderson_depth);
  std::vector<double> x = pack(res.px, res.py);
  double best = std::numeric_limits<double>::infinity();
  for (int it = 1; it <= settings.max_iterations; ++it) {
    unpack(x, res.px, res.py);
    sweep(res.px, res.py);
    const std::vector<double> g = pack(res.px, res.py);
    double change_sq = 0.0, norm_sq = 0.0;
    for (std::size_t k = 0; k < m; ++k) {
      change_sq += (g[k] - x[k]) * (g[k] - x[k]);
      norm_sq += g[k] * g[k];
    }
    res.iterations = it;
    res.residual = norm_sq > 0.0 ? std::sqrt(change_sq / norm_sq) : 0.0;
    if (res.residual <= settings.eps || m == 0) {
      res.converged = true;
      return;  // res holds G(x)
    }
    if (settings.anderson_depth <= 0) {
      x = g;
      continue;
    }
    // Safeguard: a growing fixed-point residual restarts the acceleration from the plain map.
    if (change_sq > 4.0 * best) {
      anderson.reset();
      x = g;
      best = change_sq;
      continue;
    }
    best = std::min(best, change_sq);
    anderson.step(x, g);
    unpack(x, res.px, res.py);
    project(res.px, res.py);
    x = pack(res.px, res.py);
  }
  res.message = fmt::format("{} did not converge in {} iterations (relative change {:.3e})", name,
                            res.iterations, res.residual);
}

}  // namespace rollcontact::tangential
