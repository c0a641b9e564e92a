#include "tangential/tangential_preconditioner.hpp"

#include <algorithm>
#include <cmath>

namespace rollcontact::tangential {

TangentialPreconditioner::TangentialPreconditioner(const elastic::Kernel& xx,
                                                   const elastic::Kernel& xy,
                                                   const elastic::Kernel& yy,
                                                   FftBackendKind backend)
    : mx_(xx.mx()),
      my_(xx.my()),
      nx_(elastic::good_fft_size(xx.mx())),
      ny_(elastic::good_fft_size(xx.my())),
      engine_(elastic::make_fft_engine(backend, nx_, ny_)) {
  const std::size_t nspec = engine_->spectrum_size();
  auto symbol = [&](const elastic::Kernel& k) {
    double* real = engine_->real_data();
    for (int j = 0; j < ny_; ++j) {
      const int oy = std::clamp(j <= ny_ / 2 ? j : j - ny_, -(my_ - 1), my_ - 1);
      for (int i = 0; i < nx_; ++i) {
        const int ox = std::clamp(i <= nx_ / 2 ? i : i - nx_, -(mx_ - 1), mx_ - 1);
        real[static_cast<std::size_t>(i) + static_cast<std::size_t>(nx_) * j] = k.at(ox, oy);
      }
    }
    engine_->execute_forward(ny_);
    std::vector<double> s(nspec);
    const std::complex<double>* spec = engine_->spectrum_data();
    for (std::size_t q = 0; q < nspec; ++q) s[q] = spec[q].real();
    return s;
  };
  const std::vector<double> sxx = symbol(xx), sxy = symbol(xy), syy = symbol(yy);
  // Lower bounds as for the normal preconditioner: the wrapped (Strang) circulant may have tiny
  // or negative eigenvalues at the highest frequencies.
  const double floor_xx = 0.25 * xx.at(0, 0), floor_yy = 0.25 * yy.at(0, 0);
  const double scale = 1.0 / (static_cast<double>(nx_) * static_cast<double>(ny_));
  ixx_.resize(nspec);
  ixy_.resize(nspec);
  iyy_.resize(nspec);
  for (std::size_t q = 0; q < nspec; ++q) {
    const double a = std::max(sxx[q], floor_xx), c = std::max(syy[q], floor_yy);
    double b = sxy[q];
    // Keep the 2×2 symbol positive definite.
    const double bmax = 0.9 * std::sqrt(a * c);
    b = std::clamp(b, -bmax, bmax);
    const double det = a * c - b * b;
    ixx_[q] = scale * c / det;
    ixy_[q] = -scale * b / det;
    iyy_[q] = scale * a / det;
  }
  hx_.resize(nspec);
  hy_.resize(nspec);
}

void TangentialPreconditioner::apply(const double* rx, const double* ry, double* zx, double* zy) {
  const std::size_t nspec = engine_->spectrum_size();
  double* real = engine_->real_data();
  std::complex<double>* spec = engine_->spectrum_data();
  auto forward = [&](const double* r, std::vector<std::complex<double>>& out) {
    for (int iy = 0; iy < my_; ++iy) {
      double* dst = real + static_cast<std::size_t>(nx_) * iy;
      std::copy_n(r + static_cast<std::size_t>(mx_) * iy, mx_, dst);
      std::fill(dst + mx_, dst + nx_, 0.0);
    }
    engine_->execute_forward(my_);
    std::copy_n(spec, nspec, out.data());
  };
  auto inverse = [&](double* z) {
    engine_->execute_inverse(my_);
    for (int iy = 0; iy < my_; ++iy)
      std::copy_n(real + static_cast<std::size_t>(nx_) * iy, mx_,
                  z + static_cast<std::size_t>(mx_) * iy);
  };
  forward(rx, hx_);
  forward(ry, hy_);
  for (std::size_t q = 0; q < nspec; ++q) spec[q] = ixx_[q] * hx_[q] + ixy_[q] * hy_[q];
  inverse(zx);
  for (std::size_t q = 0; q < nspec; ++q) spec[q] = ixy_[q] * hx_[q] + iyy_[q] * hy_[q];
  inverse(zy);
}

}  // namespace rollcontact::tangential
