#include "contact/nested_starts.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/discretisation.hpp"

namespace rollcontact::contact {

/// Nested iteration for large grids: the same normal problem on a grid with elements twice as
/// large (h averaged over the 2×2 fine elements), solved — itself started from a coarser grid —
/// and prolongated element-wise. Returns an empty field when the grid is too small to gain.
/// The fine solve then starts close to its solution, with few active-set changes.
Field coarse_grid_start(PatchSolver::Impl& st, int level, const Grid& grid, const Field& h,
                        normal::NormalLoad load, double value, const CombinedMaterial& material,
                        const normal::NormalSettings& settings, int& iterations) {
  constexpr std::size_t min_elements = 20000;  // below this a coarse start does not pay
  if (grid.size() < min_elements || grid.mx < 16 || grid.my < 16) return {};
  if (material.table) return {};  // a file's coefficients (C=9) exist for its element size only
  const Grid coarse{(grid.mx + 1) / 2, (grid.my + 1) / 2, grid.xl,
                    grid.yl,           2.0 * grid.dx,     2.0 * grid.dy};
  Field ch(coarse.size(), geometry::excluded_distance);
  for (int jy = 0; jy < coarse.my; ++jy)
    for (int jx = 0; jx < coarse.mx; ++jx) {
      double sum = 0.0;
      int count = 0;
      for (int iy = 2 * jy; iy < std::min(2 * jy + 2, grid.my); ++iy)
        for (int ix = 2 * jx; ix < std::min(2 * jx + 2, grid.mx); ++ix) {
          const double v = h[grid.index(ix, iy)];
          if (v < geometry::excluded_distance) {
            sum += v;
            ++count;
          }
        }
      if (count > 0) ch[coarse.index(jx, jy)] = sum / count;
    }
  Field start =
      coarse_grid_start(st, level + 1, coarse, ch, load, value, material, settings, iterations);
  NormalOperators& ops = st.operators.normal(coarse, material);
  normal::NormalSolver solver(coarse, *ops.product, ops.kernel, *ops.preconditioner);
  const normal::NormalResult r = solver.solve(
      ch, load, value, settings, start.empty() ? nullptr : &start, material.nu, material.g);
  iterations += r.iterations;
  if (!r.converged) return {};  // only a starting value: fall back to the geometric estimate
  Field fine(grid.size(), 0.0);
  for (int iy = 0; iy < grid.my; ++iy)
    for (int ix = 0; ix < grid.mx; ++ix)
      if (h[grid.index(ix, iy)] < geometry::excluded_distance)
        fine[grid.index(ix, iy)] = r.pn[coarse.index(ix / 2, iy / 2)];
  return fine;
}

/// Nested iteration for steady rolling on large grids, the tangential counterpart of
/// coarse_grid_start: the semismooth Newton iteration moves the adhesion front about one element
/// per step along the rows (docs/decisions.md), so a start whose division into adhesion and slip
/// is right to within an element or two saves most fine steps. The coarse problem has elements
/// twice as large: traction bound averaged over the 2×2 fine elements (force-conserving), slip
/// per step averaged over the fine contact elements and doubled with the rolling step, and the
/// operator (C − C′) with C′ one coarse step downstream. Its solution (itself started from a
/// coarser grid) is prolongated element-wise: slipping parents give slip at the fine bound in
/// the parent's direction, adhering parents their traction within the fine bound. Returns false
/// (start unchanged) when the grid is too small to gain or the coarse solve fails.
bool steady_coarse_start(PatchSolver::Impl& st, int level, const tangential::TangentialSystem& sys,
                         double shift_x, double shift_y, const CombinedMaterial& material,
                         const tangential::TangentialSettings& settings, Field& px, Field& py,
                         int& products) {
  constexpr std::size_t min_contact = 2000;  // measured: 71×81 (3.1k) gains 42 → 32 ms
  const Grid& grid = sys.grid;
  const std::size_t ncon =
      static_cast<std::size_t>(std::count(sys.contact.begin(), sys.contact.end(), char{1}));
  if (ncon < min_contact || grid.mx < 16 || grid.my < 16) return false;
  if (material.table) return false;  // a file's coefficients (C=9) exist for its element size only
  // The coarse steady-rolling set has no C_yx of its own, which turned coefficients need (C=4).
  if (material.inclination_corrected()) return false;
  const Grid coarse{(grid.mx + 1) / 2, (grid.my + 1) / 2, grid.xl,
                    grid.yl,           2.0 * grid.dx,     2.0 * grid.dy};
  const std::size_t nc = coarse.size();
  tangential::TangentialSystem cs;
  cs.grid = coarse;
  cs.chi = sys.chi;
  cs.contact.assign(nc, 0);
  cs.bound.assign(nc, 0.0);
  cs.bx.assign(nc, 0.0);
  cs.by.assign(nc, 0.0);
  for (int jy = 0; jy < coarse.my; ++jy)
    for (int jx = 0; jx < coarse.mx; ++jx) {
      double bound = 0.0, bx = 0.0, by = 0.0;
      int children = 0, touching = 0;
      for (int iy = 2 * jy; iy < std::min(2 * jy + 2, grid.my); ++iy)
        for (int ix = 2 * jx; ix < std::min(2 * jx + 2, grid.mx); ++ix) {
          const std::size_t i = grid.index(ix, iy);
          ++children;
          if (!sys.contact[i]) continue;
          ++touching;
          bound += sys.bound[i];
          bx += sys.bx[i];
          by += sys.by[i];
        }
      const std::size_t j = coarse.index(jx, jy);
      if (touching == 0) continue;
      cs.contact[j] = 1;
      cs.bound[j] = bound / children;
      cs.bx[j] = 2.0 * bx / touching;
      cs.by[j] = 2.0 * by / touching;
    }
  Field cpx(nc, 0.0), cpy(nc, 0.0);
  steady_coarse_start(st, level + 1, cs, 2.0 * shift_x, 2.0 * shift_y, material, settings, cpx, cpy,
                      products);
  CoarseSteadyOperators& ops =
      st.operators.coarse_steady(coarse, material, 2.0 * shift_x, 2.0 * shift_y);
  cs.a = ops.view();
  // Only a start: the division into adhesion and slip is what matters (1e-3 measured 4 % faster
  // than EPS = 1e-5 at 287×323, with the same number of fine products).
  tangential::TangentialSettings coarse_settings = settings;
  coarse_settings.eps = std::max(settings.eps, 1e-3);
  const tangential::TangentialResult r =
      tangential::solve_semismooth_newton(cs, coarse_settings, &cpx, &cpy);
  products += r.iterations;
  if (!r.converged) return false;
  for (int iy = 0; iy < grid.my; ++iy)
    for (int ix = 0; ix < grid.mx; ++ix) {
      const std::size_t i = grid.index(ix, iy), j = coarse.index(ix / 2, iy / 2);
      if (!sys.contact[i]) continue;
      const double g = sys.bound[i], pabs = std::hypot(r.px[j], r.py[j]);
      if (pabs == 0.0) {
        px[i] = py[i] = 0.0;
      } else if (r.state[j] == ElementState::Slip || pabs > g) {
        px[i] = g * r.px[j] / pabs;
        py[i] = g * r.py[j] / pabs;
      } else {
        px[i] = r.px[j];
        py[i] = r.py[j];
      }
    }
  return true;
}
}  // namespace rollcontact::contact
