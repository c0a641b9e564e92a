// BlockConvolution (u_i = Σ_j K_ij * p_j, the tangential 2×2 block and the couplings) against
// sums of dense products.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include "elastic/block_convolution.hpp"
#include "elastic/convolution.hpp"
#include "elastic/influence.hpp"
#include "support/fft_backends.hpp"
#include "support/random_field.hpp"

namespace rollcontact::elastic {
namespace {

using test_support::random_field;

/// u_i = Σ_j K_ij * p_j with DenseConvolution, the oracle.
std::vector<std::vector<double>> dense_block(int n_out, int n_in,
                                             const std::vector<const Kernel*>& kernels,
                                             const std::vector<std::vector<double>>& p) {
  const std::size_t n = p.front().size();
  std::vector<std::vector<double>> u(static_cast<std::size_t>(n_out), std::vector<double>(n, 0.0));
  std::vector<double> part(n);
  for (int i = 0; i < n_out; ++i)
    for (int j = 0; j < n_in; ++j) {
      const Kernel* k = kernels[static_cast<std::size_t>(i * n_in + j)];
      if (k == nullptr) continue;
      DenseConvolution(*k).apply(p[static_cast<std::size_t>(j)].data(), part.data());
      for (std::size_t e = 0; e < n; ++e) u[static_cast<std::size_t>(i)][e] += part[e];
    }
  return u;
}

class BlockConvolutionTest : public ::testing::TestWithParam<FftBackendKind> {};

TEST_P(BlockConvolutionTest, AgreesWithDenseProducts) {
  const CombinedMaterial m{.g = 1.3, .nu = 0.27, .k = 0.09};
  struct Case {
    int mx, my;
    double dx, dy, shift_x;
  };
  unsigned seed = 10;
  for (const Case& c :
       {Case{1, 1, 1.0, 1.0, 0.0}, Case{7, 5, 0.3, 0.3, 0.0}, Case{13, 11, 0.1, 0.07, 0.1},
        Case{24, 9, 0.2, 0.5, 0.0}, Case{1, 17, 0.5, 0.2, 0.0}, Case{33, 20, 0.1, 0.12, -0.1}}) {
    const Grid g{.mx = c.mx, .my = c.my, .xl = 0, .yl = 0, .dx = c.dx, .dy = c.dy};
    const Kernel xx = make_kernel(Component::xx, g, m, c.shift_x, 0.0);
    const Kernel xy = make_kernel(Component::xy, g, m, c.shift_x, 0.0);
    const Kernel yy = make_kernel(Component::yy, g, m, c.shift_x, 0.0);
    const Kernel xn = make_kernel(Component::xn, g, m, c.shift_x, 0.0);
    const Kernel yn = make_kernel(Component::yn, g, m, c.shift_x, 0.0);
    struct Shape {
      int n_out, n_in;
      std::vector<const Kernel*> kernels;
    };
    for (const Shape& s : {Shape{2, 2, {&xx, &xy, &xy, &yy}}, Shape{2, 2, {&xx, &xn, &yn, &yy}},
                           Shape{2, 3, {&xx, &xy, &xn, &xy, &yy, nullptr}}, Shape{2, 1, {&xn, &yn}},
                           Shape{3, 1, {&xn, nullptr, &yn}}}) {
      BlockConvolution block(s.n_out, s.n_in, s.kernels, GetParam());
      std::vector<std::vector<double>> p;
      for (int j = 0; j < s.n_in; ++j) p.push_back(random_field(g.size(), ++seed));
      const auto expected = dense_block(s.n_out, s.n_in, s.kernels, p);
      for (int repeat = 0; repeat < 2; ++repeat) {  // buffers are reused between calls
        std::vector<std::vector<double>> u(static_cast<std::size_t>(s.n_out),
                                           std::vector<double>(g.size(), 99.0));
        std::vector<const double*> in;
        std::vector<double*> out;
        for (auto& v : p) in.push_back(v.data());
        for (auto& v : u) out.push_back(v.data());
        block.apply(in.data(), out.data());
        for (int i = 0; i < s.n_out; ++i) {
          const auto& e = expected[static_cast<std::size_t>(i)];
          double scale = 0.0;
          for (double v : e) scale = std::max(scale, std::abs(v));
          for (std::size_t k = 0; k < g.size(); ++k) {
            // Zero outputs (a zero row of blocks, xy on one element) must come out exactly 0.
            ASSERT_NEAR(u[static_cast<std::size_t>(i)][k], e[k], 1e-12 * scale)
                << c.mx << "x" << c.my << " shape " << s.n_out << "x" << s.n_in << " output " << i
                << " element " << k;
          }
        }
      }
    }
  }
}

TEST_P(BlockConvolutionTest, AttenuatedBetweenPartsScalesEveryBlock) {
  // Two parts (rows 0–2 and 3–5) with f = 0.4: each output equals the dense block product of
  // the inputs weighted by f(part I, part J), written out as two masked dense products.
  const Grid g{.mx = 8, .my = 6, .xl = 0, .yl = 0, .dx = 0.2, .dy = 0.25};
  const CombinedMaterial m{.g = 1.0, .nu = 0.28, .k = 0.05};
  const Kernel xx = make_kernel(Component::xx, g, m), xy = make_kernel(Component::xy, g, m);
  const Kernel yy = make_kernel(Component::yy, g, m), xn = make_kernel(Component::xn, g, m);
  const std::vector<const Kernel*> kernels{&xx, &xy, &xn, &xy, &yy, nullptr};
  auto inter = std::make_shared<Interaction>();
  inter->n_parts = 2;
  inter->factor = {1, 0.4, 0.4, 1};
  for (std::size_t e = 0; e < g.size(); ++e)
    inter->part.push_back(static_cast<std::uint8_t>(e < 3 * 8 ? 0 : 1));
  BlockConvolution block(2, 3, kernels, GetParam());
  block.set_interaction(inter);
  std::vector<std::vector<double>> p;
  for (unsigned s = 0; s < 3; ++s) p.push_back(random_field(g.size(), 40 + s));
  std::vector<std::vector<double>> u(2, std::vector<double>(g.size()));
  const double* in[3] = {p[0].data(), p[1].data(), p[2].data()};
  double* out[2] = {u[0].data(), u[1].data()};
  block.apply(in, out);
  for (int a = 0; a < 2; ++a) {
    std::vector<std::vector<double>> q = p;
    for (auto& v : q)
      for (std::size_t e = 0; e < g.size(); ++e) v[e] *= inter->f_parts(a, inter->part[e]);
    const auto expected = dense_block(2, 3, kernels, q);
    for (int i = 0; i < 2; ++i)
      for (std::size_t e = 0; e < g.size(); ++e)
        if (inter->part[e] == a) {
          ASSERT_NEAR(u[static_cast<std::size_t>(i)][e], expected[static_cast<std::size_t>(i)][e],
                      1e-12 * 48 * xx.at(0, 0))
              << i << " " << e;
        }
  }
}

TEST_P(BlockConvolutionTest, SharedSpectraGiveTheSameProductsBitForBit) {
  // Products of one operator set share the spectra of equal kernels (a copy of C_xx is the
  // same transform); their results are those of products with spectra of their own.
  const CombinedMaterial m{.g = 1.3, .nu = 0.27, .k = 0.09};
  const Grid g{.mx = 13, .my = 11, .xl = 0, .yl = 0, .dx = 0.1, .dy = 0.07};
  const Kernel xx = make_kernel(Component::xx, g, m), xy = make_kernel(Component::xy, g, m);
  const Kernel yy = make_kernel(Component::yy, g, m), nn = make_kernel(Component::nn, g, m);
  const Kernel xx_copy = xx, yy_copy = yy;
  const std::vector<const Kernel*> full{&xx,     &xy,     nullptr, &xy, &yy,
                                        nullptr, nullptr, nullptr, &nn};
  const std::vector<const Kernel*> a{&xx_copy, &xy, &xy, &yy_copy};
  SpectrumCache cache;
  BlockConvolution full_shared(3, 3, full, GetParam(), FftPlanning::Estimate, &cache);
  BlockConvolution a_shared(2, 2, a, GetParam(), FftPlanning::Estimate, &cache);
  BlockConvolution full_own(3, 3, full, GetParam());
  BlockConvolution a_own(2, 2, a, GetParam());
  const std::size_t n = g.size();
  const std::vector<double> px = random_field(n, 3), py = random_field(n, 4),
                            pn = random_field(n, 5);
  std::vector<std::vector<double>> u(4, std::vector<double>(3 * n));
  const double* in3[3] = {px.data(), py.data(), pn.data()};
  double* out_shared[3] = {u[0].data(), u[0].data() + n, u[0].data() + 2 * n};
  double* out_own[3] = {u[1].data(), u[1].data() + n, u[1].data() + 2 * n};
  full_shared.apply(in3, out_shared);
  full_own.apply(in3, out_own);
  EXPECT_EQ(u[0], u[1]);
  double* out2_shared[2] = {u[2].data(), u[2].data() + n};
  double* out2_own[2] = {u[3].data(), u[3].data() + n};
  a_shared.apply(in3, out2_shared);
  a_own.apply(in3, out2_own);
  EXPECT_EQ(u[2], u[3]);
}

INSTANTIATE_TEST_SUITE_P(Backends, BlockConvolutionTest,
                         ::testing::ValuesIn(test_support::available_backends()),
                         test_support::backend_param_name);

}  // namespace
}  // namespace rollcontact::elastic
