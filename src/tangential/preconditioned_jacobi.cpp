// Preconditioned block-Jacobi iteration with Anderson acceleration (see tangential_system.hpp).

#include <algorithm>
#include <cmath>

#include "physics/friction_disk.hpp"
#include "tangential/element_problem.hpp"
#include "tangential/tangential_system.hpp"

namespace rollcontact::tangential {

namespace {

class PreconditionedJacobi {
 public:
  explicit PreconditionedJacobi(const TangentialSystem& sys) : sys_(sys) {
    const std::size_t n = sys.grid.size();
    for (auto* v : {&sx_, &sy_, &rx_, &ry_, &zx_, &zy_, &qx_, &qy_, &dx_, &dy_, &ax_, &ay_})
      v->assign(n, 0.0);
    adhesion_.assign(n, 0);
    d_[0] = sys.a.xx->at(0, 0);
    d_[1] = sys.a.xy->at(0, 0);
    d_[2] = sys.a.yx->at(0, 0);
    d_[3] = sys.a.yy->at(0, 0);
  }

  void sweep(std::vector<double>& px, std::vector<double>& py) {
    const std::size_t n = sys_.grid.size();
    sys_.a.apply(px, py, sx_, sy_);
    // Adhesion elements (by their local solution) get the global step.
    for (std::size_t i = 0; i < n; ++i) {
      rx_[i] = ry_[i] = 0.0;
      adhesion_[i] = 0;
      if (!sys_.contact[i]) continue;
      sx_[i] += sys_.bx[i];
      sy_[i] += sys_.by[i];
      const double cx = sx_[i] - (d_[0] * px[i] + d_[1] * py[i]);
      const double cy = sy_[i] - (d_[2] * px[i] + d_[3] * py[i]);
      if (!solve_element(cx, cy, d_, sys_.bound[i]).slip) {
        adhesion_[i] = 1;
        rx_[i] = -sx_[i];
        ry_[i] = -sy_[i];
      }
    }
    if (!sys_.a.steady)
      adhesion_cg_steps(px, py);
    else
      steady_step(px, py);
    // Adhesion elements keep the globally corrected traction (a local Jacobi correction would
    // overshoot: the diagonal of A is small next to its row sums), projected onto the bound if
    // they exceed it; slip elements solve their local problem against the updated slip.
    for (std::size_t i = 0; i < n; ++i) {
      if (!sys_.contact[i]) continue;
      if (adhesion_[i]) {
        physics::project_onto_disk(px[i], py[i], sys_.bound[i]);
        continue;
      }
      const double cx = sx_[i] + qx_[i] - (d_[0] * px[i] + d_[1] * py[i]);
      const double cy = sy_[i] + qy_[i] - (d_[2] * px[i] + d_[3] * py[i]);
      const ElementSolution e = solve_element(cx, cy, d_, sys_.bound[i]);
      px[i] = e.px;
      py[i] = e.py;
    }
  }

 private:
  /// Symmetric A: a few preconditioned CG steps for A_HH δ = r_H on the adhesion set H with the
  /// slip elements held fixed (a single preconditioned step overshoots or stalls on large grids:
  /// the restricted inverse is only approximated by M). Accumulates A·δ in (qx_, qy_).
  void adhesion_cg_steps(std::vector<double>& px, std::vector<double>& py) {
    const std::size_t n = sys_.grid.size();
    std::fill(qx_.begin(), qx_.end(), 0.0);
    std::fill(qy_.begin(), qy_.end(), 0.0);
    double rz_old = 0.0;
    for (int step = 0; step < inner_steps; ++step) {
      sys_.a.preconditioner->apply(rx_.data(), ry_.data(), zx_.data(), zy_.data());
      double rz = 0.0;
      for (std::size_t i = 0; i < n; ++i) {
        if (!adhesion_[i]) zx_[i] = zy_[i] = 0.0;
        rz += rx_[i] * zx_[i] + ry_[i] * zy_[i];
      }
      if (!(rz > 0.0)) break;
      const double beta = step == 0 ? 0.0 : rz / rz_old;
      rz_old = rz;
      for (std::size_t i = 0; i < n; ++i) {
        dx_[i] = zx_[i] + beta * dx_[i];
        dy_[i] = zy_[i] + beta * dy_[i];
      }
      sys_.a.apply(dx_, dy_, ax_, ay_);
      double dq = 0.0;
      for (std::size_t i = 0; i < n; ++i)
        if (adhesion_[i]) dq += dx_[i] * ax_[i] + dy_[i] * ay_[i];
      if (!(dq > 0.0)) break;
      const double alpha = rz / dq;
      for (std::size_t i = 0; i < n; ++i) {
        px[i] += alpha * dx_[i];
        py[i] += alpha * dy_[i];
        qx_[i] += alpha * ax_[i];
        qy_[i] += alpha * ay_[i];
        if (adhesion_[i]) {
          rx_[i] -= alpha * ax_[i];
          ry_[i] -= alpha * ay_[i];
        }
      }
    }
  }

  /// Steady rolling: one step with M = C⁻¹ (I − T)⁻¹ (no energy to minimise; full step).
  void steady_step(std::vector<double>& px, std::vector<double>& py) {
    const std::size_t n = sys_.grid.size();
    cumulative_sum_from_leading_edge(sys_.grid, sys_.chi, rx_, ry_);
    sys_.a.preconditioner->apply(rx_.data(), ry_.data(), zx_.data(), zy_.data());
    for (std::size_t i = 0; i < n; ++i)
      if (!adhesion_[i]) zx_[i] = zy_[i] = 0.0;
    sys_.a.apply(zx_, zy_, qx_, qy_);
    for (std::size_t i = 0; i < n; ++i) {
      px[i] += zx_[i];
      py[i] += zy_[i];
    }
  }

  const TangentialSystem& sys_;
  double d_[4];
  static constexpr int inner_steps = 2;
  std::vector<double> sx_, sy_, rx_, ry_, zx_, zy_, qx_, qy_, dx_, dy_, ax_, ay_;
  std::vector<char> adhesion_;
};

}  // namespace

TangentialResult solve_preconditioned_jacobi(const TangentialSystem& sys,
                                             const TangentialSettings& settings,
                                             const std::vector<double>* px0,
                                             const std::vector<double>* py0) {
  if (sys.a.preconditioner == nullptr) return solve_convex_gs(sys, settings, px0, py0);
  const std::size_t n = sys.grid.size();
  TangentialResult res;
  res.px = px0 ? *px0 : std::vector<double>(n, 0.0);
  res.py = py0 ? *py0 : std::vector<double>(n, 0.0);
  PreconditionedJacobi jacobi(sys);
  iterate_with_acceleration(
      sys, settings, res,
      [&](std::vector<double>& px, std::vector<double>& py) { jacobi.sweep(px, py); },
      "preconditioned Jacobi");
  if (!res.converged) {
    // Rarely the division into adhesion and slip keeps changing between iterations; the
    // Gauss–Seidel iteration, started from the current tractions, settles it.
    TangentialResult polished = solve_convex_gs(sys, settings, &res.px, &res.py);
    polished.iterations += res.iterations;
    return polished;
  }
  finalise(sys, res);
  return res;
}

}  // namespace rollcontact::tangential
