#include "physics/friction_disk.hpp"

#include <cmath>

namespace rollcontact::physics {

DiskLinearisation linearise_disk_projection(double zx, double zy, double g) {
  DiskLinearisation lin;
  if (g <= 0.0) return lin;
  const double magnitude = std::hypot(zx, zy);
  if (magnitude <= g) {
    lin.region = DiskLinearisation::Region::Interior;
    return lin;
  }
  lin.region = DiskLinearisation::Region::Exterior;
  lin.nx = zx / magnitude;
  lin.ny = zy / magnitude;
  lin.kappa = g / magnitude;
  return lin;
}

}  // namespace rollcontact::physics
