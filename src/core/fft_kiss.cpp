// Double-precision KISS FFT engine through Eigen's unsupported FFT module (its default backend is
// a C++ port of KISS FFT, templated on the scalar; Debian's libkissfft is float-only).
//
// 2-D transforms are 1-D transforms along the fast index, then along the slow index:
// * Real rows are transformed two at a time as the real and imaginary parts of one complex row
//   and separated by Hermitian symmetry (half the work of one complex transform per row, and it
//   works for odd lengths, unlike Eigen's real-input path that needs multiples of 4).
// * Slow-index (column) transforms gather a block of columns into contiguous buffers first, so
//   memory is read in runs of kBlock complex values instead of one value per cache line.
// * Rows the caller declares zero (forward) or not needed (inverse) are skipped.

#include <Eigen/Core>
#include <algorithm>
#include <complex>
#include <unsupported/Eigen/FFT>
#include <vector>

#include "core/fft_engines.hpp"

namespace rollcontact::core::detail {

namespace {

using Complex = std::complex<double>;

class KissEngine final : public FftEngine {
 public:
  KissEngine(int n_fast, int n_slow)
      : FftEngine(n_fast, n_slow),
        half_(n_fast / 2 + 1),
        real_(real_size(), 0.0),
        spectrum_(spectrum_size()),
        row_in_(static_cast<std::size_t>(n_fast)),
        row_out_(static_cast<std::size_t>(n_fast)),
        col_in_(static_cast<std::size_t>(kBlock) * static_cast<std::size_t>(n_slow)),
        col_out_(col_in_.size()) {
    fft_.SetFlag(Fft::Unscaled);
    // Eigen creates a plan (twiddles, factorisation) on the first use of a length: do it now, so
    // that transforms later do not allocate.
    transform(row_out_.data(), row_in_.data(), n_fast, false);
    transform(row_out_.data(), row_in_.data(), n_fast, true);
    transform(col_out_.data(), col_in_.data(), n_slow, false);
    transform(col_out_.data(), col_in_.data(), n_slow, true);
  }

  void forward(const double* in, std::complex<double>* out) override {
    std::copy_n(in, real_size(), real_.data());
    execute_forward(n_slow());
    std::copy_n(spectrum_.data(), spectrum_size(), out);
  }
  void inverse(const std::complex<double>* in, double* out) override {
    std::copy_n(in, spectrum_size(), spectrum_.data());
    execute_inverse(n_slow());
    std::copy_n(real_.data(), real_size(), out);
  }
  std::string_view name() const noexcept override { return "kiss"; }
  double* real_data() noexcept override { return real_.data(); }
  std::complex<double>* spectrum_data() noexcept override { return spectrum_.data(); }

  void execute_forward(int rows_in) override {
    rows_in = std::clamp(rows_in, 0, n_slow());
    forward_rows(rows_in);
    column_pass(false, rows_in, n_slow());
  }
  void execute_inverse(int rows_out) override {
    rows_out = std::clamp(rows_out, 0, n_slow());
    column_pass(true, n_slow(), rows_out);
    inverse_rows(rows_out);
  }

 private:
  using Fft = Eigen::FFT<double, Eigen::internal::kissfft_impl<double>>;
  static constexpr int kBlock = 8;

  void transform(Complex* dst, const Complex* src, int n, bool inverse) {
    if (n == 1) {
      dst[0] = src[0];
    } else if (inverse) {
      fft_.inv(dst, src, n);
    } else {
      fft_.fwd(dst, src, n);
    }
  }

  std::size_t row(int j, int length) const noexcept {
    return static_cast<std::size_t>(j) * static_cast<std::size_t>(length);
  }

