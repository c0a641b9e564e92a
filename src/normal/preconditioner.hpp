#pragma once
// Approximate inverses of the normal influence operator, used to precondition NormCG.

#include <complex>
#include <memory>
#include <vector>

#include "core/fft_backend.hpp"
#include "elastic/influence.hpp"
#include "rollcontact/grid.hpp"
#include "rollcontact/solution.hpp"

namespace rollcontact::normal {

/// z ≈ A⁻¹ r for residuals r that vanish outside the current contact set.
class Preconditioner {
 public:
  virtual ~Preconditioner() = default;
  /// r and z have grid.size() entries; entries of r outside the contact set are zero on input,
  /// z is overwritten on the whole grid (callers mask it).
  virtual void apply(const double* r, double* z) = 0;
  /// apply() that also returns Σ r_I·z_I, summed in index order (fused into the last pass over z).
  virtual double apply_dot(const double* r, double* z) = 0;
};

/// Identity (unpreconditioned CG), for tests and comparison.
class IdentityPreconditioner final : public Preconditioner {
 public:
  explicit IdentityPreconditioner(std::size_t n) : n_(n) {}
  void apply(const double* r, double* z) override;
  double apply_dot(const double* r, double* z) override;

 private:
  std::size_t n_;
};

/// Circulant ("Strang") approximate inverse: the influence coefficients C_nn are wrapped onto a
/// periodic nx × ny grid (nx ≥ mx, ny ≥ my, FFT-friendly sizes, no zero padding), transformed
/// once, and the inverse symbol is applied by one FFT pair of a quarter of the size of the padded
/// product. This follows the idea of Vollebregt (2014, J. Comput. Phys. 257): an FFT-based
/// approximate inverse whose cost is small next to the product A·p.
class CirculantPreconditioner final : public Preconditioner {
 public:
  /// `kernel` (optional): C_nn/G of the grid, whose values are taken instead of evaluating the
  /// closed forms again (offsets beyond it still are).
  CirculantPreconditioner(const Grid& grid, const CombinedMaterial& material,
                          FftBackendKind backend, FftPlanning planning = FftPlanning::Estimate,
                          const elastic::Kernel* kernel = nullptr);
  void apply(const double* r, double* z) override;
  double apply_dot(const double* r, double* z) override;
  int nx() const noexcept { return nx_; }
  int ny() const noexcept { return ny_; }

 private:
  void convolve(const double* r);  // M·r into the first my rows of the engine's real array

  int mx_, my_, nx_, ny_;
  std::unique_ptr<core::FftEngine> engine_;        // holds the inverse symbol (with 1/(nx ny))
  std::unique_ptr<core::SingleCirculant> single_;  // instead of engine_ where available
};

}  // namespace rollcontact::normal
