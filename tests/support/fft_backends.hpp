#pragma once
// The FFT backends built into this binary, for parametrised tests.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/fft_backend.hpp"

namespace rollcontact::test_support {

inline std::vector<FftBackendKind> available_backends() {
  std::vector<FftBackendKind> kinds;
  for (FftBackendKind k : {FftBackendKind::Fftw, FftBackendKind::Kiss}) {
    if (core::fft_backend_available(k)) kinds.push_back(k);
  }
  return kinds;
}

inline std::string backend_name(FftBackendKind k) {
  switch (k) {
    case FftBackendKind::Fftw:
      return "fftw";
    case FftBackendKind::Kiss:
      return "kiss";
    default:
      return "default";
  }
}

inline std::string backend_param_name(const ::testing::TestParamInfo<FftBackendKind>& p) {
  return backend_name(p.param);
}

}  // namespace rollcontact::test_support
