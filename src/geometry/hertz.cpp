// Analytic Hertz solutions (spec/physics.md §8).
//
// 3-D: with g = min(a,b)/max(a,b), m_c = g², c = √(ab) and ρ = 2/(A1+B1), Hertz theory gives
//   min(A1,B1)/max(A1,B1) = m_c·D/B,
//   FN = 4π c³ E* √g / (3ρE),  PEN = 2 (c√g)² K / (ρE),
// and the smaller semi-axis lies along the larger curvature. Everything below is these two
// relations solved for whichever quantities are unknown. Circle check: g = 1, K = E = π/2,
// ρ = 2R gives a³ = 3FN·R/(4E*) and PEN = a²/R.
// 2-D: line load F' = FN/L per unit length over L = 2b, R_x = 1/(2A1),
//   a² = 4 R_x F' / (π E*),  p0 = 2F'/(πa).

#include "geometry/hertz.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "rollcontact/errors.hpp"

namespace rollcontact::geometry {

namespace {

constexpr double pi = std::numbers::pi;

void require_positive(double value, const char* what) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw ProblemError(std::string("Hertz solution: ") + what +
                       " must be positive and finite (got " + std::to_string(value) + ")");
  }
}

/// Minor/major semi-axes and the load pair of a 3-D Hertz contact with known shape (g, ρ).
struct Ellipse {
  double minor, major, pen, fn;
};

Ellipse solve_size(double g, double rho, HertzLoad load, double value, double estar) {
  const EllipticIntegrals ei = complete_elliptic_integrals_mc(g * g);
  const double sg = std::sqrt(g);
  Ellipse el{};
  double c = 0.0;
  if (load == HertzLoad::Force) {
    el.fn = value;
    c = std::cbrt(3.0 * el.fn * rho * ei.e_second / (4.0 * pi * estar * sg));
    el.pen = 2.0 * (c * sg) * (c * sg) * ei.k_first / (rho * ei.e_second);
  } else {
    el.pen = value;
    c = std::sqrt(el.pen * rho * ei.e_second / (2.0 * ei.k_first * g));
    el.fn = 4.0 * pi * c * c * c * estar * sg / (3.0 * rho * ei.e_second);
  }
  el.minor = c * sg;
  el.major = c / sg;
  return el;
}

HertzReport report_3d(double a1, double b1, double aa, double bb, double pen, double fn) {
  HertzReport r;
  r.present = true;
  r.two_dimensional = false;
  r.a1 = a1;
  r.b1 = b1;
  r.aa = aa;
  r.bb = bb;
  r.rho = 2.0 / (a1 + b1);
  r.cp = std::sqrt(aa * bb);
  r.pen = pen;
  r.fn = fn;
  r.pmax = 3.0 * fn / (2.0 * pi * aa * bb);
  return r;
}

HertzReport report_2d(double a1, double aa, double bb, double fn) {
  HertzReport r;
  r.present = true;
  r.two_dimensional = true;
  r.a1 = a1;
  r.b1 = 0.0;
  r.aa = aa;
  r.bb = bb;
  r.rho = 2.0 / a1;
  r.cp = std::sqrt(aa * bb);
  r.pen = 0.0;  // not defined by 2-D Hertz theory (depends on the far field)
  r.fn = fn;
  r.pmax = 2.0 * fn / (pi * aa * 2.0 * bb);
  return r;
}

}  // namespace

double hertz_curvature_ratio(double g) {
  if (!(g > 0.0) || !(g <= 1.0)) {
    throw ProblemError("hertz_curvature_ratio: axis ratio must lie in (0, 1]");
  }
  const double mc = g * g;
  const EllipticIntegrals ei = complete_elliptic_integrals_mc(mc);
  return mc * ei.d_assoc / ei.b_assoc;
}

double hertz_axis_ratio(double r) {
  if (!(r > 0.0) || !(r <= 1.0)) {
    throw ProblemError("Hertz solution: curvature ratio min(A1,B1)/max(A1,B1) must lie in (0, 1]");
  }
  if (r == 1.0) return 1.0;
  // Bracket: the ratio behaves like g²·ln(4/g) for small g, so halving reaches any r > 1e-290
  // before g² underflows (g ≥ 1e-150).
  double lo = 0.5;
  double hi = 1.0;
  while (hertz_curvature_ratio(lo) >= r) {
    hi = lo;
    lo *= 0.5;
    if (lo < 1e-150) {
      throw ProblemError("Hertz solution: curvature ratio " + std::to_string(r) +
                         " is too small (ellipse too elongated)");
    }
  }
  // False position with the Illinois modification down to adjacent doubles, a bisection
  // whenever a step leaves the bracket or two steps failed to halve it: monotone and safe as
  // bisection, but ~10 ratio evaluations instead of ~55 (KPEC and ANALYN solve Hertz problems
  // per vertical-force iterate and per row). Full precision makes round trips exact to ~1e-15.
  double f_lo = hertz_curvature_ratio(lo) - r, f_hi = hertz_curvature_ratio(hi) - r;
  int last_side = 0;
  double width_before = hi - lo, width_two_before = 2.0 * width_before;
  for (int it = 0; it < 200; ++it) {
    if (std::nextafter(lo, hi) >= hi) break;
    double g = f_hi != f_lo ? (lo * f_hi - hi * f_lo) / (f_hi - f_lo) : 0.5 * (lo + hi);
    if (!(g > lo && g < hi) || hi - lo > 0.5 * width_two_before) g = 0.5 * (lo + hi);
    width_two_before = width_before;
    width_before = hi - lo;
    const double f = hertz_curvature_ratio(g) - r;
    if (f == 0.0) return g;
    if (f < 0.0) {
      lo = g;
      f_lo = f;
      if (last_side < 0) f_hi *= 0.5;
      last_side = -1;
    } else {
      hi = g;
      f_hi = f;
      if (last_side > 0) f_lo *= 0.5;
      last_side = 1;
    }
  }
  return 0.5 * (lo + hi);
}

