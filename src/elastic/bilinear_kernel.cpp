// Bilinear traction elements (spec-additions.md §B7).
//
// The hat h(ξ)h(η), h(ξ) = 1 − |ξ|/δx, has h'' = (δ(ξ+δx) − 2δ(ξ) + δ(ξ−δx))/δx, so with H a
// fourth antiderivative of the kernel (∂⁴H/∂X²∂Y² = f) two integrations by parts in each
// direction give
//   I[f](Δx, Δy) = (1/(δxδy)) Σ_{a,b ∈ {−1,0,1}} w_a w_b H(Δx + aδx, Δy + bδy),  w = (1, −2, 1):
// H at the 9 nodes of the support. H is fixed up to terms linear in X or in Y, which the
// stencil removes. With r = √(X² + Y²) (derived and checked symbolically, and against adaptive
// quadrature of the definition to 1e-28, in docs/decisions.md):
//   f = 1/r:     H = ½X²Y·ln(Y + r) + ½XY²·ln(X + r) − r³/6
//   f = x²/r³:   H = ½XY²·ln(X + r) + ½X²r − r³/3           (y²/r³: X and Y exchanged)
//   f = xy/r³:   H = −(XYr/3 + Y³/6·ln(X + r) + X³/6·ln(Y + r))
//   f = x/r²:    H = (XY²/2 − X³/6)·ln r + ½X²Y·atan(Y/X) + Y³/6·atan(X/Y)  (y/r²: exchanged)
// A term whose multiplier vanishes is dropped (its logarithm or atan may be singular there;
// the product tends to 0), which keeps the coefficients continuous in a rolling shift.
//
// Precision: the stencil cancels H ~ r³ down to ~δ⁴/r, losing (r/δ)⁴: in long double 1e-17
// relative at 3 elements, 5e-11 at 100, 3e-8 at 300. Beyond 3 element sizes from the support
// (where the kernel is smooth on it) the definition is integrated instead by Gauss–Legendre on
// each quadrant of the support, on which the hat is a polynomial: exponentially convergent
// (singularity at ≥ 3 sizes from a quadrant: ρ ≥ 11.9 per direction), measured 1e-16.

#include "elastic/bilinear_kernel.hpp"

#include <array>
#include <cmath>

