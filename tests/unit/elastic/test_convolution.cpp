// FftConvolution against the dense oracle, and the dense product against the definition.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include "elastic/convolution.hpp"
#include "elastic/influence.hpp"
#include "support/fft_backends.hpp"
#include "support/random_field.hpp"

namespace rollcontact::elastic {
namespace {

constexpr Component kAllComponents[] = {Component::nn, Component::xx, Component::yy,
                                        Component::xy, Component::xn, Component::yn,
                                        Component::nx, Component::ny, Component::yx};

std::vector<double> random_tractions(std::size_t n, unsigned seed, bool sparse) {
  std::vector<double> p = test_support::random_field(n, seed);
  if (sparse) {  // like an active set: many exterior elements
    for (std::size_t i = 0; i < n; i += 3) p[i] = 0.0;
  }
  return p;
}

double max_abs(const std::vector<double>& v) {
  double m = 0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

struct GridCase {
  int mx, my;
  double dx, dy;
  double shift_x, shift_y;
};

class FftConvolutionTest : public ::testing::TestWithParam<FftBackendKind> {};

TEST_P(FftConvolutionTest, AgreesWithDenseProduct) {
  const CombinedMaterial m{.g = 1.7, .nu = 0.28, .k = 0.11};
  const GridCase cases[] = {
      {1, 1, 1.0, 1.0, 0.0, 0.0},       {7, 5, 0.3, 0.3, 0.0, 0.0},
      {8, 6, 0.2, 0.5, 0.0, 0.0},       {13, 11, 0.1, 0.07, 0.0, 0.0},
      {1, 17, 0.5, 0.2, 0.0, 0.0},      {40, 1, 0.04, 200.0, 0.0, 0.0},
      {31, 1, 0.001, 1000.0, 0.0, 0.0}, {9, 10, 0.25, 0.15, 0.1, 0.0},
      {12, 7, 0.2, 0.3, -0.05, 0.07},   {33, 20, 0.1, 0.12, 0.0, 0.0},
  };
  unsigned seed = 1;
  for (const GridCase& gc : cases) {
    const Grid grid{.mx = gc.mx, .my = gc.my, .xl = 0, .yl = 0, .dx = gc.dx, .dy = gc.dy};
    for (Component c : kAllComponents) {
      const Kernel kernel = make_kernel(c, grid, m, gc.shift_x, gc.shift_y);
      FftConvolution fft(kernel, GetParam());
      DenseConvolution dense(kernel);
      for (bool sparse : {false, true}) {
        const std::vector<double> p = random_tractions(grid.size(), ++seed, sparse);
        std::vector<double> u_fft(grid.size(), 99.0), u_dense(grid.size(), -99.0);
        fft.apply(p.data(), u_fft.data());
        dense.apply(p.data(), u_dense.data());
        // Round-off of the FFT product is ~1e-16·log2(N)·Σ|K||p|; relative to max|u| that is
        // well below 1e-12 unless u cancels heavily, which random p does not produce.
        const double scale = max_abs(u_dense);
        if (scale == 0.0) continue;  // e.g. xy on a single element
        for (std::size_t i = 0; i < u_fft.size(); ++i) {
          ASSERT_NEAR(u_fft[i], u_dense[i], 1e-12 * scale)
              << gc.mx << "x" << gc.my << " component " << static_cast<int>(c) << " element " << i;
        }
        // A second application must give the same result (buffers are reused).
        std::vector<double> again(grid.size());
        fft.apply(p.data(), again.data());
        EXPECT_EQ(again, u_fft);
      }
    }
  }
}

TEST_P(FftConvolutionTest, PaddedSizeAvoidsWrapAround) {
  const Grid grid{.mx = 10, .my = 4, .xl = 0, .yl = 0, .dx = 1, .dy = 1};
  const Kernel kernel = make_kernel(Component::nn, grid, {.g = 1, .nu = 0.3, .k = 0});
  FftConvolution fft(kernel, GetParam());
  EXPECT_GE(fft.engine().n_fast(), 2 * grid.mx - 1);
  EXPECT_GE(fft.engine().n_slow(), 2 * grid.my - 1);
  // A unit load in a corner: the far corner sees exactly the kernel entry of the full offset.
  std::vector<double> p(grid.size(), 0.0), u(grid.size());
  p[0] = 1.0;
  fft.apply(p.data(), u.data());
  EXPECT_NEAR(u[grid.index(9, 3)], kernel.at(9, 3), 1e-13 * kernel.at(0, 0));
  EXPECT_NEAR(u[grid.index(0, 0)], kernel.at(0, 0), 1e-13 * kernel.at(0, 0));
}

TEST_P(FftConvolutionTest, AttenuatedBetweenPartsAgreesWithDefinition) {
  // u_I = Σ_J f(part I, part J) K(I−J) p_J, against the dense sum written out.
  const Grid grid{.mx = 9, .my = 7, .xl = 0, .yl = 0, .dx = 0.2, .dy = 0.3};
  const Kernel kernel = make_kernel(Component::nn, grid, {.g = 1, .nu = 0.28, .k = 0});
  auto inter = std::make_shared<Interaction>();
  inter->n_parts = 3;
  inter->factor = {1, 0.3, 0, 0.3, 1, 0.7, 0, 0.7, 1};
  for (int iy = 0; iy < grid.my; ++iy)
    for (int ix = 0; ix < grid.mx; ++ix)
      inter->part.push_back(static_cast<std::uint8_t>(iy < 3 ? 0 : ix < 4 ? 1 : 2));
  FftConvolution fft(kernel, GetParam());
  fft.set_interaction(inter);
  const std::vector<double> p = random_tractions(grid.size(), 7, false);
  std::vector<double> u(grid.size());
  const double dot = fft.apply_dot(p.data(), u.data());
  double expected_dot = 0.0;
  for (int iy = 0; iy < grid.my; ++iy)
    for (int ix = 0; ix < grid.mx; ++ix) {
      const std::size_t i = grid.index(ix, iy);
      double expected = 0.0;
      for (int jy = 0; jy < grid.my; ++jy)
        for (int jx = 0; jx < grid.mx; ++jx) {
          const std::size_t j = grid.index(jx, jy);
          expected += inter->f(i, j) * kernel.at(ix - jx, iy - jy) * p[j];
        }
      ASSERT_NEAR(u[i], expected, 1e-12 * kernel.at(0, 0) * 63) << ix << "," << iy;
      expected_dot += p[i] * expected;
    }
  EXPECT_NEAR(dot, expected_dot, 1e-10 * std::abs(expected_dot));
  // Without the interaction the plain product returns.
  fft.set_interaction(nullptr);
  std::vector<double> full(grid.size()), dense_u(grid.size());
  fft.apply(p.data(), full.data());
  DenseConvolution(kernel).apply(p.data(), dense_u.data());
  for (std::size_t i = 0; i < full.size(); ++i)
    EXPECT_NEAR(full[i], dense_u[i], 1e-12 * kernel.at(0, 0) * 63);
}

INSTANTIATE_TEST_SUITE_P(Backends, FftConvolutionTest,
                         ::testing::ValuesIn(test_support::available_backends()),
                         test_support::backend_param_name);

TEST(DenseConvolution, MatchesDefinition) {
  const Grid grid{.mx = 3, .my = 2, .xl = 0, .yl = 0, .dx = 0.5, .dy = 0.4};
  const CombinedMaterial m{.g = 2, .nu = 0.3, .k = 0.2};
  const Kernel kernel = make_kernel(Component::xn, grid, m);
  DenseConvolution dense(kernel);
  const std::vector<double> p = {1, -2, 0.5, 0, 3, -1};
  std::vector<double> u(6);
  dense.apply(p.data(), u.data());
  for (int iy = 0; iy < 2; ++iy) {
    for (int ix = 0; ix < 3; ++ix) {
      double expected = 0;
      for (int jy = 0; jy < 2; ++jy) {
        for (int jx = 0; jx < 3; ++jx) {
          expected += influence_coefficient(Component::xn, (ix - jx) * 0.5, (iy - jy) * 0.4, 0.5,
                                            0.4, m.nu, m.k) /
                      m.g * p[grid.index(jx, jy)];
        }
      }
      EXPECT_NEAR(u[grid.index(ix, iy)], expected, 1e-15);
    }
  }
}

TEST(DenseConvolution, UniformPressureGivesSymmetricDisplacement) {
  // Physics sanity: uniform pressure on a symmetric grid gives u_n symmetric about the centre,
  // largest in the middle, and u_x antisymmetric (pointing inward for K > 0).
  const Grid grid{.mx = 9, .my = 7, .xl = -4.5, .yl = -3.5, .dx = 1, .dy = 1};
  const CombinedMaterial m{.g = 1, .nu = 0.3, .k = 0.2};
  const std::vector<double> p(grid.size(), 1.0);
  std::vector<double> un(grid.size()), ux(grid.size());
  DenseConvolution(make_kernel(Component::nn, grid, m)).apply(p.data(), un.data());
  DenseConvolution(make_kernel(Component::xn, grid, m)).apply(p.data(), ux.data());
  EXPECT_EQ(max_abs(un), un[grid.index(4, 3)]);
  for (int iy = 0; iy < 7; ++iy) {
    for (int ix = 0; ix < 9; ++ix) {
      EXPECT_NEAR(un[grid.index(ix, iy)], un[grid.index(8 - ix, 6 - iy)], 1e-13);
      EXPECT_NEAR(ux[grid.index(ix, iy)], -ux[grid.index(8 - ix, iy)], 1e-13);
    }
  }
  EXPECT_LT(ux[grid.index(8, 3)], 0.0);
  EXPECT_GT(ux[grid.index(0, 3)], 0.0);
}

}  // namespace
}  // namespace rollcontact::elastic
