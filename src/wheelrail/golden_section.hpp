#pragma once
// Golden-section search for the minimum of a unimodal function of one variable, shared by the
// searches along the wheel (the sliced wheel's locus) and along the track (the D=5 gap).

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

}  // namespace rollcontact::wheelrail
