#pragma once
// A small interface over 2-D real-to-complex FFT libraries. Two implementations:
// FFTW3 (GPL, fastest) and KISS FFT in double precision (permissive). See docs/decisions.md.

#include <complex>
#include <memory>
#include <string_view>
#include <vector>

#include "rollcontact/fft_options.hpp"

namespace rollcontact::core {

/// Plans for real n_fast × n_slow arrays stored with the fast index contiguous
/// (element (i, j) at i + n_fast*j). The half-spectrum has (n_fast/2+1) × n_slow complex values,
/// stored likewise. Transforms are unnormalised: inverse(forward(x)) = n_fast*n_slow*x.
/// An engine owns its plans; calls are not thread-safe on one engine.
class FftEngine {
 public:
  virtual ~FftEngine() = default;
  virtual void forward(const double* in, std::complex<double>* out) = 0;
  virtual void inverse(const std::complex<double>* in, double* out) = 0;
  virtual std::string_view name() const noexcept = 0;

  /// The engine's own work arrays (aligned as the library wants them): real_data() holds
  /// real_size() values, spectrum_data() spectrum_size(). With execute_forward/execute_inverse they
  /// let a caller transform without the copies that forward()/inverse() make.
  virtual double* real_data() noexcept = 0;
  virtual std::complex<double>* spectrum_data() noexcept = 0;
  /// real_data() → spectrum_data(). Slow rows j ≥ rows_in of real_data() are taken as zero and are
  /// not read (zero-padded input: an engine may skip their transforms). rows_in ∈ [0, n_slow].
  virtual void execute_forward(int rows_in) = 0;
  /// spectrum_data() → real_data(); only slow rows j < rows_out of the result are guaranteed, the
  /// others are unspecified. spectrum_data() is destroyed. rows_out ∈ [0, n_slow].
  virtual void execute_inverse(int rows_out) = 0;

  /// Fixes the symbol of execute_convolution(): spectrum_size() values in the layout of
  /// spectrum_data() (any normalisation included). Engines may keep it in a layout of their own
  /// and make plans here; spectrum_data() is destroyed.
  virtual void set_convolution_symbol(const std::complex<double>* symbol);
  /// real_data() ← inverse(symbol · forward(real_data())), the circular convolution with the
  /// symbol of set_convolution_symbol(), with the row pruning of execute_forward(rows_in) and
  /// execute_inverse(rows_out). The default is exactly those three steps; an engine may instead
  /// keep the spectrum in its own layout between the transforms. spectrum_data() is destroyed.
  virtual void execute_convolution(int rows_in, int rows_out);

  /// Spectral buffers ("channels") for products with several inputs and outputs
  /// (BlockConvolution): `count` buffers of spectrum_size() values in the engine's own layout,
  /// the one execute_convolution() uses between its transforms (FFTW: column-major). Allocating
  /// may make plans; real_data() and spectrum_data() are destroyed.
  virtual void set_channel_count(int count);
  virtual std::complex<double>* channel(int c) noexcept { return channels_[c].data(); }
  /// real_data() → channel c, with the row pruning of execute_forward(rows_in).
  virtual void forward_to_channel(int rows_in, int c);
  /// channel c → real_data(), with the row pruning of execute_inverse(rows_out). Channel c and
  /// spectrum_data() are destroyed.
  virtual void inverse_from_channel(int c, int rows_out);
  /// Makes now the plans that execute_convolution(rows_in, rows_out) and the channel transforms
  /// with these row counts need, so that the products never plan, without transforming
  /// anything: a pass through the transforms costs an FFT pair per operator at set-up. The
  /// default plans nothing (engines without plans).
  virtual void prepare_transforms(int /*rows_in*/, int /*rows_out*/) {}
  /// A spectrum in the layout of spectrum_data() rearranged into the channel layout (symbols).
  virtual void to_channel_layout(const std::complex<double>* spectrum,
                                 std::complex<double>* out) const;

  int n_fast() const noexcept { return n_fast_; }
  int n_slow() const noexcept { return n_slow_; }
  std::size_t spectrum_size() const noexcept {
    return static_cast<std::size_t>(n_fast_ / 2 + 1) * static_cast<std::size_t>(n_slow_);
  }
  std::size_t real_size() const noexcept {
    return static_cast<std::size_t>(n_fast_) * static_cast<std::size_t>(n_slow_);
  }

 protected:
  FftEngine(int n_fast, int n_slow) : n_fast_(n_fast), n_slow_(n_slow) {}

  /// Pointwise spectrum[i] *= symbol[i], i < count.
  static void multiply(std::complex<double>* spectrum, const std::complex<double>* symbol,
                       std::size_t count) noexcept;

  std::vector<std::complex<double>> symbol_;  // set_convolution_symbol(), in the engine's layout
  std::vector<std::vector<std::complex<double>>> channels_;  // default channels (row-major)

 private:
  int n_fast_, n_slow_;
};

/// Circular convolution with a real symbol in single precision, for preconditioners: they need a
/// few correct digits only, and single precision halves the memory traffic of the transforms
/// (at 576×648 a transform pair takes 2.1 ms instead of 3.0). Sizes and layout as FftEngine.
class SingleCirculant {
 public:
  virtual ~SingleCirculant() = default;
  /// (n_fast/2+1)·n_slow real values in the layout of FftEngine::spectrum_data(), normalisation
  /// included (the transforms are unnormalised).
  virtual void set_symbol(const double* symbol) = 0;
  /// out = the mx × my block (fast index contiguous) of the convolution of `in`, an mx × my
  /// block zero-extended to the periodic grid (mx ≤ n_fast, my ≤ n_slow). Returns Σ in·out,
  /// accumulated in double precision.
  virtual double apply_dot(const double* in, double* out, int mx, int my) = 0;
};

/// A single-precision convolution for the backend, or nullptr when the backend has none (KISS:
/// callers then use an FftEngine in double precision).
std::unique_ptr<SingleCirculant> make_single_circulant(
    FftBackendKind kind, int n_fast, int n_slow, FftPlanning planning = FftPlanning::Estimate);

/// Creates an engine; Default resolves to the configure-time default. Throws NotSupportedError
/// when the requested backend was not built.
std::unique_ptr<FftEngine> make_fft_engine(FftBackendKind kind, int n_fast, int n_slow,
                                           FftPlanning planning = FftPlanning::Estimate);

/// Backends compiled into this build (Default: always true).
bool fft_backend_available(FftBackendKind kind) noexcept;

/// Default resolved to the configure-time choice (rollcontact::default_fft_backend).
FftBackendKind resolve_fft_backend(FftBackendKind kind) noexcept;

/// Smallest n ≥ n_min (n_min ≥ 1) whose only prime factors are 2, 3 and 5: sizes that both
/// backends transform fast (a prime factor such as 647 in 1294 makes KISS FFT O(n²)).
int good_fft_size(int n_min);

}  // namespace rollcontact::core
