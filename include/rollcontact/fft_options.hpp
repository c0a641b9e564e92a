#pragma once
// FFT choices a caller may make: which implementation, and how much planning effort. Kept apart
// from solve.hpp so that the FFT layer (src/core) does not include the solver API.

namespace rollcontact {

/// FFT implementation used by the convolution operators.
enum class FftBackendKind { Default, Fftw, Kiss };

/// How much effort FFT planning may take. Measure (FFTW_MEASURE) makes each transform 10–25 %
/// faster but costs seconds per new grid size on large grids; it pays off for long sequences.
enum class FftPlanning { Estimate, Measure };

}  // namespace rollcontact
