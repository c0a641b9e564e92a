// One operator notion for every iterative solver: an FFT influence product (core::LinearOperator)
// used through as_map() by the Krylov solvers solves C_nn·p = u, checked with the dense product.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/krylov.hpp"
#include "elastic/convolution.hpp"
#include "elastic/material.hpp"
#include "support/random_field.hpp"

namespace rollcontact::elastic {
namespace {

TEST(LinearOperator, FftInfluenceProductDrivesTheKrylovSolvers) {
  Grid grid;
  grid.mx = 12;
  grid.my = 10;
  grid.dx = grid.dy = 0.5;
  const CombinedMaterial m = combine_materials(0.28, 0.28, 8.0e4, 8.0e4);
  const Kernel kernel = make_kernel(Component::nn, grid, m);
  FftConvolution fft(kernel, FftBackendKind::Default);
  const std::size_t n = grid.size();
  const core::LinearMap a = core::as_map(fft, n);
  const core::LinearMap identity = [](const std::vector<double>& r, std::vector<double>& z) {
    z = r;
  };
  const std::vector<double> u = test_support::random_field(n, 5);
  DenseConvolution dense(kernel);
  for (bool use_gmres : {false, true}) {
    std::vector<double> p(n, 0.0);
    // C_nn is symmetric positive definite: CG converges; GMRES must agree.
    const core::KrylovResult r = use_gmres ? core::solve_gmres(a, identity, u, p, 1e-10, 500)
                                           : core::solve_pcg(a, identity, u, p, 1e-10, 500);
    ASSERT_TRUE(r.converged) << (use_gmres ? "GMRES" : "PCG");
    std::vector<double> check(n);
    dense.apply(p.data(), check.data());
    double err = 0.0, norm = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      err += (check[i] - u[i]) * (check[i] - u[i]);
      norm += u[i] * u[i];
    }
    // 1e-10 asked of the solver; FFT and dense products differ by ~1e-15 relative.
    EXPECT_LT(std::sqrt(err / norm), 1e-9) << (use_gmres ? "GMRES" : "PCG");
  }
}

}  // namespace
}  // namespace rollcontact::elastic
