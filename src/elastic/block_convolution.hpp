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

/// Kernel spectra shared between the products of one operator set: the C_xx of the 2×2 product
/// and of the 3×3 one are the same transform (the same bits), made and stored once. Keyed by the
/// kernel's values and the transform size; one FFT backend per cache, and the kernels must
/// outlive it.
class SpectrumCache {
 public:
  using Spectrum = std::shared_ptr<const std::vector<std::complex<double>>>;
  /// The spectrum of a kernel equal to `k` on an nf × ns engine, or null.
  Spectrum find(const Kernel& k, int nf, int ns) const;
  void add(const Kernel& k, int nf, int ns, Spectrum spectrum);

 private:
  struct Entry {
    const Kernel* kernel;
    int nf, ns;
    Spectrum spectrum;
  };
  std::vector<Entry> entries_;
};

class BlockConvolution {
 public:
  /// kernels[i * n_in + j] is K_ij or nullptr for a zero block; all kernels share mx, my.
  /// `cache` (optional): spectra shared with the other products of an operator set.
  BlockConvolution(int n_out, int n_in, const std::vector<const Kernel*>& kernels,
                   FftBackendKind backend, FftPlanning planning = FftPlanning::Estimate,
                   SpectrumCache* cache = nullptr);

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
  std::vector<SpectrumCache::Spectrum> spectra_;
  std::vector<int> block_spectrum_;
};

}  // namespace rollcontact::elastic
