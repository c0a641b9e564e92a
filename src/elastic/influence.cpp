// Closed-form influence coefficients of piecewise-constant tractions (spec/physics.md §3.2).
//
// Precision: the coefficient is a corner sum ⟦F⟧ of four terms that are much larger than the
// result for elongated elements (a 2-D strip of dx = 0.001, dy = 1000 has terms ~ 3e3 and a
// result ~ 1e-2). The corner function is therefore evaluated in long double (x86-64: 64-bit
// mantissa), and X + R, Y + R are formed without cancellation when X or Y is negative
// (X + R = Y²/(R − X)); naively, Y + R at Y = −dy/2 in such a strip loses 4 of its 16 digits.
// Measured against 40-digit references (C_nn of that strip): double 5e-11 relative error, long
// double 2e-14; for dx = 0.04, dy = 200: 2e-13 and 2e-16.

#include "elastic/influence.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <vector>

#include "elastic/viscous_kernel.hpp"
#include "rollcontact/errors.hpp"

namespace rollcontact::elastic {

namespace {

using Real = long double;
constexpr Real kPi = 3.141592653589793238462643383279502884L;

/// The component whose corner function is evaluated, and the sign of the result relative to it.
struct BaseComponent {
  Component base;
  double sign;
};

BaseComponent base_of(Component c) {
  switch (c) {
    case Component::nx:
      return {Component::xn, -1.0};
    case Component::ny:
      return {Component::yn, -1.0};
    case Component::yx:
      return {Component::xy, 1.0};
    default:
      return {c, 1.0};
  }
}

bool is_coupling(Component c) {
  return c == Component::xn || c == Component::yn || c == Component::nx || c == Component::ny;
}

/// Everything the corner function needs besides the corner (X, Y).
struct CornerContext {
  Component base;
  Real nu;
  Real log_floor;  ///< log terms vanish below this argument (δx·1e−10)
  Real atan_eps;   ///< added to atan denominators (δx·1e−20)
};

/// a + √(a² + b²) with r = √(a² + b²), accurate also for a < 0 (no cancellation).
Real plus_r(Real a, Real b, Real r) {
  return a >= 0 ? a + r : (b * b) / (r - a);
}

Real guarded_log(Real arg, Real floor) {
  return arg < floor ? 0.0L : std::log(arg);
}

/// The antiderivative F(X, Y) of the base component (prefactor excluded), see the table in §3.2.
Real corner(const CornerContext& ctx, Real x, Real y) {
  const Real r = std::sqrt(x * x + y * y);
  switch (ctx.base) {
    case Component::nn:
    case Component::xx:
    case Component::yy: {
      const Real j1 = y * guarded_log(plus_r(x, y, r), ctx.log_floor);
      const Real j2 = x * guarded_log(plus_r(y, x, r), ctx.log_floor);
      if (ctx.base == Component::nn) return j1 + j2;
      if (ctx.base == Component::xx) return j1 + (1.0L - ctx.nu) * j2;
      return j2 + (1.0L - ctx.nu) * j1;
    }
    case Component::xy:
      return r;
    case Component::xn:
      return y * guarded_log(r, ctx.log_floor) + x * std::atan(y / (x + ctx.atan_eps));
    case Component::yn:
      return x * guarded_log(r, ctx.log_floor) + y * std::atan(x / (y + ctx.atan_eps));
    default:
      return 0.0L;  // unreachable: derived components are mapped by base_of
  }
}

/// Factor in front of the corner sum of the base component.
Real prefactor(Component base, Real nu, Real k) {
  switch (base) {
    case Component::nn:
      return (1.0L - nu) / kPi;
    case Component::xx:
    case Component::yy:
      return 1.0L / kPi;
    case Component::xy:
      return -nu / kPi;
    default:  // xn, yn
      return -k / kPi;
  }
}

}  // namespace

double influence_coefficient(Component c, double ox, double oy, double dx, double dy, double nu,
                             double k) {
  if (is_coupling(c) && std::abs(k) < kCouplingThreshold) return 0.0;
  const BaseComponent b = base_of(c);
  const CornerContext ctx{b.base, nu, Real(dx) * 1e-10L, Real(dx) * 1e-20L};
  const Real hx = 0.5L * dx, hy = 0.5L * dy;
  const Real xp = Real(ox) + hx, xm = Real(ox) - hx;
  const Real yp = Real(oy) + hy, ym = Real(oy) - hy;
  const Real sum =
      (corner(ctx, xp, yp) - corner(ctx, xp, ym)) - (corner(ctx, xm, yp) - corner(ctx, xm, ym));
  return b.sign * static_cast<double>(prefactor(b.base, nu, k) * sum);
}

Kernel::Kernel(int mx, int my) : mx_(mx), my_(my) {
  if (mx < 1 || my < 1) {
    throw ProblemError("influence kernel: grid must have at least 1 x 1 elements");
  }
  data_.assign(static_cast<std::size_t>(2 * mx - 1) * static_cast<std::size_t>(2 * my - 1), 0.0);
}

namespace {

/// An interfacial layer (M=4) shears by (h/G₃)·p_t under its own element only: u_x, u_y get
/// h/G₃ at the offset whose (shifted) observation point lies in the source element.
void add_layer_compliance(Component c, const Grid& grid, const CombinedMaterial& material,
                          double shift_x, double shift_y, Kernel& kernel) {
  const double compliance = c == Component::nn ? material.normal_layer_compliance
                            : c == Component::xx || c == Component::yy ? material.layer_compliance
                                                                       : 0.0;
  if (compliance == 0.0) return;
  // dix·dx + shift_x ∈ [−dx/2, dx/2): half-open, so that a point on an element edge belongs to
  // one element (a rolling step of exactly one element lands on the neighbour's centre).
  const auto offset = [](double shift, double d) {
    return static_cast<int>(std::ceil(-0.5 - shift / d - 1e-9));
  };
  const int dix = offset(shift_x, grid.dx), diy = offset(shift_y, grid.dy);
  if (std::abs(dix) < grid.mx && std::abs(diy) < grid.my) kernel.at(dix, diy) += compliance;
}

/// The corner function on a lattice of corners, with what mirrored corners share computed once.
/// r = √(X² + Y²), L1 = log(X + R) (sees Y only as Y²) and L2 = log(Y + R) (sees X only as X²)
/// are the same bits at (X, ±Y) resp. (±X, Y) — plus_r forms the cancelling sum from the
/// square of the other coordinate — so on a lattice symmetric about 0 (no rolling shift) half
/// the logarithms, which dominate the set-up, are copies. F is then formed by the operations of
/// corner() itself: kernels are bit for bit those of the plain evaluation.
class CornerLattice {
 public:
  /// `share`: false evaluates corner() at every corner (the reference of the tests).
  CornerLattice(const CornerContext& ctx, std::vector<Real> xs, bool share)
      : ctx_(ctx),
        xs_(std::move(xs)),
        share_(share),
        x_symmetric_(share && mirrored(xs_)),
        r_(xs_.size()),
        l1_(r_.size()),
        l2_(r_.size()),
        f_(r_.size()) {}

