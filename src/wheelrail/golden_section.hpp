#pragma once
// Minimisation of a unimodal function of one variable — golden sections and Brent's method —
// shared by the searches along the wheel (the sliced wheel's locus) and along the track (the
// D=5 gap).

#include <cmath>

namespace rollcontact::wheelrail {

/// The bracket a golden-section search ends with: [a, b], its interior points c < d and f there.
struct GoldenBracket {
  double a = 0.0, b = 0.0, c = 0.0, d = 0.0, fc = 0.0, fd = 0.0;
};

/// Shrinks [a, b] around a minimum of f by golden sections, one evaluation per step, until the
/// bracket is at most `width` wide or `max_steps` steps were taken. Where f(c) = f(d) the left
/// part [a, d] is kept.
template <class F>
GoldenBracket golden_section_minimum(const F& f, double a, double b, double width, int max_steps) {
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  GoldenBracket r{a, b, b - g * (b - a), a + g * (b - a), 0.0, 0.0};
  r.fc = f(r.c);
  r.fd = f(r.d);
  for (int step = 0; step < max_steps && r.b - r.a > width; ++step) {
    if (r.fc <= r.fd) {
      r.b = r.d;
      r.d = r.c;
      r.fd = r.fc;
      r.c = r.b - g * (r.b - r.a);
      r.fc = f(r.c);
    } else {
      r.a = r.c;
      r.c = r.d;
      r.fc = r.fd;
      r.d = r.a + g * (r.b - r.a);
      r.fd = f(r.d);
    }
  }
  return r;
}

/// The minimum of f on [a, b] by Brent's method (R. P. Brent, Algorithms for Minimization
/// without Derivatives, 1973, ch. 5): parabolic steps through the three best points while they
/// stay inside the bracket and shrink, golden sections otherwise; to within about `tol`.
/// Returns x; f(x) in fx. For a smooth minimum it needs a third of golden sections' steps.
template <class F>
double brent_minimum(const F& f, double a, double b, double tol, int max_steps, double& fx) {
  const double golden = 0.5 * (3.0 - std::sqrt(5.0));
  double x = a + golden * (b - a), w = x, v = x;
  fx = f(x);
  double fw = fx, fv = fx, d = 0.0, e = 0.0;
  for (int step = 0; step < max_steps; ++step) {
    const double m = 0.5 * (a + b);
    const double tol1 = 1e-15 * std::abs(x) + tol / 3.0, tol2 = 2.0 * tol1;
    if (std::abs(x - m) <= tol2 - 0.5 * (b - a)) break;
    bool parabolic = false;
    if (std::abs(e) > tol1) {
      // The parabola through (v, fv), (w, fw), (x, fx): its vertex at x + p/q.
      double r = (x - w) * (fx - fv);
      double q = (x - v) * (fx - fw);
      double p = (x - v) * q - (x - w) * r;
      q = 2.0 * (q - r);
      if (q > 0.0) p = -p;
      q = std::abs(q);
      r = e;
      e = d;
      if (std::abs(p) < std::abs(0.5 * q * r) && p > q * (a - x) && p < q * (b - x)) {
        d = p / q;
        const double u = x + d;
        if (u - a < tol2 || b - u < tol2) d = x < m ? tol1 : -tol1;
        parabolic = true;
      }
    }
    if (!parabolic) {
      e = x < m ? b - x : a - x;
      d = golden * e;
    }
    const double u = x + (std::abs(d) >= tol1 ? d : (d > 0.0 ? tol1 : -tol1));
    const double fu = f(u);
    if (fu <= fx) {
      (u < x ? b : a) = x;
      v = w;
      fv = fw;
      w = x;
      fw = fx;
      x = u;
      fx = fu;
    } else {
      (u < x ? a : b) = u;
      if (fu <= fw || w == x) {
        v = w;
        fv = fw;
        w = u;
        fw = fu;
      } else if (fu <= fv || v == x || v == w) {
        v = u;
        fv = fu;
      }
    }
  }
  return x;
}

}  // namespace rollcontact::wheelrail
