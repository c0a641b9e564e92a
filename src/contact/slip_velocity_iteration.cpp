#include "contact/slip_velocity_iteration.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace rollcontact::contact {

namespace {

/// The element a particle comes from one element upstream in steady rolling (-1: it enters
/// the grid there). χ = 0 rolls towards +x: particles flow from high ix to low ix.
long upstream_neighbour(const Grid& grid, int ix, int iy, double chi) {
  const int jx = ix + static_cast<int>(std::lround(std::cos(chi)));
  const int jy = iy + static_cast<int>(std::lround(std::sin(chi)));
  if (jx < 0 || jx >= grid.mx || jy < 0 || jy >= grid.my || (jx == ix && jy == iy)) return -1;
  return static_cast<long>(grid.index(jx, jy));
}

double memory_weight(const FrictionMemoryInput& in, double speed) {
  const double dc = in.memory_distance_mm;
  if (dc <= 1e-9) return 0.0;
  return dc / (dc + in.dt_s * std::max(speed, in.memory_floor_speed_mm_s));
}

double norm(const Field& a) {
  double s = 0.0;
  for (double v : a) s += v * v;
  return std::sqrt(s);
}

}  // namespace

FrictionField friction_with_memory(const FrictionMemoryInput& in, const Field& speed) {
  const Grid& grid = *in.grid;
  const std::size_t n = grid.size();
  const double mu_static = in.law->coefficient();
  FrictionField f;
  f.mu.assign(n, mu_static);
  f.mu_prime.assign(n, mu_static);
  auto relax = [&](std::size_t i) {
    const double theta = memory_weight(in, speed[i]);
    const double target =
        in.target_mu != nullptr ? (*in.target_mu)[i] : in.law->coefficient_at(speed[i]);
    f.mu[i] = theta * f.mu_prime[i] + (1.0 - theta) * target;
  };
  if (!in.steady) {
    for (std::size_t i = 0; i < n; ++i) {
      if (!(*in.contact)[i]) continue;
      if (in.previous_mu != nullptr && in.previous_mu->size() == n && (*in.previous_mu)[i] >= 0.0)
        f.mu_prime[i] = (*in.previous_mu)[i];
      relax(i);
    }
    return f;
  }
  // Steady rolling: visit the elements from the leading edge downstream, so that the upstream
  // neighbour's μ is final when an element relaxes from it.
  const double cx = std::cos(in.chi_rad), cy = std::sin(in.chi_rad);
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::vector<double> along(n);
  for (int iy = 0; iy < grid.my; ++iy)
    for (int ix = 0; ix < grid.mx; ++ix)
      along[grid.index(ix, iy)] = grid.x_centre(ix) * cx + grid.y_centre(iy) * cy;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return along[a] > along[b]; });
  for (const std::size_t i : order) {
    if (!(*in.contact)[i]) continue;
    const int ix = static_cast<int>(i % static_cast<std::size_t>(grid.mx));
    const int iy = static_cast<int>(i / static_cast<std::size_t>(grid.mx));
    const long up = upstream_neighbour(grid, ix, iy, in.chi_rad);
    if (up >= 0) f.mu_prime[i] = f.mu[static_cast<std::size_t>(up)];
    relax(i);
  }
  return f;
}

bool record_pass(FrictionIterationOutcome& out, int pass, Field mu,
                 tangential::TangentialResult tangential) {
  out.passes = pass;
  out.mu = std::move(mu);
  out.tangential = std::move(tangential);
  if (out.tangential.converged) return true;
  out.message = out.tangential.message;
  return false;
}

SlipVelocityOutcome solve_with_slip_velocity(const FrictionMemoryInput& memory,
                                             const Field& initial_speed,
                                             const SlipVelocitySettings& settings,
                                             const TangentialSolveWithFriction& solve) {
  const std::vector<char>& contact = *memory.contact;
  const std::size_t n = contact.size();
  SlipVelocityOutcome out;
  Field speed(n, 0.0);
  for (std::size_t i = 0; i < n; ++i)
    if (contact[i]) speed[i] = std::max(0.0, initial_speed[i]);
  double omega = settings.relaxation;
  std::vector<ElementState> last_state;
  for (int pass = 1; pass <= std::max(1, settings.max_passes); ++pass) {
    const FrictionField friction = friction_with_memory(memory, speed);
    tangential::TangentialResult tang = solve(friction.mu);
    Field next(n, 0.0);
    int nslip = 0, nadh = 0;
    for (std::size_t i = 0; i < n; ++i) {
      if (!contact[i]) continue;
      next[i] = std::hypot(tang.sx[i], tang.sy[i]) / memory.dt_s;
      const bool slipping = tang.state[i] == ElementState::Slip;
      nslip += slipping;
      nadh += tang.state[i] == ElementState::Adhesion;
      if (pass >= 2 && slipping && friction.mu[i] > friction.mu_prime[i])
        next[i] = std::max(0.0, next[i] + (omega - 1.0) * (next[i] - speed[i]));
    }
    Field change(n);
    for (std::size_t i = 0; i < n; ++i) change[i] = next[i] - speed[i];
    const double dnorm = norm(change), snorm = norm(next);
    out.trace.push_back(
        fmt::format("{:5d}, Vel-dep: A, S= {:5d} {:5d}, |Sk-Sk-1|, .001 |Sk| : "
                    "{:12.4g} {:12.4g}",
                    pass, nadh, nslip, dnorm, 1e-3 * snorm));
    const bool division_changed = tang.state != last_state;
    last_state = tang.state;
    speed = std::move(next);
    if (!record_pass(out, pass, friction.mu, std::move(tang))) return out;
    if (dnorm <= 1e-3 * snorm || nslip == 0) {
      out.converged = true;
      return out;
    }
    if (pass % 20 == 0 && division_changed) omega *= 0.8;
  }
  out.message = fmt::format(
      "the slip-velocity iteration of the velocity-dependent friction law did not converge in "
      "{} passes (MAXIN − 10)",
      out.passes);
  return out;
}

}  // namespace rollcontact::contact
