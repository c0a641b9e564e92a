#include "contact/interfacial_layer.hpp"

#include <algorithm>
#include <cmath>

namespace rollcontact::contact {

Field yield_limits(const model::InterfacialLayer& layer, const PlasticHistory& history,
                   const Field& increment_mm) {
  Field tau(increment_mm.size());
  for (std::size_t i = 0; i < tau.size(); ++i) {
    const double before = history.accumulated.empty() ? 0.0 : history.accumulated[i];
    tau[i] = std::max(
        0.0, layer.yield_stress_N_mm2 + layer.hardening_N_mm3 * (before + increment_mm[i]));
  }
  return tau;
}

int mark_plastic_elements(const Field& friction_bound, const Field& yield_limit,
                          tangential::TangentialResult& tang, Field& increment_mm) {
  int count = 0;
  increment_mm.assign(friction_bound.size(), 0.0);
  for (std::size_t i = 0; i < friction_bound.size(); ++i) {
    if (tang.state[i] != ElementState::Slip || !(yield_limit[i] < friction_bound[i])) continue;
    tang.state[i] = ElementState::Plastic;
    increment_mm[i] = std::hypot(tang.sx[i], tang.sy[i]);
    ++count;
  }
  return count;
}

void record_plastic_state(const model::InterfacialLayer& layer, const PlasticHistory& history,
                          const tangential::TangentialResult& tang, Solution& sol) {
  const std::size_t n = tang.state.size();
  Field increment(n, 0.0);
  sol.plastic_x.assign(n, 0.0);
  sol.plastic_y.assign(n, 0.0);
  sol.plastic_accumulated.assign(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    if (!history.x.empty()) {
      sol.plastic_x[i] = history.x[i];
      sol.plastic_y[i] = history.y[i];
      sol.plastic_accumulated[i] = history.accumulated[i];
    }
    if (tang.state[i] != ElementState::Plastic) continue;
    increment[i] = std::hypot(tang.sx[i], tang.sy[i]);
    sol.plastic_x[i] -= tang.sx[i];
    sol.plastic_y[i] -= tang.sy[i];
    sol.plastic_accumulated[i] += increment[i];
  }
  sol.yield_limit = yield_limits(layer, history, increment);
}

}  // namespace rollcontact::contact
