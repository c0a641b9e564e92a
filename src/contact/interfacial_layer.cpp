#include "contact/interfacial_layer.hpp"

#include <algorithm>
#include <cmath>

namespace rollcontact::contact {

Field accumulate_along_rows(const Grid& grid, double chi_rad, const Field& per_step) {
  Field out(per_step.size(), 0.0);
  const bool forward = std::cos(chi_rad) >= 0.0;  // χ = 0: particles enter at ix = MX − 1
  for (int iy = 0; iy < grid.my; ++iy) {
    double sum = 0.0;
    for (int k = 0; k < grid.mx; ++k) {
      const std::size_t i = grid.index(forward ? grid.mx - 1 - k : k, iy);
      sum += per_step[i];
      out[i] = sum;
    }
  }
  return out;
}

Field yield_limits(const model::InterfacialLayer& layer, const PlasticHistory& history,
                   const Field& increment_mm) {
  const Field accumulated =
      history.steady_grid != nullptr
          ? accumulate_along_rows(*history.steady_grid, history.chi_rad, increment_mm)
          : Field{};
  Field tau(increment_mm.size());
  for (std::size_t i = 0; i < tau.size(); ++i) {
    const double u =
        history.steady_grid != nullptr
            ? accumulated[i]
            : (history.accumulated.empty() ? 0.0 : history.accumulated[i]) + increment_mm[i];
    tau[i] = std::max(0.0, layer.yield_stress_N_mm2 + layer.hardening_N_mm3 * u);
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
  if (history.steady_grid != nullptr) {
    // The state a particle carries at each element: the flow of its row up to there.
    Field sx(n, 0.0), sy(n, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
      if (tang.state[i] != ElementState::Plastic) continue;
      increment[i] = std::hypot(tang.sx[i], tang.sy[i]);
      sx[i] = -tang.sx[i];
      sy[i] = -tang.sy[i];
    }
    const Grid& g = *history.steady_grid;
    sol.plastic_x = accumulate_along_rows(g, history.chi_rad, sx);
    sol.plastic_y = accumulate_along_rows(g, history.chi_rad, sy);
    sol.plastic_accumulated = accumulate_along_rows(g, history.chi_rad, increment);
    sol.yield_limit = yield_limits(layer, history, increment);
    return;
  }
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
