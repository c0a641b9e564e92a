#include "physics/friction_law.hpp"

namespace rollcontact::physics {

void FrictionLaw::traction_bounds(const std::vector<double>& pressure_N_mm2,
                                  std::vector<double>& bound) const {
  bound.assign(pressure_N_mm2.size(), 0.0);
  for (std::size_t i = 0; i < pressure_N_mm2.size(); ++i)
    if (pressure_N_mm2[i] > 0.0) bound[i] = traction_bound(pressure_N_mm2[i]);
}

std::unique_ptr<FrictionLaw> make_friction_law(const model::Friction& friction) {
  return std::make_unique<CoulombLaw>(friction.static_coefficient);
}

}  // namespace rollcontact::physics
