// Modified Fastsim (spec/physics.md §11.3).

#include "simplified/fastsim.hpp"

#include <algorithm>
#include <cmath>

namespace rollcontact::simplified {

namespace {

/// μ of an element after memory: θ·μ′ + (1 − θ)·μ(s) with θ = d_c/(d_c + δt·max(s, s₀)).
double relaxed_mu(const FastsimVelocityFriction& v, double mu_prime, double speed) {
  const double dc = v.memory_distance_mm;
  const double theta =
      dc <= 1e-9 ? 0.0 : dc / (dc + v.dt_s * std::max(speed, v.memory_floor_speed_mm_s));
  return theta * mu_prime + (1.0 - theta) * v.law->coefficient_at(speed);
}

/// The slip velocity a velocity-dependent law is evaluated at: the element's rigid slip
/// velocity V·|w| [mm/s].
double law_speed(const FastsimInput& in, std::size_t i) {
  return in.rigid_speed.size() > i ? in.rigid_speed[i]
                                   : std::hypot(in.wx[i], in.wy[i]) / in.velocity->dt_s;
}

/// Solves one element given the displacement u′ of its particles one step earlier (and μ′ for
/// velocity-dependent friction); returns the element's displacement u and μ.
struct ElementOutcome {
  double ux, uy, mu;
};

ElementOutcome solve_element(const FastsimInput& in, std::size_t i, double upx, double upy,
                             double mu_prime, SimplifiedFields& out) {
  const double mu =
      in.velocity != nullptr ? relaxed_mu(*in.velocity, mu_prime, law_speed(in, i)) : in.mu;
  const double bound = mu * in.pn[i];
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
  if (!out.mu.empty()) out.mu[i] = mu;
  return {ux, uy, mu};
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
  const double mu_static = in.velocity != nullptr ? in.velocity->law->coefficient() : in.mu;
  if (in.velocity != nullptr) out.mu.assign(n, mu_static);
  if (in.steady) {
    // Particles enter at the leading edge unloaded and move one element per step (δq = δx).
    // With friction memory the first element of a run enters with the law's value at its own
    // rigid slip velocity, not with μ_static: the memory starts in the steady state
    // (docs/decisions.md: with μ_static there, tractcurv c109-c113 end their adhesion zones one
    // element early).
    const bool forward = std::cos(in.chi) >= 0.0;
    for (int iy = 0; iy < grid.my; ++iy) {
      double upx = 0.0, upy = 0.0;
      bool entering = true;
      double mu_prime = mu_static;
      for (int k = 0; k < grid.mx; ++k) {
        const int ix = forward ? grid.mx - 1 - k : k;
        const std::size_t i = grid.index(ix, iy);
        if (!(in.pn[i] > 0.0)) {
          upx = upy = 0.0;
          entering = true;
          continue;
        }
        if (entering && in.velocity != nullptr)
          mu_prime = in.velocity->law->coefficient_at(law_speed(in, i));
        entering = false;
        const ElementOutcome e = solve_element(in, i, upx, upy, mu_prime, out);
        upx = e.ux;
        upy = e.uy;
        mu_prime = e.mu;
      }
    }
    return out;
  }
  const bool has_prev = in.ux_prev.size() == n && in.uy_prev.size() == n;
  for (std::size_t i = 0; i < n; ++i) {
    if (!(in.pn[i] > 0.0)) continue;
    double mu_prime = mu_static;
    if (in.velocity != nullptr)
      mu_prime = in.mu_prev.size() == n && in.mu_prev[i] >= 0.0
                     ? in.mu_prev[i]
                     : in.velocity->law->coefficient_at(law_speed(in, i));
    solve_element(in, i, has_prev ? in.ux_prev[i] : 0.0, has_prev ? in.uy_prev[i] : 0.0, mu_prime,
                  out);
  }
  return out;
}

namespace {

/// Calls visit(i, jx, jy, tx, ty) for every element i whose point δq upstream lies within the
/// outer element centres: the point is element (jx, jy) plus (tx, ty) of an element towards
/// (jx + 1, jy + 1) (index coordinates).
template <class Visit>
void for_each_upstream_point(const Grid& grid, double chi, double dq, Visit&& visit) {
  // Position in element-centre index coordinates of the point δq upstream.
  const double sx = dq * std::cos(chi) / grid.dx, sy = dq * std::sin(chi) / grid.dy;
  for (int iy = 0; iy < grid.my; ++iy) {
    for (int ix = 0; ix < grid.mx; ++ix) {
      const double fx = ix + sx, fy = iy + sy;
      const double x0 = std::floor(fx), y0 = std::floor(fy);
      // Points beyond the outer element centres lie outside the potential contact.
      if (fx < -1e-9 || fy < -1e-9 || fx > grid.mx - 1 + 1e-9 || fy > grid.my - 1 + 1e-9) continue;
      visit(grid.index(ix, iy), static_cast<long>(x0), static_cast<long>(y0), fx - x0, fy - y0);
    }
  }
}

}  // namespace

std::vector<double> upstream_field(const Grid& grid, std::span<const double> u, double chi,
                                   double dq) {
  std::vector<double> out(grid.size(), 0.0);
  if (u.size() != grid.size()) return out;
  auto value = [&](long ix, long iy) {
    if (ix < 0 || iy < 0 || ix >= grid.mx || iy >= grid.my) return 0.0;
    return u[grid.index(static_cast<int>(ix), static_cast<int>(iy))];
  };
  for_each_upstream_point(
      grid, chi, dq, [&](std::size_t i, long jx, long jy, double tx, double ty) {
        out[i] = (1.0 - tx) * (1.0 - ty) * value(jx, jy) + tx * (1.0 - ty) * value(jx + 1, jy) +
                 (1.0 - tx) * ty * value(jx, jy + 1) + tx * ty * value(jx + 1, jy + 1);
      });
  return out;
}

std::vector<double> upstream_memory(const Grid& grid, std::span<const double> mu,
                                    std::span<const double> pn, double chi, double dq) {
  std::vector<double> out(grid.size(), -1.0);
  if (mu.size() != grid.size() || pn.size() != grid.size()) return out;
  for_each_upstream_point(
      grid, chi, dq, [&](std::size_t i, long jx, long jy, double tx, double ty) {
        double sum = 0.0, weight = 0.0;
        const auto add = [&](long kx, long ky, double w) {
          if (kx < 0 || ky < 0 || kx >= grid.mx || ky >= grid.my || w <= 0.0) return;
          const std::size_t k = grid.index(static_cast<int>(kx), static_cast<int>(ky));
          if (!(pn[k] > 0.0)) return;  // not in contact: no memory of its own
          sum += w * mu[k];
          weight += w;
        };
        add(jx, jy, (1.0 - tx) * (1.0 - ty));
        add(jx + 1, jy, tx * (1.0 - ty));
        add(jx, jy + 1, (1.0 - tx) * ty);
        add(jx + 1, jy + 1, tx * ty);
        if (weight > 0.0) out[i] = sum / weight;
      });
  return out;
}

}  // namespace rollcontact::simplified
