// Preconditioned block-Jacobi iteration with Anderson acceleration (see tangential_system.hpp).

#include <cmath>

#include "tangential/element_problem.hpp"
#include "tangential/tangential_system.hpp"

namespace rollcontact::tangential {

namespace {

class PreconditionedJacobi {
 public:
  explicit PreconditionedJacobi(const TangentialSystem& sys) : sys_(sys) {
    const std::size_t n = sys.grid.size();
    for (auto* v : {&sx_, &sy_, &rx_, &ry_, &zx_, &zy_, &qx_, &qy_}) v->assign(n, 0.0);
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
    if (!sys_.a.symmetric) cumulative_sum_from_leading_edge();
    sys_.a.preconditioner->apply(rx_.data(), ry_.data(), zx_.data(), zy_.data());
    for (std::size_t i = 0; i < n; ++i)
      if (!adhesion_[i]) zx_[i] = zy_[i] = 0.0;
    sys_.a.apply(zx_, zy_, qx_, qy_);
    // Symmetric A: the step length that minimises the energy along z (the restricted
    // preconditioned step overshoots when slip elements are held fixed). Steady rolling has no
    // energy; the full step is taken there.
    double theta = 1.0;
    if (sys_.a.symmetric) {
      double rz = 0.0, zq = 0.0;
      for (std::size_t i = 0; i < n; ++i) {
        if (!adhesion_[i]) continue;
        rz += rx_[i] * zx_[i] + ry_[i] * zy_[i];
        zq += zx_[i] * qx_[i] + zy_[i] * qy_[i];
      }
      theta = zq > 0.0 ? rz / zq : 0.0;
    }
    for (std::size_t i = 0; i < n; ++i) {
      px[i] += theta * zx_[i];
      py[i] += theta * zy_[i];
      qx_[i] *= theta;
      qy_[i] *= theta;
    }
    // Adhesion elements keep the globally corrected traction (a local Jacobi correction would
    // overshoot: the diagonal of A is small next to its row sums), projected onto the bound if
    // they exceed it; slip elements solve their local problem against the updated slip.
    for (std::size_t i = 0; i < n; ++i) {
      if (!sys_.contact[i]) continue;
      if (adhesion_[i]) {
        const double pabs = std::hypot(px[i], py[i]);
        if (pabs > sys_.bound[i] && pabs > 0.0) {
          px[i] *= sys_.bound[i] / pabs;
          py[i] *= sys_.bound[i] / pabs;
        }
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
  /// r ← (I − T)⁻¹ r: sums along each row from the leading edge (χ = 0: high ix) downwards.
  void cumulative_sum_from_leading_edge() {
    const Grid& g = sys_.grid;
    const bool forward = std::cos(sys_.chi) < 0.0;  // χ = π: leading edge at ix = 0
    for (int iy = 0; iy < g.my; ++iy) {
      double ax = 0.0, ay = 0.0;
      for (int k = 0; k < g.mx; ++k) {
        const int ix = forward ? k : g.mx - 1 - k;
        const std::size_t i = g.index(ix, iy);
        ax += rx_[i];
        ay += ry_[i];
        rx_[i] = ax;
        ry_[i] = ay;
      }
    }
  }

  const TangentialSystem& sys_;
  double d_[4];
  std::vector<double> sx_, sy_, rx_, ry_, zx_, zy_, qx_, qy_;
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