  /// True when v[n−1−i] = −v[i] exactly for all i.
  static bool mirrored(const std::vector<Real>& v) {
    for (std::size_t i = 0, n = v.size(); i < n; ++i)
      if (v[n - 1 - i] != -v[i]) return false;
    return true;
  }

  /// Differences F(X_{i+1}, y) − F(X_i, y) of the corner row at y.
  void row(Real y, std::vector<Real>& out) {
    if (split()) {
      radii_and_l1(y);
      finish_row(y, out);
      return;
    }
    for (std::size_t i = 0; i < xs_.size(); ++i) f_[i] = corner(ctx_, xs_[i], y);
    differences(out);
  }

  /// The rows at y_low = −y_high and y_high, which share r and L1.
  void row_pair(Real y_low, Real y_high, std::vector<Real>& low, std::vector<Real>& high) {
    if (!split()) {
      row(y_low, low);
      row(y_high, high);
      return;
    }
    radii_and_l1(y_high);
    finish_row(y_low, low);
    finish_row(y_high, high);
  }

 private:
  /// nn, xx, yy: F from r, L1, L2; xy: F = r. The couplings take corner() as it is.
  bool split() const noexcept {
    return share_ && (ctx_.base == Component::nn || ctx_.base == Component::xx ||
                      ctx_.base == Component::yy || ctx_.base == Component::xy);
  }
  bool logs() const noexcept { return ctx_.base != Component::xy; }

  /// r and L1 of every corner of the row at y (the same at −y).
  void radii_and_l1(Real y) {
    const std::size_t n = xs_.size();
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t m = n - 1 - i;
      if (x_symmetric_ && m < i) {
        r_[i] = r_[m];
      } else {
        const Real x = xs_[i];
        r_[i] = std::sqrt(x * x + y * y);
      }
      if (logs()) l1_[i] = guarded_log(plus_r(xs_[i], y, r_[i]), ctx_.log_floor);
    }
  }

  /// L2 (halved on a mirrored x-lattice) and F of the row at y, then its differences.
  void finish_row(Real y, std::vector<Real>& out) {
    const std::size_t n = xs_.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Real x = xs_[i], r = r_[i];
      if (!logs()) {
        f_[i] = r;
        continue;
      }
      const std::size_t m = n - 1 - i;
      l2_[i] = x_symmetric_ && m < i ? l2_[m] : guarded_log(plus_r(y, x, r), ctx_.log_floor);
      // corner()'s operations, term for term.
      const Real j1 = y * l1_[i];
      const Real j2 = x * l2_[i];
      if (ctx_.base == Component::nn)
        f_[i] = j1 + j2;
      else if (ctx_.base == Component::xx)
        f_[i] = j1 + (1.0L - ctx_.nu) * j2;
      else
        f_[i] = j2 + (1.0L - ctx_.nu) * j1;
    }
    differences(out);
  }

  void differences(std::vector<Real>& out) const {
    for (std::size_t i = 0; i + 1 < f_.size(); ++i) out[i] = f_[i + 1] - f_[i];
  }

