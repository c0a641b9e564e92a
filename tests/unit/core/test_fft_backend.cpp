// FFT engines: agreement with a direct DFT, round trips, row pruning, factory behaviour.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <string_view>
#include <vector>

#include "core/fft_backend.hpp"
#include "rollcontact/errors.hpp"
#include "rollcontact/version.hpp"
#include "support/fft_backends.hpp"
#include "support/random_field.hpp"

namespace rollcontact::core {
namespace {

using Complex = std::complex<double>;

using test_support::random_field;

/// Direct 2-D DFT half-spectrum X(kf, ks) = Σ x(i, j) e^{−2πi(kf i/nf + ks j/ns)}.
std::vector<Complex> direct_dft(const std::vector<double>& x, int nf, int ns) {
  const int half = nf / 2 + 1;
  std::vector<Complex> out(static_cast<std::size_t>(half * ns));
  for (int ks = 0; ks < ns; ++ks) {
    for (int kf = 0; kf < half; ++kf) {
      Complex sum = 0;
      for (int j = 0; j < ns; ++j) {
        for (int i = 0; i < nf; ++i) {
          // Reduce the phase modulo 1 first to keep the reference accurate.
          const long long num =
              static_cast<long long>(kf) * i * ns + static_cast<long long>(ks) * j * nf;
          const double phase = -2.0 * std::numbers::pi *
                               static_cast<double>(num % (static_cast<long long>(nf) * ns)) /
                               (nf * ns);
          sum += x[static_cast<std::size_t>(i + nf * j)] * std::polar(1.0, phase);
        }
      }
      out[static_cast<std::size_t>(kf + half * ks)] = sum;
    }
  }
  return out;
}

class FftEngineTest : public ::testing::TestWithParam<FftBackendKind> {};

TEST_P(FftEngineTest, ForwardMatchesDirectDft) {
  for (const auto& [nf, ns] : {std::pair{8, 6}, std::pair{9, 5}, std::pair{1, 7}, std::pair{6, 1},
                               std::pair{15, 14}, std::pair{1, 1}, std::pair{2, 3}}) {
    auto engine = make_fft_engine(GetParam(), nf, ns);
    EXPECT_EQ(engine->n_fast(), nf);
    EXPECT_EQ(engine->n_slow(), ns);
    EXPECT_EQ(engine->spectrum_size(), static_cast<std::size_t>((nf / 2 + 1) * ns));
    const std::vector<double> x = random_field(engine->real_size(), 1u + static_cast<unsigned>(nf));
    std::vector<Complex> got(engine->spectrum_size());
    engine->forward(x.data(), got.data());
    const std::vector<Complex> expected = direct_dft(x, nf, ns);
    // Entries are sums of nf·ns terms of size ≤ 1: round-off ~ 1e-16·√(nf ns)·log(nf ns).
    for (std::size_t i = 0; i < got.size(); ++i) {
      EXPECT_NEAR(std::abs(got[i] - expected[i]), 0.0, 1e-12) << nf << "x" << ns << " at " << i;
    }
  }
}

TEST_P(FftEngineTest, RoundTripIsUnnormalised) {
  for (const auto& [nf, ns] : {std::pair{30, 18}, std::pair{25, 27}, std::pair{1, 40},
                               std::pair{64, 1}, std::pair{11, 13}}) {
    auto engine = make_fft_engine(GetParam(), nf, ns);
    const std::vector<double> x = random_field(engine->real_size(), 7u);
    std::vector<Complex> spectrum(engine->spectrum_size());
    std::vector<double> back(engine->real_size());
    engine->forward(x.data(), spectrum.data());
    const std::vector<Complex> spectrum_copy = spectrum;
    engine->inverse(spectrum.data(), back.data());
    EXPECT_EQ(spectrum, spectrum_copy) << "inverse() must not modify its input";
    const double n = static_cast<double>(nf) * ns;
    for (std::size_t i = 0; i < x.size(); ++i) EXPECT_NEAR(back[i] / n, x[i], 1e-14);
  }
}

TEST_P(FftEngineTest, InverseOfSingleFrequency) {
  // c2r of a single spectral line gives a cosine: fixes the sign convention of the inverse.
  const int nf = 12, ns = 10;
  auto engine = make_fft_engine(GetParam(), nf, ns);
  std::vector<Complex> spectrum(engine->spectrum_size(), 0.0);
  spectrum[static_cast<std::size_t>(3 + (nf / 2 + 1) * 2)] = Complex(0.0, 1.0);  // kf = 3, ks = 2
  std::vector<double> out(engine->real_size());
  engine->inverse(spectrum.data(), out.data());
  for (int j = 0; j < ns; ++j) {
    for (int i = 0; i < nf; ++i) {
      const double phase = 2 * std::numbers::pi * (3.0 * i / nf + 2.0 * j / ns);
      // Hermitian completion doubles the line: 2·Re(i·e^{iφ}) = −2 sin φ.
      EXPECT_NEAR(out[static_cast<std::size_t>(i + nf * j)], -2 * std::sin(phase), 1e-13);
    }
  }
}

TEST_P(FftEngineTest, PrunedRowsBehaveAsZeroPadding) {
  const int nf = 20, ns = 18, rows = 7;
  auto engine = make_fft_engine(GetParam(), nf, ns);
  std::vector<double> x = random_field(engine->real_size(), 3u);
  std::vector<double> padded = x;
  std::fill(padded.begin() + rows * nf, padded.end(), 0.0);
  std::vector<Complex> expected(engine->spectrum_size());
  engine->forward(padded.data(), expected.data());

  std::copy(x.begin(), x.end(), engine->real_data());  // garbage in the rows declared zero
  engine->execute_forward(rows);
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_NEAR(std::abs(engine->spectrum_data()[i] - expected[i]), 0.0, 1e-13);
  }
  engine->execute_inverse(rows);
  for (int j = 0; j < rows; ++j) {
    for (int i = 0; i < nf; ++i) {
      const std::size_t k = static_cast<std::size_t>(i + nf * j);
      EXPECT_NEAR(engine->real_data()[k] / (nf * ns), x[k], 1e-14);
    }
  }
}

// The convolution's forward transforms with fewer nonzero rows after more: the rows beyond
// the declared ones must act as zeros, whatever an earlier transform left behind (FFTW keeps the
// row transforms' buffer and clears only the rows written before and not now).
TEST_P(FftEngineTest, ConvolutionWithFewerRowsAfterMoreSeesZeros) {
  const int nf = 20, ns = 18;
  auto engine = make_fft_engine(GetParam(), nf, ns);
  const std::vector<Complex> identity(engine->spectrum_size(), Complex(1.0, 0.0));
  engine->set_convolution_symbol(identity.data());
  const std::vector<double> x = random_field(engine->real_size(), 5u);
  for (int rows : {ns, 12, 5, 9, 1}) {
    std::copy(x.begin(), x.end(), engine->real_data());  // garbage in the rows declared zero
    engine->execute_convolution(rows, ns);
    for (int j = 0; j < ns; ++j)
      for (int i = 0; i < nf; ++i) {
        const std::size_t k = static_cast<std::size_t>(i + nf * j);
        const double expected = j < rows ? x[k] : 0.0;
        ASSERT_NEAR(engine->real_data()[k] / (nf * ns), expected, 1e-13)
            << "rows " << rows << " at " << i << ", " << j;
      }
  }
  engine->set_channel_count(1);
  for (int rows : {ns, 4}) {
    std::copy(x.begin(), x.end(), engine->real_data());
    engine->forward_to_channel(rows, 0);
    engine->inverse_from_channel(0, ns);
    for (int j = 0; j < ns; ++j)
      for (int i = 0; i < nf; ++i) {
        const std::size_t k = static_cast<std::size_t>(i + nf * j);
        ASSERT_NEAR(engine->real_data()[k] / (nf * ns), j < rows ? x[k] : 0.0, 1e-13)
            << "channel, rows " << rows << " at " << i << ", " << j;
      }
  }
}

// Engines of one size share their plans (FFTW: a process-wide table, executed on each engine's
// own arrays): interleaved transforms of two engines must not see each other's data, and an
// engine must keep working after another of its size, which made the plans, is gone.
TEST_P(FftEngineTest, EnginesOfOneSizeKeepTheirOwnData) {
  const int nf = 24, ns = 20, rows = 9;
  const std::vector<double> x = random_field(static_cast<std::size_t>(nf * ns), 11u);
  const std::vector<double> y = random_field(static_cast<std::size_t>(nf * ns), 12u);
  auto reference = make_fft_engine(GetParam(), nf, ns);
  std::vector<Complex> x_hat(reference->spectrum_size()), y_hat(reference->spectrum_size());
  reference->forward(x.data(), x_hat.data());
  reference->forward(y.data(), y_hat.data());
  auto first = make_fft_engine(GetParam(), nf, ns);
  auto second = make_fft_engine(GetParam(), nf, ns);
  std::copy(x.begin(), x.end(), first->real_data());
  std::copy(y.begin(), y.end(), second->real_data());
  first->execute_forward(ns);
  second->execute_forward(ns);
  for (std::size_t i = 0; i < x_hat.size(); ++i) {
    EXPECT_EQ(first->spectrum_data()[i], x_hat[i]);  // the same plan: the same bits
    EXPECT_EQ(second->spectrum_data()[i], y_hat[i]);
  }
  reference.reset();
  first.reset();
  second->execute_inverse(rows);  // planned now, after the others are gone
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < nf; ++i) {
      const std::size_t k = static_cast<std::size_t>(i + nf * j);
      EXPECT_NEAR(second->real_data()[k] / (nf * ns), y[k], 1e-14);
    }
}

