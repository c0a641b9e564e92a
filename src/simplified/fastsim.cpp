// Modified Fastsim (spec/physics.md §11.3).

#include "simplified/fastsim.hpp"

#include <cmath>

namespace rollcontact::simplified {

namespace {

/// Solves one element given the displacement u′ of its particles one step earlier; returns the
/// element's displacement u.
struct ElementOutcome {
  double ux, uy;
};

ElementOutcome solve_element(const FastsimInput& in, std::size_t i, double upx, double upy,
                             SimplifiedFields& out) {
  const double bound = in.mu * in.pn[i];
  double ux = upx - in.wx[i], uy = upy - in.wy[i];  // adhesion: S = u − u′ + W = 0
  double px = ux / in.flex.l1, py = uy / in.flex.l2;
  const double norm = std::hypot(px, py);
  if (norm > bound) {
    const double f = bound / norm;
    px *= f;
    py *= f;
    ux = in.flex.l1 * px;
    uy = in.flex.l2 * py;
    out.sx[i] = ux - upx + in.wx[i];
    out.sy[i] = uy - upy + in.wy[i];
    out.state[i] = ElementState::Slip;
  } else {
    out.state[i] = ElementState::Adhesion;
  }
  out.px[i] = px;
  out.py[i] = py;
  out.ux[i] = ux;
  out.uy[i] = uy;
  return {ux, uy};
}

}  // namespace

SimplifiedFields fastsim(const FastsimInput& in) {
  const Grid& grid = in.grid;
  const std::size_t n = grid.size();
  SimplifiedFields out;
  out.px.assign(n, 0.0);
  out.py.assign(n, 0.0);
  out.ux.assign(n, 0.0);
  out.uy.assign(n, 0.0);
  out.sx.assign(n, 0.0);
  out.sy.assign(n, 0.0);
  out.state.assign(n, ElementState::Exterior);
  if (in.steady) {
    // Particles enter at the leading edge unloaded and move one element per step (δq = δx).
    const bool forward = std::cos(in.chi) >= 0.0;
    for (int iy = 0; iy < grid.my; ++iy) {
      double upx = 0.0, upy = 0.0;
      for (int k = 0; k < grid.mx; ++k) {
        const int ix = forward ? grid.mx - 1 - k : k;
        const std::size_t i = grid.index(ix, iy);
        if (!(in.pn[i] > 0.0)) {
          upx = upy = 0.0;
          continue;
        }
        const ElementOutcome e = solve_element(in, i, upx, upy, out);
        upx = e.ux;
        upy = e.uy;
      }
    }
    return out;
  }
  const bool has_prev = in.ux_prev.size() == n && in.uy_prev.size() == n;
  for (std::size_t i = 0; i < n; ++i) {
    if (!(in.pn[i] > 0.0)) continue;
    solve_element(in, i, has_prev ? in.ux_prev[i] : 0.0, has_prev ? in.uy_prev[i] : 0.0, out);
  }
  return out;
}

std::vector<double> upstream_field(const Grid& grid, std::span<const double> u, double chi,
                                   double dq) {
  std::vector<double> out(grid.size(), 0.0);
  if (u.size() != grid.size()) return out;
  // Position in element-centre index coordinates of the point δq upstream.
  const double sx = dq * std::cos(chi) / grid.dx, sy = dq * std::sin(chi) / grid.dy;
  auto value = [&](long ix, long iy) {
    if (ix < 0 || iy < 0 || ix >= grid.mx || iy >= grid.my) return 0.0;
    return u[grid.index(static_cast<int>(ix), static_cast<int>(iy))];
  };
  for (int iy = 0; iy < grid.my; ++iy) {
    for (int ix = 0; ix < grid.mx; ++ix) {
      const double fx = ix + sx, fy = iy + sy;
      const double x0 = std::floor(fx), y0 = std::floor(fy);
      const double tx = fx - x0, ty = fy - y0;
      const long jx = static_cast<long>(x0), jy = static_cast<long>(y0);
      // Points beyond the outer element centres lie outside the potential contact: 0 there.
      if (fx < -1e-9 || fy < -1e-9 || fx > grid.mx - 1 + 1e-9 || fy > grid.my - 1 + 1e-9) continue;
      out[grid.index(ix, iy)] =
          (1.0 - tx) * (1.0 - ty) * value(jx, jy) + tx * (1.0 - ty) * value(jx + 1, jy) +
          (1.0 - tx) * ty * value(jx, jy + 1) + tx * ty * value(jx + 1, jy + 1);
    }
  }
  return out;
}

}  // namespace rollcontact::simplified
