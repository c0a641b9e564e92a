#pragma once
// Analytic Hertz solutions (spec/physics.md §8): 3-D elliptic contact with complete elliptic
// integrals, 2-D line contact. E* = G/(1−ν) is the combined contact modulus [N/mm²].

#include "rollcontact/solution.hpp"

namespace rollcontact::geometry {

/// Complete elliptic integrals K(k), E(k) of modulus k (0 ≤ k < 1), via Bulirsch's associate
/// integrals B(k), D(k) (K = B + D, E = B + (1−k²)D). Throws ProblemError unless |k| < 1.
struct EllipticIntegrals {
  double k_first, e_second, b_assoc, d_assoc;
};
EllipticIntegrals complete_elliptic_integrals(double k);
/// Same, from the complementary parameter m_c = 1 − k² ∈ (0, 1]. Preferred near k → 1, where
/// forming 1 − k² from k would lose digits. Throws ProblemError outside the domain.
EllipticIntegrals complete_elliptic_integrals_mc(double mc);

/// Curvature ratio min(A1,B1)/max(A1,B1) = m_c·D/B of a Hertz ellipse with axis ratio
/// g = min(a,b)/max(a,b) ∈ (0, 1]. Strictly increasing in g, 1 at g = 1.
double hertz_curvature_ratio(double g);
/// Inverse of hertz_curvature_ratio: the axis ratio g for a curvature ratio r ∈ (0, 1], to full
/// double precision (bisection). Throws ProblemError for r outside (0, 1].
double hertz_axis_ratio(double r);

/// What is prescribed for a Hertz solution. All Hertz functions throw ProblemError for
/// non-positive or non-finite data (curvatures, semi-axes, load, E*).
enum class HertzLoad { Force, Approach };

/// 3-D Hertz from curvatures A1, B1 [1/mm] and FN [N] or PEN [mm] (IPOTCN −1).
HertzReport hertz_from_curvatures(double a1, double b1, HertzLoad load, double value, double estar);
/// 3-D Hertz from A1 and the semi-axis ratio a/b (IPOTCN −2).
HertzReport hertz_from_a1_and_ratio(double a1, double aob, HertzLoad load, double value,
                                    double estar);
/// 3-D Hertz from the semi-axes a, b [mm] (IPOTCN −3): curvatures follow from the load.
HertzReport hertz_from_semiaxes(double aa, double bb, HertzLoad load, double value, double estar);
/// 2-D (line) Hertz with FN [N] over width 2b (IPOTCN −4 from A1, −5 from half length a).
/// B1 = 0; PEN is not defined by 2-D Hertz theory and is reported as 0; rho = 2/A1 (the 3-D
/// definition 2/(A1+B1)); pmax = 2FN/(π a L) with L = 2b.
HertzReport hertz_2d_from_curvature(double a1, double bb, double fn, double estar);
HertzReport hertz_2d_from_half_length(double aa, double bb, double fn, double estar);

/// Analytic Hertz pressure at (x, y) for the ellipse in `h` (3-D) or strip (2-D) [N/mm²].
/// Zero outside the ellipse (3-D) or outside |x| < a, |y| ≤ b (2-D).
double hertz_pressure(const HertzReport& h, double x, double y);

}  // namespace rollcontact::geometry
