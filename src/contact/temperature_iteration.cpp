#include "contact/temperature_iteration.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace rollcontact::contact {

namespace {

/// 2-norm of `a` over the contact elements.
double contact_norm(const Field& a, const std::vector<char>& contact) {
  double s = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (contact[i]) s += a[i] * a[i];
  return std::sqrt(s);
}

}  // namespace

TemperatureIterationOutcome solve_with_temperature(const FrictionMemoryInput& memory,
                                                   const Field& initial_temperature_C,
                                                   const TemperatureIterationSettings& settings,
                                                   const TangentialSolveWithFriction& solve,
                                                   const SurfaceTemperatureOf& temperature_of) {
  const std::vector<char>& contact = *memory.contact;
  const std::size_t n = contact.size();
  TemperatureIterationOutcome out;
  Field temperature = initial_temperature_C;
  Field speed(n, 0.0);  // slip velocities of the last pass [mm/s], for the memory weight θ
  Field target(n, memory.law->coefficient());
  FrictionMemoryInput with_target = memory;
  with_target.target_mu = &target;
  double omega = settings.relaxation;
  std::vector<ElementState> last_state;
  for (int pass = 1; pass <= std::max(1, settings.max_passes); ++pass) {
    for (std::size_t i = 0; i < n; ++i)
      if (contact[i]) target[i] = memory.law->coefficient_at_temperature(temperature[i]);
    const FrictionField friction = friction_with_memory(with_target, speed);
    tangential::TangentialResult tang = solve(friction.mu);
    Field next = temperature_of(tang);
    Field change(n, 0.0);
    int nslip = 0, nadh = 0;
    for (std::size_t i = 0; i < n; ++i) {
      if (!contact[i]) continue;
      speed[i] = std::hypot(tang.sx[i], tang.sy[i]) / memory.dt_s;
      nslip += tang.state[i] == ElementState::Slip;
      nadh += tang.state[i] == ElementState::Adhesion;
      if (pass >= 2) next[i] = temperature[i] + omega * (next[i] - temperature[i]);
      change[i] = next[i] - temperature[i];
    }
    const double dnorm = contact_norm(change, contact), tnorm = contact_norm(next, contact);
    out.trace.push_back(
        fmt::format("{:5d}, Temp-dep: A, S= {:5d} {:5d}, |Tk-Tk-1|, {:g} |Tk| : "
                    "{:12.4g} {:12.4g}",
                    pass, nadh, nslip, settings.tolerance, dnorm, settings.tolerance * tnorm));
    const bool division_changed = tang.state != last_state;
    last_state = tang.state;
    temperature = std::move(next);
    out.temperature_C = temperature;
    if (!record_pass(out, pass, friction.mu, std::move(tang))) return out;
    if (dnorm <= settings.tolerance * tnorm) {
      out.converged = true;
      return out;
    }
    if (pass % settings.reduction_period == 0 && division_changed) omega *= 0.8;
  }
  out.message = fmt::format(
      "the temperature iteration of the temperature-dependent friction law did not converge in "
      "{} passes (MAXIN − 10)",
      out.passes);
  return out;
}

}  // namespace rollcontact::contact
