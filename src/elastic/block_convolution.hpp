#pragma once
// u_i = Σ_j K_ij * p_j for a small block of Toeplitz operators (tangential 2×2 block, couplings).
// Each input is transformed once and each output inverse-transformed once, so a 2×2 block costs
// two forward and two inverse FFTs instead of four pairs.

#include <complex>
#include <memory>
#include <vector>

#include "core/fft_backend.hpp"
#include "elastic/influence.hpp"
#include "elastic/interaction.hpp"

namespace rollcontact::elastic {

class BlockConvolution {
 public:
  /// kernels[i * n_in + j] is K_ij or nullptr for a zero block; all kernels share mx, my.
  BlockConvolution(int n_out, int n_in, const std::vector<const Kernel*>& kernels,
                   FftBackendKind backend, FftPlanning planning = FftPlanning::Estimate);

  /// p[j] and u[i] point at mx*my values (ix fastest); u is overwritten. No allocation.
  void apply(const double* const* p, double* const* u);

  /// From now on every block is attenuated between parts (one product per part); nullptr: full.
  void set_interaction(InteractionPtr interaction) { interaction_ = std::move(interaction); }
  const Interaction* interaction() const noexcept { return interaction_.get(); }

  int n_out() const noexcept { return n_out_; }
  int n_in() const noexcept { return n_in_; }

 private:
  int n_out_, n_in_, mx_, my_;
  std::unique_ptr<core::FftEngine> engine_;
  /// Symbol of block (i, j) in the engine's channel layout, or nullptr for a zero block.
  const std::complex<double>* block(int i, int j) const noexcept;
  void apply_full(const double* const* p, double* const* u);
  InteractionPtr interaction_;
  PartwiseProduct partwise_;

  // Distinct kernel spectra (normalisation included) and, per block, the index of its spectrum
  // (−1: zero block).
  std::vector<std::vector<std::complex<double>>> spectra_;
  std::vector<int> block_spectrum_;
};

}  // namespace rollcontact::elastic
