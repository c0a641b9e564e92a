// u = A·p for one Toeplitz block: zero-padded FFT convolution and the dense oracle.

#include "elastic/convolution.hpp"

#include <algorithm>
#include <complex>
#include <utility>
#include <vector>

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
  const int nf = core::good_fft_size(2 * mx_ - 1);
  const int ns = core::good_fft_size(2 * my_ - 1);
  engine_ = core::make_fft_engine(backend, nf, ns, planning);

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
  std::vector<std::complex<double>> kernel_hat(engine_->spectrum_size());
  for (std::size_t i = 0; i < kernel_hat.size(); ++i) kernel_hat[i] = scale * spectrum[i];
  engine_->set_convolution_symbol(kernel_hat.data());
  // The pruned transforms are planned now, not in apply().
  std::fill_n(real, engine_->real_size(), 0.0);
  engine_->prepare_transforms(my_, my_);
}

void FftConvolution::apply(const double* p, double* u) {
  if (interaction_) {
    const std::size_t n = static_cast<std::size_t>(mx_) * static_cast<std::size_t>(my_);
    partwise_.apply(
        *interaction_, n, 1, 1, &p, &u,
        [this](const double* const* in, double* const* out) { apply_full(in[0], out[0]); });
    return;
  }
  apply_full(p, u);
}

void FftConvolution::apply_full(const double* p, double* u) {
  convolve(p);
  const std::size_t nf = static_cast<std::size_t>(engine_->n_fast());
  const std::size_t mx = static_cast<std::size_t>(mx_);
  const double* real = engine_->real_data();
  for (int iy = 0; iy < my_; ++iy) {
    std::copy_n(real + static_cast<std::size_t>(iy) * nf, mx,
                u + static_cast<std::size_t>(iy) * mx);
  }
}

double FftConvolution::apply_dot(const double* p, double* u) {
  if (interaction_) {
    apply(p, u);
    const std::size_t n = static_cast<std::size_t>(mx_) * static_cast<std::size_t>(my_);
    double dot = 0.0;
    for (std::size_t i = 0; i < n; ++i) dot += p[i] * u[i];
    return dot;
  }
  convolve(p);
  const std::size_t nf = static_cast<std::size_t>(engine_->n_fast());
  const std::size_t mx = static_cast<std::size_t>(mx_);
  const double* real = engine_->real_data();
  // Four partial sums: one running sum is bound by the latency of the addition (at 575×647
  // about 0.5 ms, 3 % of a product), four independent ones are not.
  double dot[4] = {0.0, 0.0, 0.0, 0.0};
  for (int iy = 0; iy < my_; ++iy) {
    const double* src = real + static_cast<std::size_t>(iy) * nf;
    const double* pr = p + static_cast<std::size_t>(iy) * mx;
    double* ur = u + static_cast<std::size_t>(iy) * mx;
    std::size_t ix = 0;
    for (; ix + 4 <= mx; ix += 4) {
      for (std::size_t l = 0; l < 4; ++l) {
        ur[ix + l] = src[ix + l];
        dot[l] += pr[ix + l] * src[ix + l];
      }
    }
    for (; ix < mx; ++ix) {
      ur[ix] = src[ix];
      dot[0] += pr[ix] * src[ix];
    }
  }
  return (dot[0] + dot[1]) + (dot[2] + dot[3]);
}

void FftConvolution::convolve(const double* p) {
  const std::size_t nf = static_cast<std::size_t>(engine_->n_fast());
  const std::size_t mx = static_cast<std::size_t>(mx_);
  double* real = engine_->real_data();
  // Rows ≥ my are declared zero to the engine; only the padding of the first my rows is cleared.
  for (int iy = 0; iy < my_; ++iy) {
    double* dst = real + static_cast<std::size_t>(iy) * nf;
    std::copy_n(p + static_cast<std::size_t>(iy) * mx, mx, dst);
    std::fill(dst + mx, dst + nf, 0.0);
  }
  engine_->execute_convolution(my_, my_);
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

double DenseConvolution::apply_dot(const double* p, double* u) {
  apply(p, u);
  const std::size_t n =
      static_cast<std::size_t>(kernel_.mx()) * static_cast<std::size_t>(kernel_.my());
  double dot = 0.0;
  for (std::size_t i = 0; i < n; ++i) dot += p[i] * u[i];
  return dot;
}

}  // namespace rollcontact::elastic
