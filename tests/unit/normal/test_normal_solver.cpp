// NormCG against Hertz's analytic solution and against itself (force ↔ approach consistency).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include "elastic/convolution.hpp"
#include "elastic/influence.hpp"
#include "geometry/hertz.hpp"
#include "normal/normal_solver.hpp"
#include "normal/preconditioner.hpp"

namespace rollcontact::normal {
namespace {

// Steel-like material: G = 82000 N/mm², ν = 0.28 (values do not matter for the relative errors).
const CombinedMaterial steel{82000.0, 0.28, 0.0};
double estar() {
  return steel.g / (1.0 - steel.nu);
}

struct HertzCase {
  Grid grid;
  std::vector<double> h;
  HertzReport hertz;
  elastic::Kernel kernel;
  std::unique_ptr<elastic::LinearOperator> product;
  std::unique_ptr<Preconditioner> precond;
};

/// A Hertzian case with semi-axis ratio a/b, `across` elements over the contact length 2a and a
/// potential contact 1.25 times the Hertz ellipse (odd element counts: an element at the centre).
HertzCase make_hertz_setup(double aob, int across, bool dense = false, bool precondition = true) {
  HertzCase s;
  const double fn = 1.0e4;
  // Semi-axes with a·b fixed; curvatures from the Hertz solution for these axes.
  const double a = 4.0 * std::sqrt(aob), b = 4.0 / std::sqrt(aob);
  s.hertz = geometry::hertz_from_semiaxes(a, b, geometry::HertzLoad::Force, fn, estar());
  const double scale = 1.25;
  const double dx = 2.0 * a / across;
  const int mx = 2 * static_cast<int>(std::ceil(scale * a / dx)) + 1;
  const double dy = 2.0 * b / across;
  const int my = 2 * static_cast<int>(std::ceil(scale * b / dy)) + 1;
  s.grid = Grid{mx, my, -0.5 * mx * dx, -0.5 * my * dy, dx, dy};
  s.h.resize(s.grid.size());
  for (int iy = 0; iy < my; ++iy)
    for (int ix = 0; ix < mx; ++ix) {
      const double x = s.grid.x_centre(ix), y = s.grid.y_centre(iy);
      s.h[s.grid.index(ix, iy)] = s.hertz.a1 * x * x + s.hertz.b1 * y * y;
    }
  s.kernel = elastic::make_kernel(elastic::Component::nn, s.grid, steel);
  if (dense)
    s.product = std::make_unique<elastic::DenseConvolution>(s.kernel);
  else
    s.product = std::make_unique<elastic::FftConvolution>(s.kernel, FftBackendKind::Default);
  if (precondition)
    s.precond = std::make_unique<CirculantPreconditioner>(s.grid, steel, FftBackendKind::Default);
  else
    s.precond = std::make_unique<IdentityPreconditioner>(s.grid.size());
  return s;
}

NormalResult solve_hertz(HertzCase& s, NormalLoad load, double eps = 1e-8) {
  NormalSolver solver(s.grid, *s.product, s.kernel, *s.precond);
  NormalSettings settings;
  settings.eps = eps;
  settings.max_iterations = 500;
  const double value = load == NormalLoad::Force ? s.hertz.fn : s.hertz.pen;
  return solver.solve(s.h, load, value, settings, nullptr, steel.nu, steel.g);
}

double max_of(const std::vector<double>& v) {
  return *std::max_element(v.begin(), v.end());
}

struct Errors {
  double force, approach, pmax;
};

Errors hertz_errors(double aob, int across) {
  HertzCase s = make_hertz_setup(aob, across);
  const NormalResult by_force = solve_hertz(s, NormalLoad::Force);
  const NormalResult by_pen = solve_hertz(s, NormalLoad::Approach);
  EXPECT_TRUE(by_force.converged) << by_force.message;
  EXPECT_TRUE(by_pen.converged) << by_pen.message;
  return {std::abs(by_pen.fn / s.hertz.fn - 1.0), std::abs(by_force.pen / s.hertz.pen - 1.0),
          std::abs(max_of(by_force.pn) / s.hertz.pmax - 1.0)};
}

// Acceptance: for a/b ∈ {0.2, 1, 5}, grids with ~60 elements over the contact length give FN, PEN
// and PMAX within 1 % of Hertz, and the errors decrease with refinement (20 → 40 → 60).
class HertzConvergence : public ::testing::TestWithParam<double> {};

TEST_P(HertzConvergence, WithinOnePercentAndDecreasing) {
  const double aob = GetParam();
  const Errors coarse = hertz_errors(aob, 21);
  const Errors medium = hertz_errors(aob, 41);
  const Errors fine = hertz_errors(aob, 61);
  std::printf("a/b=%g errors FN %.2e %.2e %.2e  PEN %.2e %.2e %.2e  PMAX %.2e %.2e %.2e\n", aob,
              coarse.force, medium.force, fine.force, coarse.approach, medium.approach,
              fine.approach, coarse.pmax, medium.pmax, fine.pmax);
  EXPECT_LT(fine.force, 0.01);
  EXPECT_LT(fine.approach, 0.01);
  EXPECT_LT(fine.pmax, 0.01);
  EXPECT_LT(medium.force, coarse.force);
  EXPECT_LT(fine.force, medium.force);
  EXPECT_LT(medium.approach, coarse.approach);
  EXPECT_LT(fine.approach, medium.approach);
  EXPECT_LT(fine.pmax, coarse.pmax);
}

INSTANTIATE_TEST_SUITE_P(AspectRatios, HertzConvergence, ::testing::Values(0.2, 1.0, 5.0));

TEST(NormalSolver, ForceAndApproachSolvesAreMutuallyConsistent) {
  HertzCase s = make_hertz_setup(2.0, 31);
  const NormalResult by_force = solve_hertz(s, NormalLoad::Force, 1e-10);
  ASSERT_TRUE(by_force.converged);
  NormalSolver solver(s.grid, *s.product, s.kernel, *s.precond);
  NormalSettings settings;
  settings.eps = 1e-10;
  const NormalResult by_pen =
      solver.solve(s.h, NormalLoad::Approach, by_force.pen, settings, nullptr, steel.nu, steel.g);
  ASSERT_TRUE(by_pen.converged);
  EXPECT_NEAR(by_pen.fn, s.hertz.fn, 1e-7 * s.hertz.fn);
  EXPECT_EQ(by_pen.contact_elements, by_force.contact_elements);
  for (std::size_t i = 0; i < s.h.size(); ++i)
    ASSERT_NEAR(by_pen.pn[i], by_force.pn[i], 1e-7 * max_of(by_force.pn));
}

// A warm start whose displacement the caller has (the last solve's pressure on the same grid,
// as the vertical-force iteration's estimates have) gives the solve without that start's own
// product: the same iterations and the same answer bit for bit under a prescribed approach,
// one product fewer.
TEST(NormalSolver, AKnownStartingDisplacementSavesTheStartingProduct) {
  HertzCase s = make_hertz_setup(2.0, 31);
  const NormalResult first = solve_hertz(s, NormalLoad::Approach, 1e-10);
  ASSERT_TRUE(first.converged);
  std::vector<double> deeper = s.h;  // the next estimate: the body 0.1 % deeper
  for (double& v : deeper) v -= 1e-3 * s.hertz.pen;
  NormalSolver solver(s.grid, *s.product, s.kernel, *s.precond);
  NormalSettings settings;
  settings.eps = 1e-10;
  const NormalResult plain = solver.solve(deeper, NormalLoad::Approach, s.hertz.pen, settings,
                                          &first.pn, steel.nu, steel.g);
  const NormalResult known = solver.solve(deeper, NormalLoad::Approach, s.hertz.pen, settings,
                                          &first.pn, steel.nu, steel.g, &first.un);
  ASSERT_TRUE(plain.converged && known.converged);
  EXPECT_EQ(known.products, plain.products - 1);
  EXPECT_EQ(known.iterations, plain.iterations);
  EXPECT_EQ(known.pn, plain.pn);
  EXPECT_EQ(known.fn, plain.fn);
  // Under a prescribed force the start is scaled, and its displacement with it.
  const NormalResult by_force = solver.solve(deeper, NormalLoad::Force, 1.01 * first.fn, settings,
                                             &first.pn, steel.nu, steel.g, &first.un);
  ASSERT_TRUE(by_force.converged);
  EXPECT_NEAR(by_force.fn, 1.01 * first.fn, 1e-9 * first.fn);
}

TEST(NormalSolver, SatisfiesContactConditions) {
  HertzCase s = make_hertz_setup(0.5, 31);
  const NormalResult r = solve_hertz(s, NormalLoad::Force, 1e-10);
  ASSERT_TRUE(r.converged);
  const double tol = 1e-7 * r.pen;
  for (std::size_t i = 0; i < s.h.size(); ++i) {
    const double gap = s.h[i] - r.pen + r.un[i];
    EXPECT_GE(r.pn[i], 0.0);
    if (r.pn[i] > 0.0)
      EXPECT_NEAR(gap, 0.0, tol) << "element " << i;
    else
      EXPECT_GE(gap, -tol) << "element " << i;
  }
  double sum = 0.0;
  for (double p : r.pn) sum += p;
  EXPECT_NEAR(sum * s.grid.element_area(), s.hertz.fn, 1e-9 * s.hertz.fn);
}

TEST(NormalSolver, FftAndDenseProductsGiveTheSameSolution) {
  HertzCase fft = make_hertz_setup(1.0, 15, false);
  HertzCase dense = make_hertz_setup(1.0, 15, true);
  const NormalResult a = solve_hertz(fft, NormalLoad::Force, 1e-12);
  const NormalResult b = solve_hertz(dense, NormalLoad::Force, 1e-12);
  ASSERT_EQ(a.pn.size(), b.pn.size());
  EXPECT_NEAR(a.pen, b.pen, 1e-10 * a.pen);
  for (std::size_t i = 0; i < a.pn.size(); ++i) EXPECT_NEAR(a.pn[i], b.pn[i], 1e-8 * max_of(a.pn));
}

TEST(NormalSolver, PreconditionerReducesIterationsAndKeepsTheAnswer) {
  HertzCase plain = make_hertz_setup(1.0, 61, false, false);
  HertzCase pre = make_hertz_setup(1.0, 61, false, true);
  const NormalResult a = solve_hertz(plain, NormalLoad::Force, 1e-8);
  const NormalResult b = solve_hertz(pre, NormalLoad::Force, 1e-8);
  ASSERT_TRUE(a.converged);
  ASSERT_TRUE(b.converged);
  std::printf("iterations plain %d preconditioned %d\n", a.iterations, b.iterations);
  EXPECT_LT(b.iterations, a.iterations);
  EXPECT_NEAR(a.pen, b.pen, 1e-6 * a.pen);
}

TEST(NormalSolver, ReportsNonConvergence) {
  HertzCase s = make_hertz_setup(1.0, 41);
  NormalSolver solver(s.grid, *s.product, s.kernel, *s.precond);
  NormalSettings settings;
  settings.eps = 1e-12;
  settings.max_iterations = 2;
  const NormalResult r =
      solver.solve(s.h, NormalLoad::Force, s.hertz.fn, settings, nullptr, steel.nu, steel.g);
  EXPECT_FALSE(r.converged);
  EXPECT_NE(r.message.find("did not converge"), std::string::npos);
}

TEST(NormalSolver, NoContactWhenTheBodiesAreApart) {
  HertzCase s = make_hertz_setup(1.0, 11);
  NormalSolver solver(s.grid, *s.product, s.kernel, *s.precond);
  const NormalResult r =
      solver.solve(s.h, NormalLoad::Approach, -0.01, NormalSettings{}, nullptr, steel.nu, steel.g);
  EXPECT_TRUE(r.converged);
  EXPECT_EQ(r.contact_elements, 0);
  EXPECT_EQ(max_of(r.pn), 0.0);
}

TEST(NormalSolver, ExcludedElementsCarryNoPressure) {
  HertzCase s = make_hertz_setup(1.0, 21);
  const int centre = s.grid.mx / 2;
  for (int iy = 0; iy < s.grid.my; ++iy) s.h[s.grid.index(centre, iy)] = 1e30;  // a groove
  const NormalResult r = solve_hertz(s, NormalLoad::Force, 1e-9);
  ASSERT_TRUE(r.converged);
  for (int iy = 0; iy < s.grid.my; ++iy) EXPECT_EQ(r.pn[s.grid.index(centre, iy)], 0.0);
  double sum = 0.0;
  for (double p : r.pn) sum += p;
  EXPECT_NEAR(sum * s.grid.element_area(), s.hertz.fn, 1e-9 * s.hertz.fn);
}

}  // namespace
}  // namespace rollcontact::normal
