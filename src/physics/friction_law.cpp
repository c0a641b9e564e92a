#include "physics/friction_law.hpp"

#include <algorithm>
#include <cmath>

namespace rollcontact::physics {

void FrictionLaw::traction_bounds(const std::vector<double>& pressure_N_mm2,
                                  std::vector<double>& bound) const {
  bound.assign(pressure_N_mm2.size(), 0.0);
  for (std::size_t i = 0; i < pressure_N_mm2.size(); ++i)
    if (pressure_N_mm2[i] > 0.0) bound[i] = traction_bound(pressure_N_mm2[i]);
}

FallingFrictionLaw::FallingFrictionLaw(const model::Friction& friction)
    : kind_(friction.law),
      kinetic_(friction.kinetic_coefficient),
      terms_(friction.terms),
      static_coefficient_(friction.kinetic_coefficient + friction.terms[0].coefficient +
                          friction.terms[1].coefficient) {}

double FallingFrictionLaw::coefficient_at(double slip_speed_mm_s) const {
  const double s = std::max(0.0, slip_speed_mm_s);
  const auto& [t1, t2] = terms_;
  switch (kind_) {
    case model::FrictionLawKind::LinearFalling:
      return kinetic_ + t1.coefficient * std::max(0.0, 1.0 - s / (2.0 * t1.speed_mm_s)) +
             t2.coefficient * std::max(0.0, 1.0 - s / (2.0 * t2.speed_mm_s));
    case model::FrictionLawKind::RationalFalling: {
      const double r2 = s / t2.speed_mm_s;
      return kinetic_ + t1.coefficient / (1.0 + s / t1.speed_mm_s) +
             t2.coefficient / (1.0 + r2 * r2);
    }
    case model::FrictionLawKind::ExponentialFalling:
      return kinetic_ + t1.coefficient * std::exp2(-s / t1.speed_mm_s) +
             t2.coefficient * std::exp2(-s / t2.speed_mm_s);
    case model::FrictionLawKind::Coulomb:
    case model::FrictionLawKind::TemperatureDependent:
      break;
  }
  return static_coefficient_;
}

double TemperatureFrictionLaw::coefficient_at_temperature(double temperature_C) const {
  const double fraction = std::clamp(
      (temperature_C - term_.reference_temperature_C) / term_.temperature_span_C, 0.0, 1.0);
  return reference_ + term_.change * fraction;
}

std::unique_ptr<FrictionLaw> make_friction_law(const model::Friction& friction) {
  if (friction.velocity_dependent()) return std::make_unique<FallingFrictionLaw>(friction);
  if (friction.temperature_dependent()) return std::make_unique<TemperatureFrictionLaw>(friction);
  return std::make_unique<CoulombLaw>(friction.static_coefficient);
}

}  // namespace rollcontact::physics
