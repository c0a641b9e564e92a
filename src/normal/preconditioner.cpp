#include "normal/preconditioner.hpp"

#include <algorithm>
#include <cmath>

#include "elastic/influence.hpp"

namespace rollcontact::normal {

void IdentityPreconditioner::apply(const double* r, double* z) {
  std::copy(r, r + n_, z);
}

CirculantPreconditioner::CirculantPreconditioner(const Grid& grid, const CombinedMaterial& material,
                                                 FftBackendKind backend, FftPlanning planning)
    : mx_(grid.mx),
      my_(grid.my),
      nx_(elastic::good_fft_size(grid.mx)),
      ny_(elastic::good_fft_size(grid.my)),
      engine_(elastic::make_fft_engine(backend, nx_, ny_, planning)),
      inverse_symbol_(engine_->spectrum_size()),
      work_(engine_->real_size()),
      spectrum_(engine_->spectrum_size()) {
  // Wrapped kernel: offset i is represented by the nearest periodic image (|i| ≤ n/2).
  for (int j = 0; j < ny_; ++j) {
    const int oy = j <= ny_ / 2 ? j : j - ny_;
    for (int i = 0; i < nx_; ++i) {
      const int ox = i <= nx_ / 2 ? i : i - nx_;
      work_[static_cast<std::size_t>(i) + static_cast<std::size_t>(nx_) * j] =
          elastic::influence_coefficient(elastic::Component::nn, ox * grid.dx, oy * grid.dy,
                                         grid.dx, grid.dy, material.nu, 0.0) /
          material.g;
    }
  }
  const double diagonal = work_[0];
  engine_->forward(work_.data(), spectrum_.data());
  // The symbol of a symmetric kernel is real. The wrapped (Strang) circulant may have small or
  // negative eigenvalues at the highest frequencies; bound them below by a fraction of the
  // diagonal coefficient, which is the symbol's typical size there.
  const double floor = 0.25 * diagonal;
  const double scale = 1.0 / (static_cast<double>(nx_) * static_cast<double>(ny_));
  for (std::size_t k = 0; k < spectrum_.size(); ++k)
    inverse_symbol_[k] = scale / std::max(spectrum_[k].real(), floor);
}

void CirculantPreconditioner::apply(const double* r, double* z) {
  std::fill(work_.begin(), work_.end(), 0.0);
  for (int iy = 0; iy < my_; ++iy)
    std::copy(r + static_cast<std::size_t>(mx_) * iy, r + static_cast<std::size_t>(mx_) * (iy + 1),
              work_.begin() + static_cast<std::ptrdiff_t>(nx_) * iy);
  engine_->forward(work_.data(), spectrum_.data());
  for (std::size_t k = 0; k < spectrum_.size(); ++k) spectrum_[k] *= inverse_symbol_[k];
  engine_->inverse(spectrum_.data(), work_.data());
  for (int iy = 0; iy < my_; ++iy)
    std::copy(work_.begin() + static_cast<std::ptrdiff_t>(nx_) * iy,
              work_.begin() + static_cast<std::ptrdiff_t>(nx_) * iy + mx_,
              z + static_cast<std::size_t>(mx_) * iy);
}

}  // namespace rollcontact::normal
