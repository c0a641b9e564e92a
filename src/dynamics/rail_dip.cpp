#include <cmath>
#include <numbers>

#include "rollcontact/dynamics.hpp"

namespace rollcontact::dynamics {

double RailDip::dz_mm(double s) const {
  if (depth_mm == 0.0 || !(length_mm > 0.0) || s < start_mm || s > start_mm + length_mm) return 0.0;
  return 0.5 * depth_mm * (1.0 - std::cos(2.0 * std::numbers::pi * (s - start_mm) / length_mm));
}

double RailDip::slope(double s) const {
  if (depth_mm == 0.0 || !(length_mm > 0.0) || s < start_mm || s > start_mm + length_mm) return 0.0;
  const double w = 2.0 * std::numbers::pi / length_mm;
  return 0.5 * depth_mm * w * std::sin(w * (s - start_mm));
}

}  // namespace rollcontact::dynamics
