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

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <vector>

#include "elastic/bilinear_kernel.hpp"
#include "elastic/inclination_correction.hpp"
#include "elastic/table_kernel.hpp"
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

/// The corner function on a lattice of corners, with what mirrored corners and components share
/// computed once. r = √(X² + Y²), L1 = log(X + R) (sees Y only as Y²) and L2 = log(Y + R) (sees
/// X only as X²) are the same bits at (X, ±Y) resp. (±X, Y) — plus_r forms the cancelling sum
/// from the square of the other coordinate — so on a lattice symmetric about 0 (no rolling
/// shift) half the logarithms, which dominate the set-up, are copies; and nn, xx, yy are formed
/// from the same r, L1, L2 (xy from r alone). F is then formed by the operations of corner()
/// itself: kernels are bit for bit those of the plain evaluation, one component at a time.
class CornerLattice {
 public:
  using Rows = std::vector<std::vector<Real>>;  ///< one row per component

  /// One context per component (all with the same ν and floors). `share`: false evaluates
  /// corner() at every corner for every component (the reference of the tests).
  CornerLattice(std::vector<CornerContext> ctxs, std::vector<Real> xs, bool share)
      : ctxs_(std::move(ctxs)),
        xs_(std::move(xs)),
        split_(share && std::all_of(ctxs_.begin(), ctxs_.end(), splits)),
        logs_(std::any_of(ctxs_.begin(), ctxs_.end(),
                          [](const CornerContext& c) { return c.base != Component::xy; })),
        x_symmetric_(split_ && mirrored(xs_)),
        r_(xs_.size()),
        l1_(r_.size()),
        l2_(r_.size()),
        f_(ctxs_.size(), std::vector<Real>(r_.size())) {}

  /// True when v[n−1−i] = −v[i] exactly for all i.
  static bool mirrored(const std::vector<Real>& v) {
    for (std::size_t i = 0, n = v.size(); i < n; ++i)
      if (v[n - 1 - i] != -v[i]) return false;
    return true;
  }
  /// nn, xx, yy: F from r, L1, L2; xy: F = r. The couplings take corner() as it is.
  static bool splits(const CornerContext& c) {
    return c.base == Component::nn || c.base == Component::xx || c.base == Component::yy ||
           c.base == Component::xy;
  }
  bool split() const noexcept { return split_; }

  /// Differences F(X_{i+1}, y) − F(X_i, y) of the corner row at y, per component.
  void row(Real y, Rows& out) {
    if (split_) {
      radii_and_l1(y);
      finish_row(y, out);
      return;
    }
    for (std::size_t k = 0; k < ctxs_.size(); ++k)
      for (std::size_t i = 0; i < xs_.size(); ++i) f_[k][i] = corner(ctxs_[k], xs_[i], y);
    differences(out);
  }

  /// The rows at y_low = −y_high and y_high, which share r and L1.
  void row_pair(Real y_low, Real y_high, Rows& low, Rows& high) {
    if (!split_) {
      row(y_low, low);
      row(y_high, high);
      return;
    }
    radii_and_l1(y_high);
    finish_row(y_low, low);
    finish_row(y_high, high);
  }

  /// values() at y_low = −y_high and y_high, which share r and L1 on a split lattice.
  void values_pair(Real y_low, Real y_high, Rows& low, Rows& high) {
    if (!split_) {
      low = values(y_low);
      high = values(y_high);
      return;
    }
    radii_and_l1(y_high);
    corner_values(y_low);
    low = f_;
    corner_values(y_high);
    high = f_;
  }

  /// F itself at every corner of the row at y, per component (not differenced).
  const Rows& values(Real y) {
    if (split_) {
      radii_and_l1(y);
      corner_values(y);
    } else {
      for (std::size_t k = 0; k < ctxs_.size(); ++k)
        for (std::size_t i = 0; i < xs_.size(); ++i) f_[k][i] = corner(ctxs_[k], xs_[i], y);
    }
    return f_;
  }

