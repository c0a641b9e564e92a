#pragma once
// Approximate inverse of the 2×2 tangential influence block [C_xx C_xy; C_yx C_yy]/G as a
// block-circulant operator: the kernels are wrapped onto a periodic grid of FFT-friendly size
// (no padding), each frequency's 2×2 symbol is inverted once, and application costs two forward
// and two inverse transforms of a quarter of the padded size. Same idea as the normal
// preconditioner (normal/preconditioner.hpp, after Vollebregt 2014).

#include <complex>
#include <memory>
#include <vector>

#include "core/fft_backend.hpp"
#include "elastic/influence.hpp"
#include "rollcontact/grid.hpp"

namespace rollcontact::tangential {

class TangentialPreconditioner {
 public:
  /// Kernels of the symmetric operator (C_tt/G); their range must cover half the periodic size.
  TangentialPreconditioner(const elastic::Kernel& xx, const elastic::Kernel& xy,
                           const elastic::Kernel& yy, FftBackendKind backend);
  /// (zx, zy) ≈ A⁻¹ (rx, ry) over the whole grid (callers mask).
  void apply(const double* rx, const double* ry, double* zx, double* zy);

 private:
  int mx_, my_, nx_, ny_;
  std::unique_ptr<core::FftEngine> engine_;
  // Inverse symbol per half-spectrum entry (scaled), in the engine's channel layout.
  std::vector<double> ixx_, ixy_, iyy_;
};

/// r ← (I − T)⁻¹ r for steady rolling, T the shift by one element towards the trailing edge:
/// sums along each row from the leading edge (χ = 0: high ix; χ = π: ix = 0) downwards.
void cumulative_sum_from_leading_edge(const Grid& grid, double chi, std::vector<double>& rx,
                                      std::vector<double>& ry);

}  // namespace rollcontact::tangential