INSTANTIATE_TEST_SUITE_P(Backends, FftEngineTest,
                         ::testing::ValuesIn(test_support::available_backends()),
                         test_support::backend_param_name);

TEST(FftFactory, DefaultResolvesToConfiguredBackend) {
  auto engine = make_fft_engine(FftBackendKind::Default, 4, 4);
  EXPECT_EQ(engine->name(), std::string_view(default_fft_backend));
  EXPECT_TRUE(fft_backend_available(FftBackendKind::Default));
  EXPECT_TRUE(fft_backend_available(FftBackendKind::Kiss));
  EXPECT_EQ(fft_backend_available(FftBackendKind::Fftw), ROLLCONTACT_HAVE_FFTW != 0);
}

TEST(FftFactory, RejectsUnavailableBackendAndBadSizes) {
  if (!fft_backend_available(FftBackendKind::Fftw)) {
    EXPECT_THROW(make_fft_engine(FftBackendKind::Fftw, 4, 4), NotSupportedError);
  }
  EXPECT_THROW(make_fft_engine(FftBackendKind::Kiss, 0, 4), ProblemError);
}

TEST(FftFactory, GoodSizesAreSmoothAndMinimal) {
  EXPECT_EQ(good_fft_size(1), 1);
  EXPECT_EQ(good_fft_size(7), 8);
  EXPECT_EQ(good_fft_size(1149), 1152);
  EXPECT_EQ(good_fft_size(1293), 1296);
  EXPECT_EQ(good_fft_size(1125), 1125);
  for (int n = 1; n < 3000; ++n) {
    const int g = good_fft_size(n);
    ASSERT_GE(g, n);
    int m = g;
    for (int f : {2, 3, 5}) {
      while (m % f == 0) m /= f;
    }
    ASSERT_EQ(m, 1) << n;
  }
}

}  // namespace
}  // namespace rollcontact::core

