#pragma once
// Prescribed normal pressures (spec/physics.md §7.2): the normal problem is skipped and the
// pressure is an elliptic (B=2) or parabolic (B=3) distribution over the Hertz ellipse (3-D) or
// strip (2-D) carrying the total force FN.

#include <vector>

#include "rollcontact/grid.hpp"
#include "rollcontact/solution.hpp"

namespace rollcontact::simplified {

/// Shape of a prescribed pressure (the B digit).
enum class PressureShape { Elliptic = 2, Parabolic = 3 };

/// Smallest pressure [N/mm²] of an element in the contact set; smaller values are set to 0.
inline constexpr double min_contact_pressure = 1e-20;

/// Pressure per element [N/mm²] at the element centres for the Hertz semi-axes in `hertz`
/// (3-D: a, b; 2-D: half length a, half width b, uniform in |y| ≤ b) and total force `fn` [N]:
///   3-D elliptic  p₀√(1 − x²/a² − y²/b²), p₀ = 3FN/(2πab);  parabolic p₀(1 − x²/a² − y²/b²),
///   p₀ = 2FN/(πab);  2-D elliptic p₀√(1 − x²/a²), p₀ = 2FN/(πaL);  parabolic p₀(1 − x²/a²),
///   p₀ = 3FN/(4aL), L = 2b.
/// Values ≤ 1e−20 become 0 (exterior). Throws ProblemError unless hertz.present with positive
/// semi-axes and fn > 0.
std::vector<double> prescribed_pressure(const Grid& grid, const HertzReport& hertz,
                                        PressureShape shape, double fn);

/// SDEC (B=4, spec/physics.md §7.2): two half-ellipses with the common semi-axis a [mm] along x
/// and the lateral semi-axes b_neg, b_pos [mm] below and above their widest row
/// y₀ = −(b_pos − b_neg)/2, spanning |y| ≤ b = (b_neg + b_pos)/2. Per row the half length is
/// x_l(y) = a√(1 − ((y − y₀)/b_±)²) and the pressure (p₀/a)√(x_l² − x²) with p₀ = 3FN/(2πab),
/// which carries FN exactly (for b_neg = b_pos the elliptic Hertz pressure). Values ≤ 1e−20
/// become 0. Throws ProblemError unless a, b_neg, b_pos and fn are positive.
std::vector<double> sdec_pressure(const Grid& grid, double a, double b_neg, double b_pos,
                                  double fn);

}  // namespace rollcontact::simplified
