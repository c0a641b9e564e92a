// Complete elliptic integrals through Bulirsch's associate integrals B and D.
//
// Hertz theory needs K, E and the ratio D/B for ellipses that may be very elongated (modulus
// k → 1). Forming k_c = √(1 − k²) from k loses half the digits there, so the core routine takes
// the complementary parameter m_c = 1 − k² = k_c² directly. B and D are evaluated with
// Bulirsch's generalised integral cel(k_c, p, a, b) (Numer. Math. 13, 1969), a
// Landen/AGM-type iteration that converges quadratically for every k_c > 0 and has no
// cancellation: both B and D are computed as sums of positive terms.

#include <cmath>
#include <numbers>

#include "geometry/hertz.hpp"
#include "rollcontact/errors.hpp"

namespace rollcontact::geometry {

namespace {

/// cel(k_c, 1, a, b) = ∫₀^{π/2} (a cos²θ + b sin²θ) / √(cos²θ + k_c² sin²θ) dθ for k_c > 0.
/// With p = 1 the general algorithm simplifies (no p-transformation needed).
double cel_p1(double kc, double a, double b) {
  // Convergence is quadratic; the relative error after the stop test is about tol², so
  // tol = 1e-9 gives results at the level of machine precision.
  constexpr double tol = 1e-9;
  double qc = kc;
  double p = 1.0;
  double e = qc;
  double em = 1.0;
  for (int it = 0; it < 64; ++it) {
    const double f = a;
    a += b / p;
    double g = e / p;
    b += f * g;
    b += b;
    p = g + p;
    g = em;
    em += qc;
    if (std::abs(g - qc) <= g * tol) break;
    qc = 2.0 * std::sqrt(e);
    e = qc * em;
  }
  return 0.5 * std::numbers::pi * (b + a * em) / (em * (em + p));
}

}  // namespace

EllipticIntegrals complete_elliptic_integrals_mc(double mc) {
  if (!(mc > 0.0) || !(mc <= 1.0)) {
    throw ProblemError("complete_elliptic_integrals_mc: m_c must lie in (0, 1]");
  }
  const double kc = std::sqrt(mc);
  EllipticIntegrals r{};
  r.b_assoc = cel_p1(kc, 1.0, 0.0);  // B = ∫ cos²θ/Δ
  r.d_assoc = cel_p1(kc, 0.0, 1.0);  // D = ∫ sin²θ/Δ
  r.k_first = r.b_assoc + r.d_assoc;
  r.e_second = r.b_assoc + mc * r.d_assoc;
  return r;
}

EllipticIntegrals complete_elliptic_integrals(double k) {
  if (!(std::abs(k) < 1.0)) {
    throw ProblemError("complete_elliptic_integrals: modulus k must satisfy |k| < 1");
  }
  // (1 − k)(1 + k) keeps the relative accuracy of m_c when k is close to 1.
  return complete_elliptic_integrals_mc((1.0 - k) * (1.0 + k));
}

}  // namespace rollcontact::geometry
