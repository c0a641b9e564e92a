// The FFT evaluation of subsurface fields at the element centres (post/subsurface_lattice)
// against the direct superposition it replaces (post/nodal_loads + response_from_sums): the
// same sums, so the same fields to rounding, for both bodies, at the surface and deep down.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "post/half_space_response.hpp"
#include "post/nodal_loads.hpp"
#include "post/subsurface.hpp"
#include "post/subsurface_lattice.hpp"

namespace rollcontact::post {
namespace {

TEST(SubsurfaceLattice, EqualsTheDirectSumAtEveryCentre) {
  Grid grid;
  grid.mx = 13;
  grid.my = 9;
  grid.xl = -1.3;
  grid.yl = -0.7;
  grid.dx = 0.2;
  grid.dy = 0.15;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> px(grid.size()), py(grid.size()), pn(grid.size());
  for (std::size_t i = 0; i < grid.size(); ++i) {
    pn[i] = 500.0 * (1.0 + u(rng));  // a rough pressure field, some elements unloaded
    px[i] = 100.0 * u(rng);
    py[i] = 100.0 * u(rng);
    if (u(rng) > 0.6) pn[i] = px[i] = py[i] = 0.0;
  }
  const NodalLoads loads(grid, px, py, pn);
  SubsurfaceLattice lattice(grid, px, py, pn);
  const double g = 82000.0, nu = 0.28;
  for (const double z : {loads.effective_depth(0.0), 0.05, 0.4, 3.0}) {
    for (const double sign : {1.0, -1.0}) {
      LatticeFields f;
      lattice.evaluate(z, g, nu, sign, f);
      double worst = 0.0, scale = 0.0;
      for (int iy = 0; iy < grid.my; ++iy)
        for (int ix = 0; ix < grid.mx; ++ix) {
          CornerSums s = loads.sums(grid.x_centre(ix), grid.y_centre(iy), z);
          for (std::size_t c = 0; c < kCornerCount; ++c) {
            s.x[c] *= sign;
            s.y[c] *= sign;
          }
          const HalfSpaceResponse h = response_from_sums(s, z, g, nu);
          const double direct[kFieldCount] = {h.u[0],         h.u[1],         h.u[2],
                                              h.stress[0][0], h.stress[0][1], h.stress[0][2],
                                              h.stress[1][1], h.stress[1][2], h.stress[2][2]};
          for (std::size_t o = 3; o < kFieldCount; ++o) {  // stresses [N/mm²]
            scale = std::max(scale, std::abs(direct[o]));
            worst = std::max(worst, std::abs(f[o][grid.index(ix, iy)] - direct[o]));
          }
          for (std::size_t o = 0; o < 3; ++o)  // displacements [mm], ~1e-3
            EXPECT_NEAR(f[o][grid.index(ix, iy)], direct[o], 1e-12) << "z " << z;
        }
      // Rounding of sums over ~100 nodes with corner values up to ~10: 1e-10 of the stresses.
      EXPECT_LT(worst, 1e-10 * scale) << "z " << z << " sign " << sign;
      EXPECT_GT(scale, 10.0);
    }
  }
}

TEST(SubsurfaceLattice, LargeBlocksTakeTheLatticeAndAgreeWithSmallOnes) {
  // A 40 × 30 grid under a Hertz-like pressure: ISUBS 1 at three depths goes through the lattice
  // (1200 points × ~1200 nodes), a block of three columns and rows (ISUBS 3) through the direct
  // sum; their common points agree.
  Solution sol;
  sol.grid.mx = 40;
  sol.grid.my = 30;
  sol.grid.xl = -4.0;
  sol.grid.yl = -3.0;
  sol.grid.dx = sol.grid.dy = 0.2;
  sol.pn.assign(sol.grid.size(), 0.0);
  sol.px.assign(sol.grid.size(), 0.0);
  sol.py.assign(sol.grid.size(), 0.0);
  for (int iy = 0; iy < sol.grid.my; ++iy)
    for (int ix = 0; ix < sol.grid.mx; ++ix) {
      const double x = sol.grid.x_centre(ix) / 3.5, y = sol.grid.y_centre(iy) / 2.5;
      const double r2 = x * x + y * y;
      if (r2 < 1.0) {
        sol.pn[sol.grid.index(ix, iy)] = 1000.0 * std::sqrt(1.0 - r2);
        sol.px[sol.grid.index(ix, iy)] = 200.0 * std::sqrt(1.0 - r2) * x;
      }
    }
  model::Bodies bodies;
  bodies.body1 = bodies.body2 = {0.28, 82000.0};
  model::SubsurfaceBlock all;
  all.isubs = 1;
  all.z = {0.0, 0.5, 1.5};
  model::SubsurfaceBlock few;
  few.isubs = 3;
  few.ix = {5, 20, 33};
  few.iy = {4, 15, 27};
  few.z = all.z;
  const auto r = compute_subsurface({all, few}, bodies, sol);
  ASSERT_EQ(r.size(), 2u);
  const SubsurfaceResult &a = r[0], &b = r[1];
  ASSERT_EQ(a.size(), 40u * 30u * 3u);
  ASSERT_EQ(b.size(), 27u);
  std::size_t k = 0;
  for (std::size_t iz = 0; iz < 3; ++iz)
    for (const int iy : few.iy)
      for (const int ix : few.ix) {
        const std::size_t at = static_cast<std::size_t>(ix - 1) + 40u * (iy - 1) + 1200u * iz;
        EXPECT_NEAR(a.sigvm[at], b.sigvm[k], 1e-9 * 1000.0);
        EXPECT_NEAR(a.szz[at], b.szz[k], 1e-9 * 1000.0);
        EXPECT_NEAR(a.uz[at], b.uz[k], 1e-12);
        ++k;
      }
  // The maximum von Mises stress lies below the surface, 0.5–0.65 p0 for a Hertzian pressure.
  EXPECT_GT(a.max_sigvm.z, 0.0);
  EXPECT_GT(a.max_sigvm.value, 0.5 * 1000.0);
  EXPECT_LT(a.max_sigvm.value, 0.65 * 1000.0);
}

}  // namespace
}  // namespace rollcontact::post
