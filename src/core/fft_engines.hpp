#pragma once
// Internal: constructors of the concrete FFT engines, used by the factory in fft_backend.cpp.

#include <memory>
#include <string>

#include "core/fft_backend.hpp"

namespace rollcontact::core::detail {

/// FFTW3 engine (only when ROLLCONTACT_HAVE_FFTW; otherwise throws NotSupportedError).
std::unique_ptr<FftEngine> make_fftw_engine(int n_fast, int n_slow, FftPlanning planning);

/// FFTW3 single-precision convolution (nullptr when FFTW is not built).
std::unique_ptr<SingleCirculant> make_fftw_single_circulant(int n_fast, int n_slow,
                                                            FftPlanning planning);

/// Whether this process made an FFTW plan that no wisdom held (rollcontact/fft_plan_cache.hpp).
bool fftw_planned_beyond_wisdom() noexcept;

/// Single-precision wisdom (FFTW text) to read before the first single-precision plan.
void defer_single_precision_wisdom(std::string text);
/// Whether this process made a single-precision FFTW plan.
bool fftw_single_precision_used() noexcept;

/// Double-precision KISS FFT engine (Eigen's unsupported FFT module).
std::unique_ptr<FftEngine> make_kiss_engine(int n_fast, int n_slow);

}  // namespace rollcontact::core::detail