namespace rollcontact::core {
namespace {

// The single-precision convolution of the preconditioners against the double-precision engine:
// the same circular convolution with a real symbol, to single-precision accuracy.
TEST(SingleCirculant, MatchesTheDoublePrecisionConvolution) {
  const int nf = 30, ns = 24, mx = 25, my = 21;
  auto single = make_single_circulant(FftBackendKind::Fftw, nf, ns);
  if (!fft_backend_available(FftBackendKind::Fftw)) {
    EXPECT_EQ(single, nullptr);
    GTEST_SKIP() << "FFTW not built";
  }
  ASSERT_NE(single, nullptr);
  EXPECT_EQ(make_single_circulant(FftBackendKind::Kiss, nf, ns), nullptr);  // double-only backend

  auto engine = make_fft_engine(FftBackendKind::Fftw, nf, ns);
  std::vector<std::complex<double>> symbol(engine->spectrum_size());
  std::vector<double> real_symbol(symbol.size());
  for (std::size_t k = 0; k < symbol.size(); ++k) {
    real_symbol[k] = (1.0 + 0.5 * std::cos(0.37 * static_cast<double>(k))) / (nf * ns);
    symbol[k] = real_symbol[k];
  }
  engine->set_convolution_symbol(symbol.data());
  single->set_symbol(real_symbol.data());

  std::vector<double> in(static_cast<std::size_t>(mx * my)), out(in.size());
  for (std::size_t i = 0; i < in.size(); ++i) in[i] = std::sin(0.7 * static_cast<double>(i)) + 0.2;
  // Twice: the second call must not see the first one's data beyond the block.
  single->apply_dot(in.data(), out.data(), mx, my);
  const double dot = single->apply_dot(in.data(), out.data(), mx, my);

  double* real = engine->real_data();
  std::fill_n(real, engine->real_size(), 0.0);
  for (int iy = 0; iy < my; ++iy)
    for (int ix = 0; ix < mx; ++ix) real[ix + nf * iy] = in[static_cast<std::size_t>(ix + mx * iy)];
  engine->execute_convolution(ns, ns);
  double worst = 0.0, scale = 0.0, reference_dot = 0.0;
  for (int iy = 0; iy < my; ++iy)
    for (int ix = 0; ix < mx; ++ix) {
      const double ref = real[ix + nf * iy], got = out[static_cast<std::size_t>(ix + mx * iy)];
      worst = std::max(worst, std::abs(got - ref));
      scale = std::max(scale, std::abs(ref));
      reference_dot += in[static_cast<std::size_t>(ix + mx * iy)] * ref;
    }
  EXPECT_LT(worst, 1e-5 * scale);
  EXPECT_NEAR(dot, reference_dot, 1e-5 * std::abs(reference_dot));
}

}  // namespace
}  // namespace rollcontact::core
