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
      nx_(core::good_fft_size(xx.mx())),
      ny_(core::good_fft_size(xx.my())),
      engine_(core::make_fft_engine(backend, nx_, ny_)) {
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
  // The symbols in the engine's channel layout (a real symbol, as a complex spectrum).
  auto to_layout = [&](std::vector<double>& v) {
    std::vector<std::complex<double>> spectrum(v.begin(), v.end()), layout(nspec);
    engine_->to_channel_layout(spectrum.data(), layout.data());
    for (std::size_t q = 0; q < nspec; ++q) v[q] = layout[q].real();
  };
  to_layout(ixx_);
  to_layout(ixy_);
  to_layout(iyy_);
  // Channels 0, 1: transformed residuals; 2, 3: the results being formed.
  engine_->set_channel_count(4);
}

void TangentialPreconditioner::apply(const double* rx, const double* ry, double* zx, double* zy) {
  const std::size_t nspec = engine_->spectrum_size();
  double* real = engine_->real_data();
  auto forward = [&](const double* r, int c) {
    for (int iy = 0; iy < my_; ++iy) {
      double* dst = real + static_cast<std::size_t>(nx_) * iy;
      std::copy_n(r + static_cast<std::size_t>(mx_) * iy, mx_, dst);
      std::fill(dst + mx_, dst + nx_, 0.0);
    }
    engine_->forward_to_channel(my_, c);
  };
  auto inverse = [&](int c, double* z) {
    engine_->inverse_from_channel(c, my_);
    for (int iy = 0; iy < my_; ++iy)
      std::copy_n(real + static_cast<std::size_t>(nx_) * iy, mx_,
                  z + static_cast<std::size_t>(mx_) * iy);
  };
  forward(rx, 0);
  forward(ry, 1);
  const std::complex<double>* hx = engine_->channel(0);
  const std::complex<double>* hy = engine_->channel(1);
  std::complex<double>* ox = engine_->channel(2);
  std::complex<double>* oy = engine_->channel(3);
  for (std::size_t q = 0; q < nspec; ++q) {
    ox[q] = ixx_[q] * hx[q] + ixy_[q] * hy[q];
    oy[q] = ixy_[q] * hx[q] + iyy_[q] * hy[q];
  }
  inverse(2, zx);
  inverse(3, zy);
}

void cumulative_sum_from_leading_edge(const Grid& grid, double chi, std::vector<double>& rx,
                                      std::vector<double>& ry) {
  const bool forward = std::cos(chi) < 0.0;  // χ = π: leading edge at ix = 0
  for (int iy = 0; iy < grid.my; ++iy) {
    double ax = 0.0, ay = 0.0;
    for (int k = 0; k < grid.mx; ++k) {
      const int ix = forward ? k : grid.mx - 1 - k;
      const std::size_t i = grid.index(ix, iy);
      ax += rx[i];
      ay += ry[i];
      rx[i] = ax;
      ry[i] = ay;
    }
  }
}

}  // namespace rollcontact::tangential
