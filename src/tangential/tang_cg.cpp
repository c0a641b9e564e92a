// TangCG: projected, preconditioned nonlinear conjugate gradients for the frictional tangential
// problem with a symmetric operator (shifts, transient rolling).
//
// For fixed pressure the problem is the convex program
//     min ½ pᵀA p + bᵀp   subject to |p_I| ≤ g_I per element,
// whose gradient is the slip S = b + A p; its optimality conditions are exactly Coulomb's law
// (adhesion: S = 0 inside the disk; slip: S = −λ p/g on its rim). Following the idea of Zhao,
// Vollebregt & Oosterlee (2015, J. Comput. Phys. 288), CG iterates on the adhesion elements (two
// unknowns) and on the slip elements along the tangent of their disk (one unknown, with the
// constraint's curvature λ/g added to the Hessian), projects onto the disks after each step and
// restarts the conjugate directions when the adhesion/slip division changes. Products with A by
// FFT, preconditioning by the block-circulant approximate inverse.

#include <algorithm>
#include <cmath>

#include "tangential/tangential_system.hpp"

namespace rollcontact::tangential {

TangentialResult solve_tang_cg(const TangentialSystem& sys, const TangentialSettings& settings,
                               const std::vector<double>* px0, const std::vector<double>* py0) {
  if (sys.a.preconditioner == nullptr || !sys.a.symmetric)
    return solve_convex_gs(sys, settings, px0, py0);
  const std::size_t n = sys.grid.size();
  TangentialResult res;
  std::vector<double>& px = res.px;
  std::vector<double>& py = res.py;
  px = px0 ? *px0 : std::vector<double>(n, 0.0);
  py = py0 ? *py0 : std::vector<double>(n, 0.0);

  enum : char { outside = 0, adhesion = 1, slip = 2 };
  std::vector<char> kind(n, outside), kind_old(n, outside);
  auto project = [&](std::size_t i) {
    const double pabs = std::hypot(px[i], py[i]);
    if (pabs > sys.bound[i]) {
      const double f = pabs > 0.0 ? sys.bound[i] / pabs : 0.0;
      px[i] *= f;
      py[i] *= f;
    }
  };
  for (std::size_t i = 0; i < n; ++i) {
    if (sys.contact[i])
      project(i);
    else
      px[i] = py[i] = 0.0;
  }

  std::vector<double> sx(n), sy(n), rx(n), ry(n), zx(n), zy(n), dx(n, 0.0), dy(n, 0.0), qx(n),
      qy(n), tx(n, 0.0), ty(n, 0.0), curv(n, 0.0);
  double rz_old = 0.0;
  bool restart = true;
  for (int it = 1; it <= settings.max_iterations; ++it) {
    sys.a.apply(px, py, sx, sy);
    // Classify and form the projected residual r = −∇ (tangential part on the rim).
    bool changed = false;
    for (std::size_t i = 0; i < n; ++i) {
      rx[i] = ry[i] = 0.0;
      curv[i] = 0.0;
      if (!sys.contact[i]) continue;
      sx[i] += sys.bx[i];
      sy[i] += sys.by[i];
      const double g = sys.bound[i];
      const double pabs = std::hypot(px[i], py[i]);
      const bool on_rim = g <= 0.0 || pabs >= g * (1.0 - 1e-12);
      const double sp = sx[i] * px[i] + sy[i] * py[i];
      kind[i] = on_rim && (g <= 0.0 || sp < 0.0) ? slip : adhesion;
      changed |= kind[i] != kind_old[i];
      if (kind[i] == adhesion) {
        rx[i] = -sx[i];
        ry[i] = -sy[i];
      } else if (g > 0.0) {
        tx[i] = -py[i] / pabs;
        ty[i] = px[i] / pabs;
        const double st = sx[i] * tx[i] + sy[i] * ty[i];
        rx[i] = -st * tx[i];
        ry[i] = -st * ty[i];
        curv[i] = -sp / (pabs * g);  // λ/g with S = −λ p/g on the rim
      }
    }
    kind_old = kind;
    sys.a.preconditioner->apply(rx.data(), ry.data(), zx.data(), zy.data());
    double rz = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      if (kind[i] == adhesion) {
        // z as computed
      } else if (kind[i] == slip && sys.bound[i] > 0.0) {
        const double zt = zx[i] * tx[i] + zy[i] * ty[i];
        zx[i] = zt * tx[i];
        zy[i] = zt * ty[i];
      } else {
        zx[i] = zy[i] = 0.0;
      }
      rz += rx[i] * zx[i] + ry[i] * zy[i];
    }
    restart = restart || changed;
    const double beta = restart || rz_old <= 0.0 ? 0.0 : rz / rz_old;
    restart = false;
    rz_old = rz;
    for (std::size_t i = 0; i < n; ++i) {
      if (kind[i] == outside || (kind[i] == slip && sys.bound[i] <= 0.0)) {
        dx[i] = dy[i] = 0.0;
        continue;
      }
      dx[i] = zx[i] + beta * dx[i];
      dy[i] = zy[i] + beta * dy[i];
      if (kind[i] == slip) {  // keep the direction in the current tangent
        const double dt = dx[i] * tx[i] + dy[i] * ty[i];
        dx[i] = dt * tx[i];
        dy[i] = dt * ty[i];
      }
    }
    sys.a.apply(dx, dy, qx, qy);
    double dq = 0.0, p_sq = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      if (kind[i] == outside) continue;
      dq += dx[i] * (qx[i] + curv[i] * dx[i]) + dy[i] * (qy[i] + curv[i] * dy[i]);
    }
    res.iterations = it;
    if (!(dq > 0.0) || rz <= 0.0) {
      // Nothing left to do (zero residual) or no descent direction: converged when the
      // residual vanished, otherwise stop with a message.
      res.converged = rz <= 0.0 || rz < 1e-300;
      if (!res.converged) res.message = "TangCG: breakdown (no descent direction)";
      break;
    }
    const double alpha = rz / dq;
    double change_sq = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      if (kind[i] == outside) continue;
      const double ox = px[i], oy = py[i];
      px[i] += alpha * dx[i];
      py[i] += alpha * dy[i];
      project(i);
      if (kind[i] == adhesion && std::hypot(px[i], py[i]) >= sys.bound[i] * (1.0 - 1e-12))
        restart = true;  // an element reached the bound
      change_sq += (px[i] - ox) * (px[i] - ox) + (py[i] - oy) * (py[i] - oy);
      p_sq += px[i] * px[i] + py[i] * py[i];
    }
    res.residual = p_sq > 0.0 ? std::sqrt(change_sq / p_sq) : 0.0;
    if (!changed && res.residual <= settings.eps) {
      res.converged = true;
      break;
    }
  }
  {
    // The CG stop (a small step) does not bound the error of the adhesion/slip division well, and
    // CG can stall when a few elements keep changing between adhesion and slip. The accelerated
    // Gauss–Seidel iteration started from the CG result verifies the solution — one sweep when
    // it is accurate — and settles the remaining elements otherwise.
    TangentialResult polished = solve_convex_gs(sys, settings, &res.px, &res.py);
    polished.iterations += res.iterations;
    return polished;
  }
}

}  // namespace rollcontact::tangential