HertzReport hertz_from_curvatures(double a1, double b1, HertzLoad load, double value,
                                  double estar) {
  require_positive(a1, "curvature A1");
  require_positive(b1, "curvature B1");
  require_positive(value, load == HertzLoad::Force ? "normal force FN" : "approach PEN");
  require_positive(estar, "contact modulus E* = G/(1-nu)");
  const double g = hertz_axis_ratio(std::min(a1, b1) / std::max(a1, b1));
  const Ellipse el = solve_size(g, 2.0 / (a1 + b1), load, value, estar);
  // The smaller semi-axis lies along the larger curvature.
  const double aa = a1 >= b1 ? el.minor : el.major;
  const double bb = a1 >= b1 ? el.major : el.minor;
  return report_3d(a1, b1, aa, bb, el.pen, el.fn);
}

HertzReport hertz_from_a1_and_ratio(double a1, double aob, HertzLoad load, double value,
                                    double estar) {
  require_positive(a1, "curvature A1");
  require_positive(aob, "semi-axis ratio AOB = a/b");
  require_positive(value, load == HertzLoad::Force ? "normal force FN" : "approach PEN");
  require_positive(estar, "contact modulus E* = G/(1-nu)");
  // The curvature ratio depends on the axis ratio only, so B1 follows in closed form; no
  // iteration on B1 (the spec's halve/double + regula falsi) is needed.
  const double g = aob <= 1.0 ? aob : 1.0 / aob;
  const double r = hertz_curvature_ratio(g);
  // a ≤ b: a along the larger curvature, i.e. A1 ≥ B1.
  const double b1 = aob <= 1.0 ? a1 * r : a1 / r;
  const Ellipse el = solve_size(g, 2.0 / (a1 + b1), load, value, estar);
  const double aa = aob <= 1.0 ? el.minor : el.major;
  const double bb = aob <= 1.0 ? el.major : el.minor;
  return report_3d(a1, b1, aa, bb, el.pen, el.fn);
}

HertzReport hertz_from_semiaxes(double aa, double bb, HertzLoad load, double value, double estar) {
  require_positive(aa, "semi-axis AA");
  require_positive(bb, "semi-axis BB");
  require_positive(value, load == HertzLoad::Force ? "normal force FN" : "approach PEN");
  require_positive(estar, "contact modulus E* = G/(1-nu)");
  const double g = std::min(aa, bb) / std::max(aa, bb);
  const double mc = g * g;
  const EllipticIntegrals ei = complete_elliptic_integrals_mc(mc);
  const double sg = std::sqrt(g);
  const double c = std::sqrt(aa * bb);
  const double minor = std::min(aa, bb);
  double rho = 0.0;
  double fn = 0.0;
  double pen = 0.0;
  if (load == HertzLoad::Force) {
    fn = value;
    rho = 4.0 * pi * c * c * c * estar * sg / (3.0 * fn * ei.e_second);
    pen = 2.0 * minor * minor * ei.k_first / (rho * ei.e_second);
  } else {
    pen = value;
    rho = 2.0 * minor * minor * ei.k_first / (pen * ei.e_second);
    fn = 4.0 * pi * c * c * c * estar * sg / (3.0 * rho * ei.e_second);
  }
  const double r = mc * ei.d_assoc / ei.b_assoc;
  const double cmax = (2.0 / rho) / (1.0 + r);
  const double cmin = r * cmax;
  const double a1 = aa <= bb ? cmax : cmin;
  const double b1 = aa <= bb ? cmin : cmax;
  return report_3d(a1, b1, aa, bb, pen, fn);
}

HertzReport hertz_2d_from_curvature(double a1, double bb, double fn, double estar) {
  require_positive(a1, "curvature A1");
  require_positive(bb, "half width BB");
  require_positive(fn, "normal force FN");
  require_positive(estar, "contact modulus E* = G/(1-nu)");
  const double f_per_length = fn / (2.0 * bb);
  const double rx = 1.0 / (2.0 * a1);
  const double aa = std::sqrt(4.0 * rx * f_per_length / (pi * estar));
  return report_2d(a1, aa, bb, fn);
}

HertzReport hertz_2d_from_half_length(double aa, double bb, double fn, double estar) {
  require_positive(aa, "half length AA");
  require_positive(bb, "half width BB");
  require_positive(fn, "normal force FN");
  require_positive(estar, "contact modulus E* = G/(1-nu)");
  const double f_per_length = fn / (2.0 * bb);
  const double rx = pi * aa * aa * estar / (4.0 * f_per_length);
  return report_2d(1.0 / (2.0 * rx), aa, bb, fn);
}

double hertz_pressure(const HertzReport& h, double x, double y) {
  if (!h.present || !(h.aa > 0.0)) return 0.0;
  const double xa = x / h.aa;
  if (h.two_dimensional) {
    if (std::abs(y) > h.bb) return 0.0;
    const double t = 1.0 - xa * xa;
    return t > 0.0 ? h.pmax * std::sqrt(t) : 0.0;
  }
  if (!(h.bb > 0.0)) return 0.0;
  const double yb = y / h.bb;
  const double t = 1.0 - xa * xa - yb * yb;
  return t > 0.0 ? h.pmax * std::sqrt(t) : 0.0;
}

}  // namespace rollcontact::geometry
