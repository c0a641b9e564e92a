// Prescribed elliptic and parabolic pressures (spec/physics.md §7.2).

#include "simplified/prescribed_pressure.hpp"

#include <cmath>
#include <numbers>

#include "rollcontact/errors.hpp"

namespace rollcontact::simplified {

std::vector<double> prescribed_pressure(const Grid& grid, const HertzReport& hertz,
                                        PressureShape shape, double fn) {
  if (!hertz.present || !(hertz.aa > 0.0) || !(hertz.bb > 0.0))
    throw ProblemError(
        "prescribed pressures (B=2,3) need the semi-axes of a Hertzian potential contact "
        "(IPOTCN < 0)");
  if (!(fn > 0.0) || !std::isfinite(fn))
    throw ProblemError("prescribed pressures (B=2,3) need a positive normal force");
  constexpr double pi = std::numbers::pi;
  const double a = hertz.aa, b = hertz.bb;
  const bool elliptic = shape == PressureShape::Elliptic;
  double p0 = 0.0;
  if (hertz.two_dimensional) {
    const double length = 2.0 * b;
    p0 = elliptic ? 2.0 * fn / (pi * a * length) : 3.0 * fn / (4.0 * a * length);
  } else {
    p0 = elliptic ? 1.5 * fn / (pi * a * b) : 2.0 * fn / (pi * a * b);
  }
  std::vector<double> p(grid.size(), 0.0);
  for (int iy = 0; iy < grid.my; ++iy) {
    const double y = grid.y_centre(iy);
    if (hertz.two_dimensional && std::abs(y) > b) continue;
    const double ty = hertz.two_dimensional ? 0.0 : (y / b) * (y / b);
    for (int ix = 0; ix < grid.mx; ++ix) {
      const double x = grid.x_centre(ix) / a;
      const double t = 1.0 - x * x - ty;
      if (!(t > 0.0)) continue;
      const double v = p0 * (elliptic ? std::sqrt(t) : t);
      p[grid.index(ix, iy)] = v > min_contact_pressure ? v : 0.0;
    }
  }
  return p;
}

std::vector<double> sdec_pressure(const Grid& grid, double a, double b_neg, double b_pos,
                                  double fn) {
  if (!(a > 0.0) || !(b_neg > 0.0) || !(b_pos > 0.0) || !std::isfinite(a + b_neg + b_pos))
    throw ProblemError("SDEC (B=4) needs positive semi-axes AA, BNEG, BPOS");
  if (!(fn > 0.0) || !std::isfinite(fn))
    throw ProblemError("SDEC (B=4) needs a positive normal force");
  const double b = 0.5 * (b_neg + b_pos);
  const double y0 = -0.5 * (b_pos - b_neg);  // −bψ with ψ = (b_pos − b_neg)/(2b)
  const double p0 = 1.5 * fn / (std::numbers::pi * a * b);
  std::vector<double> p(grid.size(), 0.0);
  for (int iy = 0; iy < grid.my; ++iy) {
    const double y = grid.y_centre(iy);
    const double t = (y - y0) / (y > y0 ? b_pos : b_neg);  // b(1 ± ψ) = b_pos, b_neg
    const double xl2 = a * a * (1.0 - t * t);
    if (!(xl2 > 0.0)) continue;
    for (int ix = 0; ix < grid.mx; ++ix) {
      const double x = grid.x_centre(ix);
      const double s = xl2 - x * x;
      if (!(s > 0.0)) continue;
      const double v = p0 / a * std::sqrt(s);
      p[grid.index(ix, iy)] = v > min_contact_pressure ? v : 0.0;
    }
  }
  return p;
}

}  // namespace rollcontact::simplified
