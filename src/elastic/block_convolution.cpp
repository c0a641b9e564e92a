#include "elastic/block_convolution.hpp"

#include <algorithm>
#include <stdexcept>

namespace rollcontact::elastic {

namespace {

int wrap(int d, int n) {
  return d >= 0 ? d : d + n;
}

}  // namespace

SpectrumCache::Spectrum SpectrumCache::find(const Kernel& k, int nf, int ns) const {
  for (const Entry& e : entries_)
    if (e.nf == nf && e.ns == ns && e.kernel->mx() == k.mx() && e.kernel->my() == k.my() &&
        (e.kernel == &k || e.kernel->data() == k.data()))
      return e.spectrum;
  return nullptr;
}

void SpectrumCache::add(const Kernel& k, int nf, int ns, Spectrum spectrum) {
  entries_.push_back({&k, nf, ns, std::move(spectrum)});
}

BlockConvolution::BlockConvolution(int n_out, int n_in, const std::vector<const Kernel*>& kernels,
                                   FftBackendKind backend, FftPlanning planning,
                                   SpectrumCache* cache)
    : n_out_(n_out), n_in_(n_in), mx_(0), my_(0) {
  if (kernels.size() != static_cast<std::size_t>(n_out) * static_cast<std::size_t>(n_in))
    throw std::invalid_argument("BlockConvolution: wrong number of kernels");
  for (const Kernel* k : kernels)
    if (k != nullptr) {
      mx_ = k->mx();
      my_ = k->my();
    }
  if (mx_ == 0) throw std::invalid_argument("BlockConvolution: all blocks are zero");
  const int nf = core::good_fft_size(2 * mx_ - 1);
  const int ns = core::good_fft_size(2 * my_ - 1);
  engine_ = core::make_fft_engine(backend, nf, ns, planning);
  const double scale = 1.0 / (static_cast<double>(nf) * static_cast<double>(ns));

  double* real = engine_->real_data();
  block_spectrum_.assign(kernels.size(), -1);
  for (std::size_t b = 0; b < kernels.size(); ++b) {
    const Kernel* kernel = kernels[b];
    if (kernel == nullptr) continue;
    // A kernel used by several blocks (C_xy = C_yx) is transformed and stored once.
    const auto same =
        std::find(kernels.begin(), kernels.begin() + static_cast<std::ptrdiff_t>(b), kernel);
    if (same != kernels.begin() + static_cast<std::ptrdiff_t>(b)) {
      block_spectrum_[b] = block_spectrum_[static_cast<std::size_t>(same - kernels.begin())];
      continue;
    }
    block_spectrum_[b] = static_cast<int>(spectra_.size());
    SpectrumCache::Spectrum shared = cache ? cache->find(*kernel, nf, ns) : nullptr;
    if (shared) {
      spectra_.push_back(std::move(shared));
      continue;
    }
    std::fill_n(real, engine_->real_size(), 0.0);
    for (int diy = -(my_ - 1); diy < my_; ++diy) {
      double* dst = real + static_cast<std::size_t>(wrap(diy, ns)) * static_cast<std::size_t>(nf);
      for (int dix = -(mx_ - 1); dix < mx_; ++dix) dst[wrap(dix, nf)] = kernel->at(dix, diy);
    }
    engine_->execute_forward(ns);
    std::complex<double>* spectrum = engine_->spectrum_data();
    for (std::size_t s = 0; s < engine_->spectrum_size(); ++s) spectrum[s] *= scale;
    auto layout = std::make_shared<std::vector<std::complex<double>>>(engine_->spectrum_size());
    engine_->to_channel_layout(spectrum, layout->data());
    spectra_.push_back(layout);
    if (cache) cache->add(*kernel, nf, ns, spectra_.back());
  }
  // Channels 0 … n_in−1 hold the transformed inputs, the next n_out the outputs being formed.
  engine_->set_channel_count(n_in + n_out);
  // Make the pruned plans now so that apply() never plans.
  std::fill_n(engine_->real_data(), engine_->real_size(), 0.0);
  engine_->prepare_transforms(my_, my_);
}

const std::complex<double>* BlockConvolution::block(int i, int j) const noexcept {
  const int k = block_spectrum_[static_cast<std::size_t>(i * n_in_ + j)];
  return k < 0 ? nullptr : spectra_[static_cast<std::size_t>(k)]->data();
}

namespace {

/// out = k·a (assign) or out += k·a, written out: std::complex operator* calls a library routine
/// per element (C Annex G) without -ffast-math.
void multiply_into(std::complex<double>* out, const std::complex<double>* k,
                   const std::complex<double>* a, std::size_t n, bool accumulate) noexcept {
  if (accumulate) {
    for (std::size_t s = 0; s < n; ++s) {
      const double ar = a[s].real(), ai = a[s].imag(), br = k[s].real(), bi = k[s].imag();
      out[s] += std::complex<double>(ar * br - ai * bi, ar * bi + ai * br);
    }
  } else {
    for (std::size_t s = 0; s < n; ++s) {
      const double ar = a[s].real(), ai = a[s].imag(), br = k[s].real(), bi = k[s].imag();
      out[s] = std::complex<double>(ar * br - ai * bi, ar * bi + ai * br);
    }
  }
}

/// The full 2×2 block in one pass: each input spectrum and each symbol is read once.
void multiply_2x2(std::complex<double>* u0, std::complex<double>* u1,
                  const std::complex<double>* k00, const std::complex<double>* k01,
                  const std::complex<double>* k10, const std::complex<double>* k11,
                  const std::complex<double>* p0, const std::complex<double>* p1,
                  std::size_t n) noexcept {
  for (std::size_t s = 0; s < n; ++s) {
    const double xr = p0[s].real(), xi = p0[s].imag(), yr = p1[s].real(), yi = p1[s].imag();
    const double ar = k00[s].real(), ai = k00[s].imag(), br = k01[s].real(), bi = k01[s].imag();
    const double cr = k10[s].real(), ci = k10[s].imag(), dr = k11[s].real(), di = k11[s].imag();
    u0[s] = std::complex<double>(ar * xr - ai * xi + br * yr - bi * yi,
                                 ar * xi + ai * xr + br * yi + bi * yr);
    u1[s] = std::complex<double>(cr * xr - ci * xi + dr * yr - di * yi,
                                 cr * xi + ci * xr + dr * yi + di * yr);
  }
}

}  // namespace

void BlockConvolution::apply(const double* const* p, double* const* u) {
  if (interaction_) {
    const std::size_t n = static_cast<std::size_t>(mx_) * static_cast<std::size_t>(my_);
    partwise_.apply(*interaction_, n, n_in_, n_out_, p, u,
                    [this](const double* const* in, double* const* out) { apply_full(in, out); });
    return;
  }
  apply_full(p, u);
}

void BlockConvolution::apply_full(const double* const* p, double* const* u) {
  const std::size_t nf = static_cast<std::size_t>(engine_->n_fast());
  const std::size_t mx = static_cast<std::size_t>(mx_);
  const std::size_t nspec = engine_->spectrum_size();
  double* real = engine_->real_data();

  for (int j = 0; j < n_in_; ++j) {
    for (int iy = 0; iy < my_; ++iy) {
      double* dst = real + static_cast<std::size_t>(iy) * nf;
      std::copy_n(p[j] + static_cast<std::size_t>(iy) * mx, mx, dst);
      std::fill(dst + mx, dst + nf, 0.0);
    }
    engine_->forward_to_channel(my_, j);
  }
  // Output spectra in channels n_in … n_in+n_out−1; returns false for a row of zero blocks.
  auto form_output = [&](int i) {
    bool any = false;
    for (int j = 0; j < n_in_; ++j) {
      const std::complex<double>* k = block(i, j);
      if (k == nullptr) continue;
      multiply_into(engine_->channel(n_in_ + i), k, engine_->channel(j), nspec, any);
      any = true;
    }
    return any;
  };
  const bool full_2x2 = n_out_ == 2 && n_in_ == 2 && block(0, 0) != nullptr &&
                        block(0, 1) != nullptr && block(1, 0) != nullptr && block(1, 1) != nullptr;
  if (full_2x2) {
    multiply_2x2(engine_->channel(2), engine_->channel(3), block(0, 0), block(0, 1), block(1, 0),
                 block(1, 1), engine_->channel(0), engine_->channel(1), nspec);
  }
  for (int i = 0; i < n_out_; ++i) {
    if (!full_2x2 && !form_output(i)) {
      std::fill_n(u[i], mx * static_cast<std::size_t>(my_), 0.0);
      continue;
    }
    engine_->inverse_from_channel(n_in_ + i, my_);
    for (int iy = 0; iy < my_; ++iy)
      std::copy_n(real + static_cast<std::size_t>(iy) * nf, mx,
                  u[i] + static_cast<std::size_t>(iy) * mx);
  }
}

}  // namespace rollcontact::elastic