 private:
  /// r and L1 of every corner of the row at y (the same at −y).
  void radii_and_l1(Real y) {
    const std::size_t n = xs_.size();
    const Real log_floor = ctxs_.front().log_floor;
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t m = n - 1 - i;
      if (x_symmetric_ && m < i) {
        r_[i] = r_[m];
      } else {
        const Real x = xs_[i];
        r_[i] = std::sqrt(x * x + y * y);
      }
      if (logs_) l1_[i] = guarded_log(plus_r(xs_[i], y, r_[i]), log_floor);
    }
  }

  /// L2 (halved on a mirrored x-lattice) and F of the row at y, then its differences.
  void finish_row(Real y, Rows& out) {
    corner_values(y);
    differences(out);
  }

  /// L2 and F of the row at y, after radii_and_l1(y).
  void corner_values(Real y) {
    const std::size_t n = xs_.size();
    const Real log_floor = ctxs_.front().log_floor;
    for (std::size_t i = 0; i < n; ++i) {
      const Real x = xs_[i];
      const std::size_t m = n - 1 - i;
      if (logs_)
        l2_[i] = x_symmetric_ && m < i ? l2_[m] : guarded_log(plus_r(y, x, r_[i]), log_floor);
      // corner()'s operations, term for term.
      const Real j1 = logs_ ? y * l1_[i] : 0.0L;
      const Real j2 = logs_ ? x * l2_[i] : 0.0L;
      for (std::size_t k = 0; k < ctxs_.size(); ++k) {
        const CornerContext& c = ctxs_[k];
        Real& f = f_[k][i];
        if (c.base == Component::xy)
          f = r_[i];
        else if (c.base == Component::nn)
          f = j1 + j2;
        else if (c.base == Component::xx)
          f = j1 + (1.0L - c.nu) * j2;
        else
          f = j2 + (1.0L - c.nu) * j1;
      }
    }
  }

  void differences(Rows& out) const {
    for (std::size_t k = 0; k < f_.size(); ++k)
      for (std::size_t i = 0; i + 1 < f_[k].size(); ++i) out[k][i] = f_[k][i + 1] - f_[k][i];
  }

  std::vector<CornerContext> ctxs_;
  std::vector<Real> xs_;
  bool split_, logs_, x_symmetric_;
  std::vector<Real> r_, l1_, l2_;
  Rows f_;
};

/// The terms of components `cs` on one corner lattice: their corner contexts, the factors
/// sign·prefactor/G of their sums, and which of cs each is. Couplings of an uncoupled material
/// have none (their kernels stay zero).
struct LatticeTerms {
  std::vector<CornerContext> ctxs;
  std::vector<Real> factors;
  std::vector<std::size_t> which;
};

LatticeTerms lattice_terms(const std::vector<Component>& cs, const CombinedMaterial& material,
                           Real log_floor, Real dx) {
  LatticeTerms t;
  for (std::size_t q = 0; q < cs.size(); ++q) {
    if (is_coupling(cs[q]) && !is_coupled(material)) continue;
    const BaseComponent b = base_of(cs[q]);
    t.ctxs.push_back({b.base, material.nu, log_floor, dx * 1e-20L});
    t.factors.push_back(b.sign * prefactor(b.base, material.nu, material.k) / Real(material.g));
    t.which.push_back(q);
  }
  return t;
}

/// The lattices the components of one call share, as indices into cs: nn, xx, yy and xy on one
/// (their logarithms; first, possibly empty), each coupling on its own.
std::vector<std::vector<std::size_t>> lattice_groups(const std::vector<Component>& cs) {
  std::vector<std::vector<std::size_t>> groups(1);
  for (std::size_t q = 0; q < cs.size(); ++q) {
    if (CornerLattice::splits({base_of(cs[q]).base, 0.0L, 0.0L, 0.0L}))
      groups.front().push_back(q);
    else
      groups.push_back({q});
  }
  return groups;
}

/// The corner ordinates (j − my + ½)·dy + shift_y, j = 0 … 2my−1 [mm].
std::vector<Real> corner_ordinates(int my, Real dy, Real shift_y) {
  std::vector<Real> ys(static_cast<std::size_t>(2 * my));
  for (int j = 0; j < 2 * my; ++j)
    ys[static_cast<std::size_t>(j)] = (Real(j - my) + 0.5L) * dy + shift_y;
  return ys;
}

/// Walks the corner rows j = 0 … 2my−1 and hands store(diy, upper, lower) rows my+diy and
/// my+diy−1 for every offset diy. row(j, out) makes row j. Where the rows are mirrored about
/// y = 0 (no lateral shift), pair(j_low, j_high, low, high) makes rows my−1−k and my+k together,
/// outwards from the centre (they share r and L1): the same values as row by row, bit for bit.
template <class Row, class Pair, class Store>
void walk_corner_rows(int my, bool mirrored, const CornerLattice::Rows& blank, Row&& row,
                      Pair&& pair, Store&& store) {
  CornerLattice::Rows prev = blank, cur = blank;
  if (!mirrored) {
    row(0, prev);
    for (int j = 1; j < 2 * my; ++j) {
      row(j, cur);
      store(j - my, cur, prev);
      prev.swap(cur);
    }
    return;
  }
  CornerLattice::Rows prev_low = blank, cur_low = blank;
  pair(my - 1, my, prev_low, prev);
  store(0, prev, prev_low);
  for (int k = 1; k < my; ++k) {
    pair(my - 1 - k, my + k, cur_low, cur);
    store(k, cur, prev);
    store(-k, prev_low, cur_low);
    prev.swap(cur);
    prev_low.swap(cur_low);
  }
}