namespace rollcontact::elastic {

namespace {

using Real = long double;
constexpr Real kPi = 3.141592653589793238462643383279502884L;

/// The integrals I[f] of the six kernel functions of §B7 against one hat (mm).
struct HatIntegrals {
  Real inv_r = 0, xx = 0, yy = 0, xy = 0, x = 0, y = 0;  ///< 1/r, x²/r³, y²/r³, xy/r³, x/r², y/r²
};

/// a + √(a² + b²) with r = √(a² + b²), without cancellation for a < 0.
Real plus_r(Real a, Real b, Real r) {
  return a >= 0 ? a + r : (b * b) / (r - a);
}

/// m·log(arg), 0 where the multiplier vanishes (the limit of the product).
Real times_log(Real m, Real arg) {
  return m == 0 ? 0.0L : m * std::log(arg);
}

/// m·atan(num/den), 0 where the multiplier vanishes (den = 0 makes it vanish as well).
Real times_atan(Real m, Real num, Real den) {
  return m == 0 ? 0.0L : m * std::atan(num / den);
}

/// The fourth antiderivatives H of the file comment at (X, Y) [mm⁴-ish units of the kernels].
HatIntegrals antiderivatives(Real x, Real y, bool coupled) {
  const Real r = std::sqrt(x * x + y * y);
  const Real lx = times_log(0.5L * x * y * y, plus_r(x, y, r));  // ½XY²·ln(X + r)
  const Real ly = times_log(0.5L * x * x * y, plus_r(y, x, r));  // ½X²Y·ln(Y + r)
  const Real r3 = r * r * r;
  HatIntegrals h;
  h.inv_r = ly + lx - r3 / 6.0L;
  h.xx = lx + 0.5L * x * x * r - r3 / 3.0L;
  h.yy = ly + 0.5L * y * y * r - r3 / 3.0L;
  h.xy = -(x * y * r / 3.0L + times_log(y * y * y / 6.0L, plus_r(x, y, r)) +
           times_log(x * x * x / 6.0L, plus_r(y, x, r)));
  if (coupled) {
    const Real log_r = r == 0 ? 0.0L : std::log(r);
    h.x = (0.5L * x * y * y - x * x * x / 6.0L) * log_r + times_atan(0.5L * x * x * y, y, x) +
          times_atan(y * y * y / 6.0L, x, y);
    h.y = (0.5L * y * x * x - y * y * y / 6.0L) * log_r + times_atan(0.5L * y * y * x, x, y) +
          times_atan(x * x * x / 6.0L, y, x);
  }
  return h;
}

void add_scaled(HatIntegrals& s, const HatIntegrals& h, Real w) {
  s.inv_r += w * h.inv_r;
  s.xx += w * h.xx;
  s.yy += w * h.yy;
  s.xy += w * h.xy;
  s.x += w * h.x;
  s.y += w * h.y;
}

/// The 9-node stencil of the closed forms (near the load).
HatIntegrals closed_form(Real ox, Real oy, Real dx, Real dy, bool coupled) {
  constexpr std::array<Real, 3> w{1.0L, -2.0L, 1.0L};
  HatIntegrals s;
  for (int b = 0; b < 3; ++b)
    for (int a = 0; a < 3; ++a)
      add_scaled(s, antiderivatives(ox + (a - 1) * dx, oy + (b - 1) * dy, coupled),
                 w[static_cast<std::size_t>(a)] * w[static_cast<std::size_t>(b)]);
  const Real inv_area = 1.0L / (dx * dy);
  HatIntegrals out;
  add_scaled(out, s, inv_area);
  return out;
}

/// Gauss–Legendre nodes and weights on [0, 1] (10 points), for the quadrants of the support.
struct Rule {
  std::array<Real, 10> t, w;
};

Rule gauss_legendre_10() {
  // Nodes ±t_k and weights of the 10-point rule on [−1, 1] (Abramowitz & Stegun 25.4.30).
  constexpr std::array<Real, 5> t{0.1488743389816312108848260L, 0.4333953941292471907992659L,
                                  0.6794095682990244062343274L, 0.8650633666889845107320967L,
                                  0.9739065285171717200779640L};
  constexpr std::array<Real, 5> w{0.2955242247147528701738930L, 0.2692667193099963550912269L,
                                  0.2190863625159820439955349L, 0.1494513491505805931457763L,
                                  0.0666713443086881375935688L};
  Rule r;
  for (std::size_t k = 0; k < 5; ++k) {
    r.t[4 - k] = 0.5L * (1.0L - t[k]);
    r.t[5 + k] = 0.5L * (1.0L + t[k]);
    r.w[4 - k] = r.w[5 + k] = 0.5L * w[k];
  }
  return r;
}

/// The definition integrated by Gauss–Legendre on the four quadrants of the support (far from
/// the load, where the kernel is smooth there). On a quadrant ξ = ±u·δx, η = ±v·δy, u, v ∈
/// [0, 1], the hat is (1 − u)(1 − v).
HatIntegrals quadrature(Real ox, Real oy, Real dx, Real dy, bool coupled) {
  const Rule rule = gauss_legendre_10();
  HatIntegrals s;
  for (const Real sx : {-1.0L, 1.0L})
    for (const Real sy : {-1.0L, 1.0L})
      for (std::size_t j = 0; j < rule.t.size(); ++j) {
        const Real y = oy - sy * rule.t[j] * dy;
        const Real wy = rule.w[j] * (1.0L - rule.t[j]);
        for (std::size_t i = 0; i < rule.t.size(); ++i) {
          const Real x = ox - sx * rule.t[i] * dx;
          const Real w = wy * rule.w[i] * (1.0L - rule.t[i]);
          const Real r2 = x * x + y * y, r = std::sqrt(r2);
          const Real wr = w / r, wr3 = wr / r2;
          s.inv_r += wr;
          s.xx += wr3 * x * x;
          s.yy += wr3 * y * y;
          s.xy += wr3 * x * y;
          if (coupled) {
            s.x += w * x / r2;
            s.y += w * y / r2;
          }
        }
      }
  HatIntegrals out;
  add_scaled(out, s, dx * dy);  // the quadrants' Jacobian
  return out;
}

/// I[f] at the offset: quadrature beyond 3 element sizes from the support, else closed forms.
HatIntegrals hat_integrals(Real ox, Real oy, Real dx, Real dy, bool coupled) {
  const Real gx = std::fabs(ox) - dx, gy = std::fabs(oy) - dy;  // gaps to the support
  const Real gap = std::sqrt(std::fmax(gx, 0.0L) * std::fmax(gx, 0.0L) +
                             std::fmax(gy, 0.0L) * std::fmax(gy, 0.0L));
  return gap >= 3.0L * std::fmax(dx, dy) ? quadrature(ox, oy, dx, dy, coupled)
                                         : closed_form(ox, oy, dx, dy, coupled);
}

bool coupling(Component c) {
  return c == Component::xn || c == Component::yn || c == Component::nx || c == Component::ny;
}

/// C_ij from the integrals (§B7; the same prefactors and signs as the constant elements, §3.2).
Real coefficient(Component c, const HatIntegrals& h, Real nu, Real k) {
  switch (c) {
    case Component::nn:
      return (1.0L - nu) / kPi * h.inv_r;
    case Component::xx:
      return ((1.0L - nu) * h.inv_r + nu * h.xx) / kPi;
    case Component::yy:
      return ((1.0L - nu) * h.inv_r + nu * h.yy) / kPi;
    case Component::xy:
    case Component::yx:
      return nu / kPi * h.xy;
    case Component::nx:
      return k / kPi * h.x;
    case Component::ny:
      return k / kPi * h.y;
    case Component::xn:
      return -k / kPi * h.x;
    case Component::yn:
      return -k / kPi * h.y;
  }
  return 0.0L;
}

/// Sign of component c under x → −x (sx) and y → −y (sy) for the unshifted kernel.
double parity(Component c, int sx, int sy) {
  switch (c) {
    case Component::xy:
    case Component::yx:
      return sx * sy;
    case Component::xn:
    case Component::nx:
      return sx;
    case Component::yn:
    case Component::ny:
      return sy;
    default:
      return 1.0;
  }
}

}  // namespace

double bilinear_coefficient(Component c, double ox, double oy, double dx, double dy, double nu,
                            double k) {
  const bool coupled = std::fabs(k) >= kCouplingThreshold;
  if (coupling(c) && !coupled) return 0.0;
  return static_cast<double>(coefficient(c, hat_integrals(ox, oy, dx, dy, coupled), nu, k));
}

std::vector<Kernel> bilinear_kernels(const std::vector<Component>& cs, const Grid& grid,
                                     const CombinedMaterial& material, double shift_x,
                                     double shift_y) {
  std::vector<Kernel> kernels(cs.size(), Kernel(grid.mx, grid.my));
  const bool coupled = is_coupled(material);
  const Real nu = material.nu, k = material.k, g = material.g;
  // Unshifted: one quadrant, mirrored with each component's parity, so that the symmetries
  // (C_nn even, C_xy odd, …) hold exactly and odd components vanish on their axes.
  const bool mirror = shift_x == 0.0 && shift_y == 0.0;
  const int x0 = mirror ? 0 : -(grid.mx - 1), y0 = mirror ? 0 : -(grid.my - 1);
  for (int diy = y0; diy < grid.my; ++diy)
    for (int dix = x0; dix < grid.mx; ++dix) {
      const HatIntegrals h = hat_integrals(
          Real(dix) * grid.dx + shift_x, Real(diy) * grid.dy + shift_y, grid.dx, grid.dy, coupled);
      for (std::size_t q = 0; q < cs.size(); ++q) {
        const Component c = cs[q];
        if (coupling(c) && !coupled) continue;  // stays zero
        const double v = static_cast<double>(coefficient(c, h, nu, k) / g);
        Kernel& kernel = kernels[q];
        if (!mirror) {
          kernel.at(dix, diy) = v;
          continue;
        }
        const double px = dix == 0 ? std::fmax(parity(c, -1, 1), 0.0) : 1.0;
        const double py = diy == 0 ? std::fmax(parity(c, 1, -1), 0.0) : 1.0;
        kernel.at(dix, diy) = px * py * v;
        kernel.at(-dix, diy) = px * py * parity(c, -1, 1) * v;
        kernel.at(dix, -diy) = px * py * parity(c, 1, -1) * v;
        kernel.at(-dix, -diy) = px * py * parity(c, -1, -1) * v;
      }
    }
  return kernels;
}

}  // namespace rollcontact::elastic
