// The active-set normal solver for non-symmetric influence operators (viscoelastic rolling):
// on a symmetric (elastic) problem it must find NormCG's solution, on a non-symmetric one the
// contact conditions themselves.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "elastic/convolution.hpp"
#include "elastic/influence.hpp"
#include "normal/active_set_solver.hpp"
#include "normal/normal_solver.hpp"
#include "normal/preconditioner.hpp"

namespace rollcontact::normal {
namespace {

/// A ball-like gap h = 0.05(x² + y²) on 25 × 25 elements of 0.2 mm.
struct Ball {
  Grid grid{25, 25, -2.5, -2.5, 0.2, 0.2};
  std::vector<double> h;
  Ball() {
    h.resize(grid.size());
    for (int iy = 0; iy < grid.my; ++iy)
      for (int ix = 0; ix < grid.mx; ++ix) {
        const double x = grid.x_centre(ix), y = grid.y_centre(iy);
        h[grid.index(ix, iy)] = 0.05 * (x * x + y * y);
      }
  }
};

double max_abs_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double m = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) m = std::max(m, std::abs(a[i] - b[i]));
  return m;
}

TEST(ActiveSetNormalSolver, FindsNormCGsSolutionOfASymmetricProblem) {
  const Ball ball;
  const CombinedMaterial pa6{1143.0, 0.4, 0.0};
  const elastic::Kernel kernel = elastic::make_kernel(elastic::Component::nn, ball.grid, pa6);
  elastic::FftConvolution a(kernel, FftBackendKind::Default);
  CirculantPreconditioner m(ball.grid, pa6, FftBackendKind::Default);
  NormalSettings settings;
  settings.eps = 1e-12;
  settings.max_iterations = 1000;
  for (NormalLoad load : {NormalLoad::Force, NormalLoad::Approach}) {
    const double value = load == NormalLoad::Force ? 600.0 : 0.2;
    NormalSolver cg(ball.grid, a, kernel, m);
    const NormalResult ref = cg.solve(ball.h, load, value, settings, nullptr, pa6.nu, pa6.g);
    ActiveSetNormalSolver active(ball.grid, a);
    const NormalResult r = active.solve(ball.h, load, value, settings, nullptr, pa6.nu, pa6.g);
    ASSERT_TRUE(ref.converged && r.converged) << r.message;
    const double pmax = *std::max_element(ref.pn.begin(), ref.pn.end());
    EXPECT_LT(max_abs_difference(r.pn, ref.pn), 1e-8 * pmax);
    EXPECT_EQ(r.contact_elements, ref.contact_elements);
    EXPECT_NEAR(r.pen, ref.pen, 1e-9 * ref.pen);
    EXPECT_NEAR(r.fn, ref.fn, 1e-9 * ref.fn);
  }
}

TEST(ActiveSetNormalSolver, MeetsTheContactConditionsOfANonSymmetricProblem) {
  // Viscoelastic rolling, ℓ = 1.5 mm (about the contact radius): C_nn favours upstream loads.
  const Ball ball;
  CombinedMaterial visco{1143.0, 0.4, 0.0};
  visco.viscous[0] = {1.0, 0.4, 0.0, 1.5};
  const elastic::Kernel kernel = elastic::make_kernel(elastic::Component::nn, ball.grid, visco);
  ASSERT_NE(kernel.at(-3, 0), kernel.at(3, 0));
  elastic::FftConvolution a(kernel, FftBackendKind::Default);
  ActiveSetNormalSolver solver(ball.grid, a);
  NormalSettings settings;
  const NormalResult r = solver.solve(ball.h, NormalLoad::Force, 600.0, settings);
  ASSERT_TRUE(r.converged) << r.message;
  EXPECT_NEAR(r.fn, 600.0, 1e-9 * 600.0);
  double scale = 0.0;
  for (double u : r.un) scale = std::max(scale, std::abs(u));
  for (std::size_t i = 0; i < r.pn.size(); ++i) {
    const double gap = ball.h[i] + r.un[i] - r.pen;
    EXPECT_GE(r.pn[i], 0.0);
    if (r.pn[i] > 0.0)
      EXPECT_NEAR(gap, 0.0, 1e-9 * scale) << i;
    else
      EXPECT_GE(gap, -1e-9 * scale) << i;
  }
}

}  // namespace
}  // namespace rollcontact::normal