  /// Real rows j < rows → half-spectrum rows (fast-index transform).
  void forward_rows(int rows) {
    const int n = n_fast();
    for (int j = 0; j < rows; j += 2) {
      const double* a = real_.data() + row(j, n);
      const bool pair = j + 1 < rows;
      if (pair) {
        const double* b = a + n;
        for (int i = 0; i < n; ++i) row_in_[static_cast<std::size_t>(i)] = Complex(a[i], b[i]);
      } else {
        for (int i = 0; i < n; ++i) row_in_[static_cast<std::size_t>(i)] = Complex(a[i], 0.0);
      }
      transform(row_out_.data(), row_in_.data(), n, false);
      // Z = A + iB with A, B real: A_k = (Z_k + conj Z_{n−k})/2, B_k = (Z_k − conj Z_{n−k})/(2i).
      Complex* sa = spectrum_.data() + row(j, half_);
      Complex* sb = sa + half_;
      for (int k = 0; k < half_; ++k) {
        const Complex z = row_out_[static_cast<std::size_t>(k)];
        const Complex zc = std::conj(row_out_[static_cast<std::size_t>(k == 0 ? 0 : n - k)]);
        sa[k] = 0.5 * (z + zc);
        if (pair) sb[k] = Complex(0.0, -0.5) * (z - zc);
      }
    }
  }

  /// Half-spectrum rows j < rows → real rows (fast-index inverse transform).
  void inverse_rows(int rows) {
    const int n = n_fast();
    for (int j = 0; j < rows; j += 2) {
      const Complex* sa = spectrum_.data() + row(j, half_);
      const bool pair = j + 1 < rows;
      const Complex* sb = sa + half_;
      for (int k = 0; k < half_; ++k) {
        Complex a = sa[k];
        Complex b = pair ? sb[k] : Complex(0.0, 0.0);
        if (k == 0 || 2 * k == n) {
          // Like FFTW's c2r, use only the real part of the self-conjugate (DC, Nyquist) entries.
          a = Complex(a.real(), 0.0);
          b = Complex(b.real(), 0.0);
        }
        row_in_[static_cast<std::size_t>(k)] = a + Complex(0.0, 1.0) * b;
      }
      for (int k = half_; k < n; ++k) {
        const Complex a = std::conj(sa[n - k]);
        const Complex b = pair ? std::conj(sb[n - k]) : Complex(0.0, 0.0);
        row_in_[static_cast<std::size_t>(k)] = a + Complex(0.0, 1.0) * b;
      }
      transform(row_out_.data(), row_in_.data(), n, true);
      double* ra = real_.data() + row(j, n);
      for (int i = 0; i < n; ++i) ra[i] = row_out_[static_cast<std::size_t>(i)].real();
      if (pair) {
        double* rb = ra + n;
        for (int i = 0; i < n; ++i) rb[i] = row_out_[static_cast<std::size_t>(i)].imag();
      }
    }
  }

  /// Slow-index transforms of every spectrum column; input rows ≥ rows_in are taken as zero,
  /// output rows ≥ rows_out are not stored.
  void column_pass(bool inverse, int rows_in, int rows_out) {
    const int ns = n_slow();
    for (int c0 = 0; c0 < half_; c0 += kBlock) {
      const int nb = std::min(kBlock, half_ - c0);
      for (int s = 0; s < rows_in; ++s) {
        const Complex* src = spectrum_.data() + row(s, half_) + c0;
        for (int b = 0; b < nb; ++b) col_in_[row(b, ns) + static_cast<std::size_t>(s)] = src[b];
      }
      for (int b = 0; b < nb; ++b) {
        std::fill(col_in_.begin() + static_cast<std::ptrdiff_t>(row(b, ns) + rows_in),
                  col_in_.begin() + static_cast<std::ptrdiff_t>(row(b + 1, ns)), Complex(0.0, 0.0));
        transform(col_out_.data() + row(b, ns), col_in_.data() + row(b, ns), ns, inverse);
      }
      for (int s = 0; s < rows_out; ++s) {
        Complex* dst = spectrum_.data() + row(s, half_) + c0;
        for (int b = 0; b < nb; ++b) dst[b] = col_out_[row(b, ns) + static_cast<std::size_t>(s)];
      }
    }
  }

  int half_;
  Fft fft_;
  std::vector<double> real_;
  std::vector<Complex> spectrum_;
  std::vector<Complex> row_in_, row_out_;
  std::vector<Complex> col_in_, col_out_;
};

}  // namespace

std::unique_ptr<FftEngine> make_kiss_engine(int n_fast, int n_slow) {
  return std::make_unique<KissEngine>(n_fast, n_slow);
}

}  // namespace rollcontact::core::detail
