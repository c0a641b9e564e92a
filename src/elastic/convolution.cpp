// u = A·p for one Toeplitz block: zero-padded FFT convolution and the dense oracle.

#include "elastic/convolution.hpp"

#include <algorithm>
#include <utility>

namespace rollcontact::elastic {

namespace {

/// Index of offset d (|d| < m ≤ (n+1)/2) in a circular array of length n.
int wrap(int d, int n) {
  return d >= 0 ? d : d + n;
}

}  // namespace

FftConvolution::FftConvolution(const Kernel& kernel, FftBackendKind backend, FftPlanning planning)
    : mx_(kernel.mx()), my_(kernel.my()) {
  // Padding to ≥ 2m−1 keeps the offsets −(m−1) … m−1 distinct modulo the padded length, so the
  // circular convolution equals the linear one on the first m entries.
  const int nf = good_fft_size(2 * mx_ - 1);
  const int ns = good_fft_size(2 * my_ - 1);
  engine_ = make_fft_engine(backend, nf, ns, planning);

  double* real = engine_->real_data();
  std::fill_n(real, engine_->real_size(), 0.0);
  for (int diy = -(my_ - 1); diy < my_; ++diy) {
    double* dst = real + static_cast<std::size_t>(wrap(diy, ns)) * static_cast<std::size_t>(nf);
    for (int dix = -(mx_ - 1); dix < mx_; ++dix) dst[wrap(dix, nf)] = kernel.at(dix, diy);
  }
  engine_->execute_forward(ns);
  // The transforms are unnormalised: fold 1/(nf·ns) into the kernel once.
  const double scale = 1.0 / (static_cast<double>(nf) * static_cast<double>(ns));
  const std::complex<double>* spectrum = engine_->spectrum_data();
  kernel_hat_.resize(engine_->spectrum_size());
  for (std::size_t i = 0; i < kernel_hat_.size(); ++i) kernel_hat_[i] = scale * spectrum[i];
  // One pass through the pruned transforms lets the engine make its plans now, not in apply().
  std::fill_n(real, engine_->real_size(), 0.0);
  engine_->execute_forward(my_);
  engine_->execute_inverse(my_);
}

void FftConvolution::apply(const double* p, double* u) {
  const std::size_t nf = static_cast<std::size_t>(engine_->n_fast());
  const std::size_t mx = static_cast<std::size_t>(mx_);
  double* real = engine_->real_data();
  // Rows ≥ my are declared zero to the engine; only the padding of the first my rows is cleared.
  for (int iy = 0; iy < my_; ++iy) {
    double* dst = real + static_cast<std::size_t>(iy) * nf;
    std::copy_n(p + static_cast<std::size_t>(iy) * mx, mx, dst);
    std::fill(dst + mx, dst + nf, 0.0);
  }
  engine_->execute_forward(my_);
  // Complex product written out: std::complex's operator* handles inf/NaN per C Annex G (a
  // library call per element without -ffast-math), which doubled the cost of this loop.
  std::complex<double>* spectrum = engine_->spectrum_data();
  const std::complex<double>* k = kernel_hat_.data();
  const std::size_t n = kernel_hat_.size();
  for (std::size_t i = 0; i < n; ++i) {
    const double ar = spectrum[i].real(), ai = spectrum[i].imag();
    const double br = k[i].real(), bi = k[i].imag();
    spectrum[i] = std::complex<double>(ar * br - ai * bi, ar * bi + ai * br);
  }
  engine_->execute_inverse(my_);
  for (int iy = 0; iy < my_; ++iy) {
    std::copy_n(real + static_cast<std::size_t>(iy) * nf, mx,
                u + static_cast<std::size_t>(iy) * mx);
  }
}

DenseConvolution::DenseConvolution(Kernel kernel) : kernel_(std::move(kernel)) {}

void DenseConvolution::apply(const double* p, double* u) {
  const int mx = kernel_.mx(), my = kernel_.my();
  const std::size_t n = static_cast<std::size_t>(mx) * static_cast<std::size_t>(my);
  std::fill_n(u, n, 0.0);
  for (int jy = 0; jy < my; ++jy) {
    for (int jx = 0; jx < mx; ++jx) {
      const double pj = p[static_cast<std::size_t>(jx + mx * jy)];
      if (pj == 0.0) continue;
      for (int iy = 0; iy < my; ++iy) {
        double* ui = u + static_cast<std::size_t>(mx) * static_cast<std::size_t>(iy);
        for (int ix = 0; ix < mx; ++ix) ui[ix] += kernel_.at(ix - jx, iy - jy) * pj;
      }
    }
  }
}

}  // namespace rollcontact::elastic
