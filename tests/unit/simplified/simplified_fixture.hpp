#pragma once
// Shared set-up of the simplified-theory tests: a Hertzian grid with the elliptic pressure and
// the rigid shift of steady rolling (δq = δx, χ = 0 or π, no spin-centre offset).

#include <cmath>
#include <numbers>
#include <numeric>
#include <vector>

#include "rollcontact/grid.hpp"
#include "rollcontact/solution.hpp"
#include "simplified/prescribed_pressure.hpp"
#include "simplified/simplified_solver.hpp"

namespace rollcontact::simplified::test {

struct Patch {
  Grid grid;
  HertzReport hertz;
  std::vector<double> pn;
  double fn = 0.0;  ///< prescribed force [N]
  double fn_discrete() const {
    return std::accumulate(pn.begin(), pn.end(), 0.0) * grid.element_area();
  }
};

/// Elliptic (Hertzian) pressure for force fn on an mx × my grid covering scale × the ellipse.
inline Patch elliptic_patch(double a, double b, double fn, int mx, int my, double scale = 1.05) {
  Patch p;
  p.grid.mx = mx;
  p.grid.my = my;
  p.grid.dx = 2.0 * scale * a / mx;
  p.grid.dy = 2.0 * scale * b / my;
  p.grid.xl = -scale * a;
  p.grid.yl = -scale * b;
  p.hertz.present = true;
  p.hertz.aa = a;
  p.hertz.bb = b;
  p.fn = fn;
  p.pn = prescribed_pressure(p.grid, p.hertz, PressureShape::Elliptic, fn);
  return p;
}

/// Rigid shift per step of steady rolling, δq = δx: W = δq(ξ − φy, η + φx), split in the parts
/// without and with spin.
inline RigidShiftParts steady_shift(const Grid& g, const Creepages& cr) {
  RigidShiftParts w;
  const std::size_t n = g.size();
  w.wx.assign(n, g.dx * cr.ksi);
  w.wy.assign(n, g.dx * cr.eta);
  w.spin_x.resize(n);
  w.spin_y.resize(n);
  for (int iy = 0; iy < g.my; ++iy)
    for (int ix = 0; ix < g.mx; ++ix) {
      w.spin_x[g.index(ix, iy)] = -g.dx * cr.phi * g.y_centre(iy);
      w.spin_y[g.index(ix, iy)] = g.dx * cr.phi * g.x_centre(ix);
    }
  return w;
}

inline double sum(const std::vector<double>& v, const Grid& g) {
  return std::accumulate(v.begin(), v.end(), 0.0) * g.element_area();
}

}  // namespace rollcontact::simplified::test