/// The corner sums of the components `cs` on the grid, divided by G, tabulated together on one
/// corner lattice; `log_floor` [mm]: log terms whose argument lies below it count as 0.
std::vector<Kernel> corner_sum_kernels(const std::vector<Component>& cs, const Grid& grid,
                                       const CombinedMaterial& material, double shift_x,
                                       double shift_y, Real log_floor, bool share = true) {
  const int mx = grid.mx, my = grid.my;
  std::vector<Kernel> kernels(cs.size(), Kernel(mx, my));
  const LatticeTerms terms = lattice_terms(cs, material, log_floor, grid.dx);
  if (terms.ctxs.empty()) return kernels;

  // Neighbouring offsets share corners: F is tabulated once per corner instead of four times.
  // Corner i in x sits at X_i = (i − mx + ½)·dx + shift_x, i = 0 … 2mx−1; offset dix has
  // X₋ = X_{dix+mx−1} and X₊ = X_{dix+mx} (likewise in y). Offset diy is the difference of the
  // x-differences of corner rows my+diy and my+diy−1.
  const int ncx = 2 * mx;
  std::vector<Real> xs(static_cast<std::size_t>(ncx));
  for (int i = 0; i < ncx; ++i)
    xs[static_cast<std::size_t>(i)] = (Real(i - mx) + 0.5L) * Real(grid.dx) + shift_x;
  const std::vector<Real> ys = corner_ordinates(my, grid.dy, shift_y);
  CornerLattice lattice(terms.ctxs, xs, share);
  using Rows = CornerLattice::Rows;
  const auto store = [&](int diy, const Rows& upper, const Rows& lower) {
    for (std::size_t k = 0; k < terms.ctxs.size(); ++k) {
      Kernel& kernel = kernels[terms.which[k]];
      for (int i = 0; i + 1 < ncx; ++i) {
        const std::size_t s = static_cast<std::size_t>(i);
        kernel.at(i - (mx - 1), diy) =
            static_cast<double>(terms.factors[k] * (upper[k][s] - lower[k][s]));
      }
    }
  };
  const auto y = [&](int j) { return ys[static_cast<std::size_t>(j)]; };
  walk_corner_rows(
      my, lattice.split() && CornerLattice::mirrored(ys),
      Rows(terms.ctxs.size(), std::vector<Real>(static_cast<std::size_t>(ncx - 1))),
      [&](int j, Rows& out) { lattice.row(y(j), out); },
      [&](int jl, int jh, Rows& low, Rows& high) { lattice.row_pair(y(jl), y(jh), low, high); },
      store);
  return kernels;
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
  return std::move(
      corner_sum_kernels({c}, grid, material, shift_x, shift_y, std::numeric_limits<Real>::min())
          .front());
}

std::vector<Kernel> make_integrated_kernels(const std::vector<Component>& cs, const Grid& grid,
                                            const CombinedMaterial& material, double shift_y,
                                            const CornerXRule& rule) {
  check_grid(material, grid);
  const int mx = grid.mx, my = grid.my;
  std::vector<Kernel> kernels(cs.size(), Kernel(mx, my));
  const auto n = static_cast<std::size_t>(2 * mx);
  if (rule.begin.size() != n + 1 || rule.carry.size() != n ||
      rule.begin.back() > rule.x_mm.size() || rule.weight.size() != rule.x_mm.size())
    throw std::logic_error("make_integrated_kernels: the rule does not fit the grid's corners");
  const std::vector<Real> ys = corner_ordinates(my, grid.dy, shift_y);
  const auto y = [&](int j) { return ys[static_cast<std::size_t>(j)]; };
  for (const std::vector<std::size_t>& group : lattice_groups(cs)) {
    std::vector<Component> members;
    for (std::size_t q : group) members.push_back(cs[q]);
    // Continuous in x (no log guard), as the history integrals need (make_continuous_kernel).
    const LatticeTerms terms =
        lattice_terms(members, material, std::numeric_limits<Real>::min(), grid.dx);
    if (terms.ctxs.empty()) continue;
    CornerLattice lattice(terms.ctxs, rule.x_mm, true);
    using Rows = CornerLattice::Rows;
    // G of a row from F at the rule's abscissae, corner by corner from the last.
    const auto integrate = [&](const Rows& f, Rows& g) {
      for (std::size_t k = 0; k < terms.ctxs.size(); ++k) {
        Real carried = 0.0L;
        for (std::size_t i = n; i-- > 0;) {
          Real sum = 0.0L;
          for (std::size_t m = rule.begin[i]; m < rule.begin[i + 1]; ++m)
            sum += rule.weight[m] * f[k][m];
          carried = sum + rule.carry[i] * carried;
          g[k][i] = carried;
        }
      }
    };
    const auto store = [&](int diy, const Rows& upper, const Rows& lower) {
      for (std::size_t k = 0; k < terms.ctxs.size(); ++k)
        for (std::size_t i = 0; i + 1 < n; ++i)
          kernels[group[terms.which[k]]].at(static_cast<int>(i) - (mx - 1), diy) =
              static_cast<double>(terms.factors[k] * ((upper[k][i + 1] - upper[k][i]) -
                                                      (lower[k][i + 1] - lower[k][i])));
    };
    Rows f_low, f_high;
    walk_corner_rows(
        my, lattice.split() && CornerLattice::mirrored(ys),
        Rows(terms.ctxs.size(), std::vector<Real>(n)),
        [&](int j, Rows& out) { integrate(lattice.values(y(j)), out); },
        [&](int jl, int jh, Rows& low, Rows& high) {
          lattice.values_pair(y(jl), y(jh), f_low, f_high);
          integrate(f_low, low);
          integrate(f_high, high);
        },
        store);
  }
  return kernels;
}

