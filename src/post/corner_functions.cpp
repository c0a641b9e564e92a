// Corner functions of the rectangle potentials V, L, M (see corner_functions.hpp).
//
// Derivations (a, b, z as in the header, ρ² = a² + b² + z², z > 0):
//  * V: classical potential of a uniform rectangle, ∂²F/∂a∂b = 1/ρ; its x-, y-, z-derivatives
//    follow by differentiation (ln(b+ρ), ln(a+ρ), −atan(ab/(zρ)); the last is minus the solid
//    angle, so V_z → −2π inside the loaded area as z → 0⁺).
//  * θ(a,b) = ∫ a/(ρ(ρ+z)) db: split 1/(ρ(ρ+z)) = 1/(a²+b²) − z/(ρ(a²+b²)) and use
//    ∫ db/((a²+b²)ρ) = atan(bz/(aρ))/(az). The difference of the two arctangents is combined
//    into atan(ab(ρ−z)/(a²ρ + b²z)), which is continuous at a = 0 for z > 0 (no branch jump).
//  * L_x = ∫ ln(ρ+z) db: by parts, b ln(ρ+z) − ∫ b²/(ρ(ρ+z)) db, with the same split.
//  * M_xx = ∫ Ω_a db = −∫ a/(ρ+z) db, with a/(ρ+z) = a(ρ−z)/(a²+b²) and ∫ ρ/(a²+b²) db
//    = ln(b+ρ) + (z/a) atan(bz/(aρ)).
//  * Mixed derivatives (∂_a∂_b of the antiderivative) are the integrands themselves: 1/ρ,
//    ln(ρ+z), Ω and their derivatives.
// Precision: b + ρ is formed without cancellation for b < 0 ((a²+z²)/(ρ−b)), likewise a + ρ,
// and ρ − z = (a²+b²)/(ρ+z).

#include "post/corner_functions.hpp"

#include <cmath>

namespace rollcontact::post {

namespace {

/// s + ρ for ρ = √(s² + t²), accurate also for s < 0.
double plus_rho(double s, double t2, double rho) {
  return s >= 0.0 ? s + rho : t2 / (rho - s);
}

}  // namespace

CornerValues corner_values(double a, double b, double z) {
  const double a2 = a * a, b2 = b * b, z2 = z * z;
  const double rho = std::sqrt(a2 + b2 + z2);
  const double ap = plus_rho(a, b2 + z2, rho);  // a + ρ
  const double bp = plus_rho(b, a2 + z2, rho);  // b + ρ
  const double rz = rho + z;
  const double rmz = (a2 + b2) / rz;  // ρ − z
  const double la = std::log(ap), lb = std::log(bp), lrz = std::log(rz);
  // atan2 with a non-negative second argument equals atan of the quotient and yields 0 (not NaN)
  // directly below a corner, where the quotient is 0/0 but its limit is 0.
  const double th_ab = std::atan2(a * b * rmz, a2 * rho + b2 * z);
  const double th_ba = std::atan2(a * b * rmz, b2 * rho + a2 * z);
  const double solid = std::atan2(a * b, z * rho);

  CornerValues c{};
  c[kV] = a * lb + b * la - z * solid;
  c[kVx] = lb;
  c[kVy] = la;
  c[kVz] = -solid;
  c[kVxx] = a / (rho * bp);
  c[kVyy] = b / (rho * ap);
  c[kVxy] = 1.0 / rho;
  c[kVxz] = z / (rho * bp);
  c[kVyz] = z / (rho * ap);
  c[kLx] = b * lrz + z * lb + a * th_ab;
  c[kLy] = a * lrz + z * la + b * th_ba;
  c[kLxx] = th_ab;
  c[kLyy] = th_ba;
  c[kLxy] = lrz;
  c[kLxxy] = a / (rho * rz);
  c[kLxyy] = b / (rho * rz);
  c[kMxx] = z * th_ab - a * lb;
  c[kMyy] = z * th_ba - b * la;
  c[kMxy] = z * lrz - rho;
  c[kMxxy] = -a / rz;
  c[kMxyy] = -b / rz;
  return c;
}

}  // namespace rollcontact::post
