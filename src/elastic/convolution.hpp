#pragma once
// u = A·p for one Toeplitz (convolution) block of the influence matrix: by zero-padded FFT with
// the kernel transformed once, or by dense summation (tiny grids, test oracle).

#include <complex>
#include <memory>
#include <vector>

#include "core/fft_backend.hpp"
#include "core/linear_operator.hpp"
#include "elastic/influence.hpp"
#include "elastic/interaction.hpp"

namespace rollcontact::elastic {

/// The grid operators below are core::LinearOperators: u_I = Σ_J K(I−J) p_J over the whole
/// mx × my grid.
using core::LinearOperator;

/// FFT-based product; kernel spectrum and plans made in the constructor. The padded size is
/// good_fft_size(2mx−1) × good_fft_size(2my−1): at least 2m−1 avoids wrap-around of the linear
/// convolution, and 2-3-5-smooth sizes keep both backends fast (2mx itself may contain a large
/// prime). apply() allocates nothing.
class FftConvolution final : public LinearOperator {
 public:
  FftConvolution(const Kernel& kernel, FftBackendKind backend,
                 FftPlanning planning = FftPlanning::Estimate);
  void apply(const double* p, double* u) override;
  double apply_dot(const double* p, double* u) override;
  const core::FftEngine& engine() const noexcept { return *engine_; }
  int mx() const noexcept { return mx_; }
  int my() const noexcept { return my_; }

  /// From now on u_I = Σ_J f(part I, part J) K(I−J) p_J (one product per part); nullptr: full.
  void set_interaction(InteractionPtr interaction) { interaction_ = std::move(interaction); }
  const Interaction* interaction() const noexcept { return interaction_.get(); }

 private:
  void convolve(const double* p);  // A·p into the first my rows of the engine's real array
  void apply_full(const double* p, double* u);

  int mx_, my_;
  std::unique_ptr<core::FftEngine> engine_;  // holds the kernel spectrum (scaled by 1/(nf ns))
  InteractionPtr interaction_;
  PartwiseProduct partwise_;
};

/// Dense O(N²) product, the oracle.
class DenseConvolution final : public LinearOperator {
 public:
  explicit DenseConvolution(Kernel kernel);
  void apply(const double* p, double* u) override;
  double apply_dot(const double* p, double* u) override;
  const Kernel& kernel() const noexcept { return kernel_; }

 private:
  Kernel kernel_;
};

}  // namespace rollcontact::elastic