Kernel make_unshared_kernel(Component c, const Grid& grid, const CombinedMaterial& material,
                            double shift_x, double shift_y) {
  check_grid(material, grid);
  return std::move(
      corner_sum_kernels({c}, grid, material, shift_x, shift_y, Real(grid.dx) * 1e-10L, false)
          .front());
}

namespace {

/// What make_kernels adds to the corner sums — an interfacial layer's compliance, the viscous
/// parts of viscoelastic bodies (all components on one history lattice) —, and its check.
void finish_kernels(const std::vector<Component>& cs, const Grid& grid,
                    const CombinedMaterial& material, double shift_x, double shift_y,
                    std::vector<Kernel>& kernels) {
  for (std::size_t q = 0; q < cs.size(); ++q)
    add_layer_compliance(cs[q], grid, material, shift_x, shift_y, kernels[q]);
  if (material.viscoelastic()) add_viscous_parts(cs, grid, material, shift_x, shift_y, kernels);
  // Element sizes far outside what the closed forms can represent (e.g. DX = 1e30 mm) overflow
  // to inf or NaN: reject the grid here rather than report a NaN force later.
  for (const Kernel& kernel : kernels)
    for (double v : kernel.data())
      if (!std::isfinite(v)) {
        throw GeometryError(
            fmt::format("element size DX = {} mm, DY = {} mm overflows the influence coefficients",
                        grid.dx, grid.dy));
      }
}

}  // namespace

std::vector<Kernel> make_kernels(const std::vector<Component>& cs, const Grid& grid,
                                 const CombinedMaterial& material, double shift_x, double shift_y) {
  check_grid(material, grid);
  if (material.inclination_corrected())
    return inclination_corrected_kernels(cs, grid, material, shift_x, shift_y);
  if (material.table) {
    std::vector<Kernel> out;
    out.reserve(cs.size());
    for (Component c : cs) out.push_back(table_kernel(c, grid, material, shift_x, shift_y));
    finish_kernels(cs, grid, material, shift_x, shift_y, out);
    return out;
  }
  if (material.elements == model::TractionElements::bilinear) {
    std::vector<Kernel> out = bilinear_kernels(cs, grid, material, shift_x, shift_y);
    finish_kernels(cs, grid, material, shift_x, shift_y, out);
    return out;
  }
  const Real floor = Real(grid.dx) * 1e-10L;
  std::vector<Kernel> out(cs.size(), Kernel(grid.mx, grid.my));
  for (const std::vector<std::size_t>& group : lattice_groups(cs)) {
    std::vector<Component> members;
    for (std::size_t q : group) members.push_back(cs[q]);
    std::vector<Kernel> kernels =
        corner_sum_kernels(members, grid, material, shift_x, shift_y, floor);
    for (std::size_t k = 0; k < group.size(); ++k) out[group[k]] = std::move(kernels[k]);
  }
  finish_kernels(cs, grid, material, shift_x, shift_y, out);
  return out;
}

Kernel make_kernel(Component c, const Grid& grid, const CombinedMaterial& material, double shift_x,
                   double shift_y) {
  return std::move(make_kernels({c}, grid, material, shift_x, shift_y).front());
}

}  // namespace rollcontact::elastic
