// Principal stresses in closed form: the deviator's eigenvalues are 2√(J₂/3) cos(φ − 2πk/3)
// with cos 3φ = (J₃/2)(3/J₂)^{3/2} (trigonometric solution of the characteristic cubic; exact
// for symmetric tensors, no iteration).

#include "post/stress_invariants.hpp"

#include <algorithm>
#include <cmath>

namespace rollcontact::post {

StressInvariants stress_invariants(const Matrix3& s) {
  constexpr double kPi = 3.14159265358979323846;
  StressInvariants r;
  const double sxx = s[0][0], syy = s[1][1], szz = s[2][2];
  const double sxy = s[0][1], sxz = s[0][2], syz = s[1][2];
  const double mean = (sxx + syy + szz) / 3.0;
  const double dx = sxx - mean, dy = syy - mean, dz = szz - mean;
  const double off2 = sxy * sxy + sxz * sxz + syz * syz;
  const double j2 = 0.5 * (dx * dx + dy * dy + dz * dz) + off2;
  r.hydrostatic = mean;
  r.von_mises = std::sqrt(3.0 * j2);
  if (j2 <= 1e-30 * (mean * mean + 1e-300)) {
    r.principal = {mean, mean, mean};
    return r;
  }
  // det of the deviator
  const double j3 =
      dx * (dy * dz - syz * syz) - sxy * (sxy * dz - syz * sxz) + sxz * (sxy * syz - dy * sxz);
  const double arg = std::clamp(0.5 * j3 * std::pow(3.0 / j2, 1.5), -1.0, 1.0);
  const double phi = std::acos(arg) / 3.0;  // in [0, π/3]: k = 0 gives the largest root
  const double amp = 2.0 * std::sqrt(j2 / 3.0);
  r.principal[0] = mean + amp * std::cos(phi);
  r.principal[2] = mean + amp * std::cos(phi + 2.0 * kPi / 3.0);
  r.principal[1] = 3.0 * mean - r.principal[0] - r.principal[2];
  r.tresca = r.principal[0] - r.principal[2];
  return r;
}

}  // namespace rollcontact::post
