// Backend selection for the FFT engines.

#include "core/fft_backend.hpp"

#include <algorithm>
#include <string>
#include <string_view>

#include "core/fft_engines.hpp"
#include "rollcontact/errors.hpp"
#include "rollcontact/version.hpp"

namespace rollcontact::core {

FftBackendKind resolve_fft_backend(FftBackendKind kind) noexcept {
  if (kind != FftBackendKind::Default) return kind;
  return std::string_view(default_fft_backend) == "fftw" ? FftBackendKind::Fftw
                                                         : FftBackendKind::Kiss;
}

bool fft_backend_available(FftBackendKind kind) noexcept {
  switch (kind) {
    case FftBackendKind::Default:
      return fft_backend_available(resolve_fft_backend(kind));
    case FftBackendKind::Fftw:
      return ROLLCONTACT_HAVE_FFTW != 0;
    case FftBackendKind::Kiss:
      return true;
  }
  return false;
}

void FftEngine::multiply(std::complex<double>* spectrum, const std::complex<double>* symbol,
                         std::size_t count) noexcept {
  // Complex product written out: std::complex's operator* handles inf/NaN per C Annex G (a
  // library call per element without -ffast-math), which doubled the cost of this loop.
  for (std::size_t i = 0; i < count; ++i) {
    const double ar = spectrum[i].real(), ai = spectrum[i].imag();
    const double br = symbol[i].real(), bi = symbol[i].imag();
    spectrum[i] = std::complex<double>(ar * br - ai * bi, ar * bi + ai * br);
  }
}

void FftEngine::set_convolution_symbol(const std::complex<double>* symbol) {
  symbol_.assign(symbol, symbol + spectrum_size());
}

void FftEngine::execute_convolution(int rows_in, int rows_out) {
  execute_forward(rows_in);
  multiply(spectrum_data(), symbol_.data(), spectrum_size());
  execute_inverse(rows_out);
}

void FftEngine::set_channel_count(int count) {
  channels_.assign(static_cast<std::size_t>(count),
                   std::vector<std::complex<double>>(spectrum_size()));
}

void FftEngine::forward_to_channel(int rows_in, int c) {
  execute_forward(rows_in);
  std::copy_n(spectrum_data(), spectrum_size(), channel(c));
}

void FftEngine::inverse_from_channel(int c, int rows_out) {
  std::copy_n(channel(c), spectrum_size(), spectrum_data());
  execute_inverse(rows_out);
}

void FftEngine::to_channel_layout(const std::complex<double>* spectrum,
                                  std::complex<double>* out) const {
  std::copy_n(spectrum, spectrum_size(), out);
}

std::unique_ptr<FftEngine> make_fft_engine(FftBackendKind kind, int n_fast, int n_slow,
                                           FftPlanning planning) {
  if (n_fast < 1 || n_slow < 1) {
    throw ProblemError("FFT size must be at least 1 x 1, got " + std::to_string(n_fast) + " x " +
                       std::to_string(n_slow));
  }
  const FftBackendKind resolved = resolve_fft_backend(kind);
  if (!fft_backend_available(resolved)) {
    throw NotSupportedError(
        "the FFTW backend was not built (configure with ROLLCONTACT_WITH_FFTW)");
  }
  if (resolved == FftBackendKind::Fftw) return detail::make_fftw_engine(n_fast, n_slow, planning);
  return detail::make_kiss_engine(n_fast, n_slow);
}

std::unique_ptr<SingleCirculant> make_single_circulant(FftBackendKind kind, int n_fast, int n_slow,
                                                       FftPlanning planning) {
  if (n_fast < 1 || n_slow < 1) return nullptr;
  if (resolve_fft_backend(kind) != FftBackendKind::Fftw) return nullptr;
  return detail::make_fftw_single_circulant(n_fast, n_slow, planning);
}

int good_fft_size(int n_min) {
  if (n_min < 1) throw ProblemError("good_fft_size: size must be at least 1");
  for (int n = n_min;; ++n) {
    int m = n;
    for (int f : {2, 3, 5}) {
      while (m % f == 0) m /= f;
    }
    if (m == 1) return n;
  }
}

}  // namespace rollcontact::core
