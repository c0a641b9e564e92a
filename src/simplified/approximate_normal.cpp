// KPEC and modified ANALYN (spec/physics.md §7.3).

#include "simplified/approximate_normal.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>

#include "elastic/influence.hpp"
#include "geometry/hertz.hpp"

namespace rollcontact::simplified {

namespace {

/// Gaps at or above this are excluded elements (h = 1e30), never in contact.
constexpr double kExcluded = 1e29;
/// Smallest equivalent curvature [1/mm] (a flat direction would give an infinite semi-axis).
constexpr double kMinCurvature = 1e-4;

struct Deepest {
  std::size_t index = 0;
  int ix = 0, iy = 0;
  double h_min = 0.0;  ///< min h_tot (< 0 when the bodies interpenetrate) [mm]
};

Deepest deepest_point(const Grid& grid, const std::vector<double>& h) {
  Deepest d;
  d.h_min = h.empty() ? 0.0 : h[0];
  for (std::size_t i = 1; i < h.size(); ++i)
    if (h[i] < d.h_min) {
      d.h_min = h[i];
      d.index = i;
    }
  d.ix = static_cast<int>(d.index % static_cast<std::size_t>(grid.mx));
  d.iy = static_cast<int>(d.index / static_cast<std::size_t>(grid.mx));
  return d;
}

double gap(const Grid& grid, const std::vector<double>& h, int ix, int iy) {
  return h[grid.index(ix, iy)];
}

/// A1 of the parabola through the deepest point and the nearest points of its row outside
/// {h_tot ≤ level} (the row's ends when the region reaches them).
double row_curvature(const Grid& grid, const std::vector<double>& h, const Deepest& d,
                     double level) {
  int il = d.ix - 1, ir = d.ix + 1;
  while (il > 0 && gap(grid, h, il, d.iy) <= level) --il;
  while (ir < grid.mx - 1 && gap(grid, h, ir, d.iy) <= level) ++ir;
  il = std::max(il, 0);
  ir = std::min(ir, grid.mx - 1);
  if (il == d.ix || ir == d.ix) return kMinCurvature;  // a single column: no curvature known
  const double xl = grid.x_centre(il), xm = grid.x_centre(d.ix), xr = grid.x_centre(ir);
  const double hl = gap(grid, h, il, d.iy), hm = d.h_min, hr = gap(grid, h, ir, d.iy);
  const double a1 = ((hr - hm) / (xr - xm) - (hm - hl) / (xm - xl)) / (xr - xl);
  return std::max(kMinCurvature, a1);
}

/// Where h_tot crosses `level` between element centres j_in (inside) and j_out (outside) of
/// column ix, by linear interpolation [mm].
double crossing_y(const Grid& grid, const std::vector<double>& h, int ix, int j_in, int j_out,
                  double level) {
  const double h_in = gap(grid, h, ix, j_in), h_out = gap(grid, h, ix, j_out);
  const double t = h_out >= kExcluded || h_out == h_in ? 0.5 : (level - h_in) / (h_out - h_in);
  return grid.y_centre(j_in) + t * (grid.y_centre(j_out) - grid.y_centre(j_in));
}

/// The y-extent [y_s, y_e] of {h_tot ≤ level} along the deepest point's column.
std::pair<double, double> column_extent(const Grid& grid, const std::vector<double>& h,
                                        const Deepest& d, double level) {
  int js = d.iy, je = d.iy;
  while (js > 0 && gap(grid, h, d.ix, js - 1) <= level) --js;
  while (je < grid.my - 1 && gap(grid, h, d.ix, je + 1) <= level) ++je;
  const double ys =
      js > 0 ? crossing_y(grid, h, d.ix, js, js - 1, level) : grid.y_centre(0) - 0.5 * grid.dy;
  const double ye = je < grid.my - 1 ? crossing_y(grid, h, d.ix, je, je + 1, level)
                                     : grid.y_centre(grid.my - 1) + 0.5 * grid.dy;
  return {ys, ye};
}

/// Where h_tot crosses `level` between the row's elements i_in (inside) and i_out [mm].
double crossing_x(const Grid& grid, const std::vector<double>& h, int iy, int i_in, int i_out,
                  double level) {
  const double h_in = gap(grid, h, i_in, iy), h_out = gap(grid, h, i_out, iy);
  const double t = h_out >= kExcluded || h_out == h_in ? 0.5 : (level - h_in) / (h_out - h_in);
  return grid.x_centre(i_in) + t * (grid.x_centre(i_out) - grid.x_centre(i_in));
}

/// Σ_J C_nn(I − J) s_J / G: the normal displacement at element I of the pressure field s [mm],
/// `cnn` the grid's normal kernel (already divided by G).
double displacement_at(const Grid& grid, const std::vector<double>& s, std::size_t i,
                       const elastic::Kernel& cnn) {
  const int ix = static_cast<int>(i % static_cast<std::size_t>(grid.mx));
  const int iy = static_cast<int>(i / static_cast<std::size_t>(grid.mx));
  double u = 0.0;
  for (int jy = 0; jy < grid.my; ++jy)
    for (int jx = 0; jx < grid.mx; ++jx) {
      const double v = s[grid.index(jx, jy)];
      if (v != 0.0) u += v * cnn.at(ix - jx, iy - jy);
    }
  return u;
}

double contact_modulus(const CombinedMaterial& m) {
  return m.g / (1.0 - m.nu);
}

/// ANALYN's A1 of row iy: the least-squares parabola over a symmetric window of 1 to 10 elements
/// on each side of the locus ix, widened while h_tot on both sides stays ≤ `level`.
double fitted_curvature(const Grid& grid, const std::vector<double>& h, int ix, int iy,
                        double level) {
  constexpr int kMaxHalfWidth = 10;
  int w = 1;
  while (w < kMaxHalfWidth && ix - w - 1 >= 0 && ix + w + 1 < grid.mx &&
         gap(grid, h, ix - w - 1, iy) <= level && gap(grid, h, ix + w + 1, iy) <= level)
    ++w;
  w = std::min({w, ix, grid.mx - 1 - ix});
  if (w < 1) return kMinCurvature;
  // Symmetric abscissae t = k·dx: the odd moments vanish, so the x² coefficient is
  // (n Σt²h − Σt² Σh) / (n Σt⁴ − (Σt²)²).
  double n = 0.0, st2 = 0.0, st4 = 0.0, sh = 0.0, st2h = 0.0;
  for (int k = -w; k <= w; ++k) {
    const double v = gap(grid, h, ix + k, iy);
    if (v >= kExcluded) return kMinCurvature;
    const double t2 = (k * grid.dx) * (k * grid.dx);
    n += 1.0;
    st2 += t2;
    st4 += t2 * t2;
    sh += v;
    st2h += t2 * v;
  }
  return (n * st2h - st2 * sh) / (n * st4 - st2 * st2);
}

}  // namespace

ApproximateNormal kpec_pressure(const Grid& grid, const std::vector<double>& h,
                                const CombinedMaterial& material,
                                const elastic::Kernel& normal_kernel) {
  ApproximateNormal r;
  r.pn.assign(grid.size(), 0.0);
  const Deepest d = deepest_point(grid, h);
  if (!(d.h_min < 0.0)) return r;
  const double pen = -d.h_min;
  r.pen_total = pen;

  // 1. Equivalent curvatures from the region where the interpenetration exceeds pen/2.
  const double half = 0.5 * d.h_min;
  const double a1 = row_curvature(grid, h, d, half);
  const auto [ys, ye] = column_extent(grid, h, d, half);
  const double y_mid = 0.5 * (ys + ye);
  const double b1 = std::max(kMinCurvature, (half - d.h_min) / ((ye - y_mid) * (ye - y_mid)));

  // 2. The Hertz ellipse of these curvatures at the full approach.
  r.hertz = geometry::hertz_from_curvatures(a1, b1, geometry::HertzLoad::Approach, pen,
                                            contact_modulus(material));
  const double a = r.hertz.aa, b = r.hertz.bb;

  // 3.–4. Per row the virtual penetration ε(y) that reproduces the ellipse, the contact edges
  // where h_tot = (1 − ε)·h_min, and a semi-elliptic shape over the row. ε > 1 (a row the
  // ellipse wants longer than its interpenetration: a second lobe of the gap beyond the
  // ellipse) is kept: the row's shape spans the virtual row and its pressure is cut where the
  // bodies do not interpenetrate (docs/decisions.md, KPEC c1: CONTACT's forces within 2 %).
  std::vector<double> length(static_cast<std::size_t>(grid.my), 0.0),
      middle(static_cast<std::size_t>(grid.my), 0.0);
  std::vector<char> virtual_row(static_cast<std::size_t>(grid.my), 0);
  double longest = 0.0;
  for (int iy = 0; iy < grid.my; ++iy) {
    const double s = (grid.y_centre(iy) - y_mid) / b;
    const double eps_raw = (a1 * a * a - (a1 * a * a - b1 * b * b) * s * s) / pen;
    const double eps = std::max(eps_raw, 0.0);
    const double level = (1.0 - eps) * d.h_min;
    int first = -1, last = -1;
    bool interpenetrates = false;
    for (int ix = 0; ix < grid.mx; ++ix) {
      const double v = gap(grid, h, ix, iy);
      interpenetrates = interpenetrates || v < 0.0;
      if (v <= level) {
        if (first < 0) first = ix;
        last = ix;
      }
    }
    if (eps_raw > 1.0 && interpenetrates) ++r.rows_beyond_interpenetration;
    if (first < 0 || (eps_raw > 1.0 && !interpenetrates)) continue;
    virtual_row[static_cast<std::size_t>(iy)] = eps_raw > 1.0;
    const double x_le = first > 0 ? crossing_x(grid, h, iy, first, first - 1, level)
                                  : grid.x_centre(first) - 0.5 * grid.dx;
    const double x_te = last < grid.mx - 1 ? crossing_x(grid, h, iy, last, last + 1, level)
                                           : grid.x_centre(last) + 0.5 * grid.dx;
    const auto row = static_cast<std::size_t>(iy);
    length[row] = x_te - x_le;
    middle[row] = 0.5 * (x_le + x_te);
    longest = std::max(longest, length[row]);
  }
  if (!(longest > 0.0)) return r;
  std::vector<double> shape(grid.size(), 0.0);
  for (int iy = 0; iy < grid.my; ++iy) {
    const auto row = static_cast<std::size_t>(iy);
    const double half_length = 0.5 * length[row];
    const double cut = virtual_row[row] ? 0.0 : kExcluded;
    for (int ix = 0; ix < grid.mx; ++ix) {
      const double dx = grid.x_centre(ix) - middle[row];
      const double t = half_length * half_length - dx * dx;
      if (t > 0.0 && gap(grid, h, ix, iy) < cut)
        shape[grid.index(ix, iy)] = std::sqrt(t) / (0.5 * longest);
    }
  }

  // 5. The level: the normal displacement at the deepest point equals the approach there.
  const double u = displacement_at(grid, shape, d.index, normal_kernel);
  if (!(u > 0.0)) return r;
  const double p_max = pen / u;
  for (std::size_t i = 0; i < shape.size(); ++i) r.pn[i] = p_max * shape[i];
  return r;
}

ApproximateNormal kpec_pressure(const Grid& grid, const std::vector<double>& h,
                                const CombinedMaterial& material) {
  return kpec_pressure(grid, h, material,
                       elastic::make_kernel(elastic::Component::nn, grid, material));
}

ApproximateNormal analyn_pressure(const Grid& grid, const std::vector<double>& h,
                                  const CombinedMaterial& material) {
  ApproximateNormal r;
  r.pn.assign(grid.size(), 0.0);
  const Deepest d = deepest_point(grid, h);
  if (!(d.h_min < 0.0)) return r;
  const double pen = -d.h_min;
  r.pen_total = pen;
  const double estar = contact_modulus(material);

  // Per row: the locus (deepest element), its gap above the deepest point and the x-curvature.
  const auto my = static_cast<std::size_t>(grid.my);
  std::vector<int> locus(my, 0);
  std::vector<double> row_gap(my, 0.0), a1(my, kMinCurvature), b1(my, kMinCurvature);
  for (int iy = 0; iy < grid.my; ++iy) {
    const auto row = static_cast<std::size_t>(iy);
    int best = 0;
    for (int ix = 1; ix < grid.mx; ++ix)
      if (gap(grid, h, ix, iy) < gap(grid, h, best, iy)) best = ix;
    locus[row] = best;
    row_gap[row] = gap(grid, h, best, iy) + pen;
    a1[row] = std::max(kMinCurvature, fitted_curvature(grid, h, best, iy, 0.3 * d.h_min));
  }
  // y-curvature by the second difference of the row gaps (one-sided at the grid's edges).
  for (int iy = 0; iy < grid.my; ++iy) {
    if (grid.my < 3) break;
    const int c = std::clamp(iy, 1, grid.my - 2);
    const auto lo = static_cast<std::size_t>(c - 1), mid = static_cast<std::size_t>(c),
               hi = static_cast<std::size_t>(c + 1);
    if (row_gap[lo] >= kExcluded || row_gap[hi] >= kExcluded) continue;
    const double second = row_gap[hi] - 2.0 * row_gap[mid] + row_gap[lo];
    b1[static_cast<std::size_t>(iy)] = std::max(kMinCurvature, second / (2.0 * grid.dy * grid.dy));
  }
  r.hertz = geometry::hertz_from_curvatures(a1[static_cast<std::size_t>(d.iy)],
                                            b1[static_cast<std::size_t>(d.iy)],
                                            geometry::HertzLoad::Approach, pen, estar);

  // Per row: the local Hertz problem, corrected so that a Hertzian gap gives Hertz' pressure.
  for (int iy = 0; iy < grid.my; ++iy) {
    const auto row = static_cast<std::size_t>(iy);
    if (row_gap[row] >= kExcluded) continue;
    const HertzReport global = geometry::hertz_from_curvatures(
        a1[row], b1[row], geometry::HertzLoad::Approach, pen, estar);
    const double alpha = pen / (a1[row] * global.aa * global.aa);
    const double beta = pen / (b1[row] * global.bb * global.bb);
    const double pen_local = pen - beta * row_gap[row];
    if (!(pen_local > 0.0)) continue;
    const double half_length = std::sqrt(pen_local / (alpha * a1[row]));
    const HertzReport local = geometry::hertz_from_curvatures(
        a1[row], b1[row], geometry::HertzLoad::Approach, pen_local, estar);
    const double p_max = 1.5 * local.fn / (std::numbers::pi * local.aa * local.bb);
    const double x_lc = grid.x_centre(locus[row]);
    for (int ix = 0; ix < grid.mx; ++ix) {
      const double t = (grid.x_centre(ix) - x_lc) / half_length;
      if (t * t < 1.0 && gap(grid, h, ix, iy) < kExcluded)
        r.pn[grid.index(ix, iy)] = p_max * std::sqrt(1.0 - t * t);
    }
  }
  return r;
}

}  // namespace rollcontact::simplified
