#include "elastic/block_convolution.hpp"

#include <algorithm>
#include <stdexcept>

namespace rollcontact::elastic {

namespace {

int wrap(int d, int n) {
  return d >= 0 ? d : d + n;
}

}  // namespace

BlockConvolution::BlockConvolution(int n_out, int n_in, const std::vector<const Kernel*>& kernels,
                                   FftBackendKind backend, FftPlanning planning)
    : n_out_(n_out), n_in_(n_in), mx_(0), my_(0) {
  if (kernels.size() != static_cast<std::size_t>(n_out) * static_cast<std::size_t>(n_in))
    throw std::invalid_argument("BlockConvolution: wrong number of kernels");
  for (const Kernel* k : kernels)
    if (k != nullptr) {
      mx_ = k->mx();
      my_ = k->my();
    }
  if (mx_ == 0) throw std::invalid_argument("BlockConvolution: all blocks are zero");
  const int nf = good_fft_size(2 * mx_ - 1);
  const int ns = good_fft_size(2 * my_ - 1);
  engine_ = make_fft_engine(backend, nf, ns, planning);
  const double scale = 1.0 / (static_cast<double>(nf) * static_cast<double>(ns));

  double* real = engine_->real_data();
  kernel_hat_.resize(kernels.size());
  for (std::size_t b = 0; b < kernels.size(); ++b) {
    const Kernel* kernel = kernels[b];
    if (kernel == nullptr) continue;
    std::fill_n(real, engine_->real_size(), 0.0);
    for (int diy = -(my_ - 1); diy < my_; ++diy) {
      double* dst = real + static_cast<std::size_t>(wrap(diy, ns)) * static_cast<std::size_t>(nf);
      for (int dix = -(mx_ - 1); dix < mx_; ++dix) dst[wrap(dix, nf)] = kernel->at(dix, diy);
    }
    engine_->execute_forward(ns);
    const std::complex<double>* spectrum = engine_->spectrum_data();
    kernel_hat_[b].assign(spectrum, spectrum + engine_->spectrum_size());
    for (auto& v : kernel_hat_[b]) v *= scale;
  }
  input_hat_.assign(static_cast<std::size_t>(n_in),
                    std::vector<std::complex<double>>(engine_->spectrum_size()));
  // Make the pruned plans now so that apply() never plans.
  std::fill_n(real, engine_->real_size(), 0.0);
  engine_->execute_forward(my_);
  engine_->execute_inverse(my_);
}

void BlockConvolution::apply(const double* const* p, double* const* u) {
  const std::size_t nf = static_cast<std::size_t>(engine_->n_fast());
  const std::size_t mx = static_cast<std::size_t>(mx_);
  const std::size_t nspec = engine_->spectrum_size();
  double* real = engine_->real_data();
  std::complex<double>* spectrum = engine_->spectrum_data();

  for (int j = 0; j < n_in_; ++j) {
    for (int iy = 0; iy < my_; ++iy) {
      double* dst = real + static_cast<std::size_t>(iy) * nf;
      std::copy_n(p[j] + static_cast<std::size_t>(iy) * mx, mx, dst);
      std::fill(dst + mx, dst + nf, 0.0);
    }
    engine_->execute_forward(my_);
    std::copy_n(spectrum, nspec, input_hat_[static_cast<std::size_t>(j)].data());
  }
  for (int i = 0; i < n_out_; ++i) {
    std::fill_n(spectrum, nspec, std::complex<double>(0.0, 0.0));
    bool any = false;
    for (int j = 0; j < n_in_; ++j) {
      const auto& k = kernel_hat_[static_cast<std::size_t>(i * n_in_ + j)];
      if (k.empty()) continue;
      any = true;
      const std::complex<double>* a = input_hat_[static_cast<std::size_t>(j)].data();
      // Written out: std::complex operator* calls a library routine per element (Annex G).
      for (std::size_t s = 0; s < nspec; ++s) {
        const double ar = a[s].real(), ai = a[s].imag();
        const double br = k[s].real(), bi = k[s].imag();
        spectrum[s] += std::complex<double>(ar * br - ai * bi, ar * bi + ai * br);
      }
    }
    if (!any) {
      std::fill_n(u[i], mx * static_cast<std::size_t>(my_), 0.0);
      continue;
    }
    engine_->execute_inverse(my_);
    for (int iy = 0; iy < my_; ++iy)
      std::copy_n(real + static_cast<std::size_t>(iy) * nf, mx,
                  u[i] + static_cast<std::size_t>(iy) * mx);
  }
}

}  // namespace rollcontact::elastic