  CornerContext ctx_;
  std::vector<Real> xs_;
  bool share_, x_symmetric_;
  std::vector<Real> r_, l1_, l2_, f_;
};

/// The corner sums of component c on the grid, divided by G; `log_floor` [mm]: log terms whose
/// argument lies below it count as 0.
Kernel corner_sum_kernel(Component c, const Grid& grid, const CombinedMaterial& material,
                         double shift_x, double shift_y, Real log_floor, bool share = true) {
  const int mx = grid.mx, my = grid.my;
  Kernel kernel(mx, my);
  if (is_coupling(c) && !is_coupled(material)) return kernel;

  const BaseComponent b = base_of(c);
  const Real dx = grid.dx, dy = grid.dy;
  const CornerContext ctx{b.base, material.nu, log_floor, dx * 1e-20L};
  const Real factor = b.sign * prefactor(b.base, material.nu, material.k) / Real(material.g);

  // Neighbouring offsets share corners: F is tabulated once per corner instead of four times.
  // Corner i in x sits at X_i = (i − mx + ½)·dx + shift_x, i = 0 … 2mx−1; offset dix has
  // X₋ = X_{dix+mx−1} and X₊ = X_{dix+mx} (likewise in y). Offset diy is the difference of the
  // x-differences of corner rows my+diy and my+diy−1.
  const int ncx = 2 * mx;
  std::vector<Real> xs(static_cast<std::size_t>(ncx)), ys(static_cast<std::size_t>(2 * my));
  for (int i = 0; i < ncx; ++i)
    xs[static_cast<std::size_t>(i)] = (Real(i - mx) + 0.5L) * dx + shift_x;
  for (int j = 0; j < 2 * my; ++j)
    ys[static_cast<std::size_t>(j)] = (Real(j - my) + 0.5L) * dy + shift_y;
  CornerLattice lattice(ctx, xs, share);
  const auto store = [&](int diy, const std::vector<Real>& upper, const std::vector<Real>& lower) {
    for (int i = 0; i + 1 < ncx; ++i) {
      const std::size_t s = static_cast<std::size_t>(i);
      kernel.at(i - (mx - 1), diy) = static_cast<double>(factor * (upper[s] - lower[s]));
    }
  };
  const auto y = [&](int j) { return ys[static_cast<std::size_t>(j)]; };
  std::vector<Real> prev(static_cast<std::size_t>(ncx - 1)), cur(prev.size());
  if (!share || !CornerLattice::mirrored(ys)) {
    lattice.row(y(0), prev);
    for (int j = 1; j < 2 * my; ++j) {
      lattice.row(y(j), cur);
      store(j - my, cur, prev);
      prev.swap(cur);
    }
    return kernel;
  }
  // Mirrored rows my−1−k and my+k together, outwards from the centre: offsets ±k.
  std::vector<Real> prev_low(prev.size()), cur_low(prev.size());
  lattice.row_pair(y(my - 1), y(my), prev_low, prev);
  store(0, prev, prev_low);
  for (int k = 1; k < my; ++k) {
    lattice.row_pair(y(my - 1 - k), y(my + k), cur_low, cur);
    store(k, cur, prev);
    store(-k, prev_low, cur_low);
    prev.swap(cur);
    prev_low.swap(cur_low);
  }
  return kernel;
}

void check_grid(const CombinedMaterial& material, const Grid& grid) {
  if (!(material.g > 0.0)) throw ProblemError("influence kernel: combined G must be positive");
  if (!(grid.dx > 0.0 && grid.dy > 0.0)) {
    throw ProblemError("influence kernel: element sizes must be positive");
  }
}

}  // namespace

Kernel make_continuous_kernel(Component c, const Grid& grid, const CombinedMaterial& material,
                              double shift_x, double shift_y) {
  check_grid(material, grid);
  return corner_sum_kernel(c, grid, material, shift_x, shift_y, std::numeric_limits<Real>::min());
}

Kernel make_unshared_kernel(Component c, const Grid& grid, const CombinedMaterial& material,
                            double shift_x, double shift_y) {
  check_grid(material, grid);
  return corner_sum_kernel(c, grid, material, shift_x, shift_y, Real(grid.dx) * 1e-10L, false);
}

Kernel make_kernel(Component c, const Grid& grid, const CombinedMaterial& material, double shift_x,
                   double shift_y) {
  check_grid(material, grid);
  Kernel kernel = corner_sum_kernel(c, grid, material, shift_x, shift_y, Real(grid.dx) * 1e-10L);
  add_layer_compliance(c, grid, material, shift_x, shift_y, kernel);
  if (material.viscoelastic()) add_viscous_parts(c, grid, material, shift_x, shift_y, kernel);
  // Element sizes far outside what the closed forms can represent (e.g. DX = 1e30 mm) overflow
  // to inf or NaN: reject the grid here rather than report a NaN force later.
  for (double v : kernel.data())
    if (!std::isfinite(v)) {
      throw GeometryError(
          fmt::format("element size DX = {} mm, DY = {} mm overflows the influence coefficients",
                      grid.dx, grid.dy));
    }
  return kernel;
}

}  // namespace rollcontact::elastic
