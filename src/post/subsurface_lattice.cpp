#include "post/subsurface_lattice.hpp"

#include <algorithm>

#include "post/corner_functions.hpp"
#include "post/half_space_response.hpp"
#include "post/nodal_loads.hpp"

namespace rollcontact::post {

std::array<double, kFieldCount> fields_of(const HalfSpaceResponse& h) {
  const Matrix3& s = h.stress;
  return {h.u[0], h.u[1], h.u[2], s[0][0], s[0][1], s[0][2], s[1][1], s[1][2], s[2][2]};
}

namespace {

/// coefficient[f][c][k]: how much corner sum k of load component c (x, y, n) contributes to
/// field f at depth z — the response is linear in the sums, so unit sums read it off.
using Coefficients = std::array<std::array<CornerValues, 3>, kFieldCount>;
Coefficients response_coefficients(double z, double g, double nu) {
  Coefficients c{};
  for (std::size_t comp = 0; comp < 3; ++comp)
    for (std::size_t k = 0; k < kCornerCount; ++k) {
      CornerSums unit;
      (comp == 0 ? unit.x : comp == 1 ? unit.y : unit.n)[k] = 1.0;
      const auto f = fields_of(response_from_sums(unit, z, g, nu));
      for (std::size_t o = 0; o < kFieldCount; ++o) c[o][comp][k] = f[o];
    }
  return c;
}

}  // namespace

SubsurfaceLattice::SubsurfaceLattice(const Grid& grid, const std::vector<double>& px,
                                     const std::vector<double>& py, const std::vector<double>& pn)
    : grid_(grid),
      // Offsets centre − node span −mx..mx−1 (fast) and −my..my−1 (slow): no wrap-around.
      n_fast_(core::good_fft_size(2 * grid.mx)),
      n_slow_(core::good_fft_size(2 * grid.my)),
      fft_(core::make_fft_engine(FftBackendKind::Default, n_fast_, n_slow_)) {
  // The direct sum's nodal weights, on the periodic grid.
  const std::vector<double>* loads[3] = {&px, &py, &pn};
  std::vector<double> w(fft_->real_size());
  for (std::size_t c = 0; c < 3; ++c) {
    std::fill(w.begin(), w.end(), 0.0);
    const std::vector<double>& p = *loads[c];
    for (int j = 0; j <= grid.my; ++j)
      for (int i = 0; i <= grid.mx; ++i)
        w[static_cast<std::size_t>(i + n_fast_ * j)] = nodal_weight(grid, p, i, j);
    load_spectra_[c].resize(fft_->spectrum_size());
    fft_->forward(w.data(), load_spectra_[c].data());
  }
}

SubsurfaceLattice::~SubsurfaceLattice() = default;

void SubsurfaceLattice::evaluate(double depth, double g, double nu, double tangential_sign,
                                 LatticeFields& out) {
  const std::size_t nr = fft_->real_size(), ns = fft_->spectrum_size();
  // The corner functions at every centre-to-node offset (d + ½)·(dx, dy), stored circularly.
  std::vector<std::vector<double>> kernels(kCornerCount, std::vector<double>(nr, 0.0));
  for (int dj = -grid_.my; dj < grid_.my; ++dj)
    for (int di = -grid_.mx; di < grid_.mx; ++di) {
      const CornerValues v = corner_values((di + 0.5) * grid_.dx, (dj + 0.5) * grid_.dy, depth);
      const std::size_t at =
          static_cast<std::size_t>((di + n_fast_) % n_fast_) +
          static_cast<std::size_t>(n_fast_) * static_cast<std::size_t>((dj + n_slow_) % n_slow_);
      for (std::size_t k = 0; k < kCornerCount; ++k) kernels[k][at] = v[k];
    }
  std::vector<std::vector<std::complex<double>>> spectra(kCornerCount,
                                                         std::vector<std::complex<double>>(ns));
  for (std::size_t k = 0; k < kCornerCount; ++k)
    fft_->forward(kernels[k].data(), spectra[k].data());

  const Coefficients coef = response_coefficients(depth, g, nu);
  const double sign[3] = {tangential_sign, tangential_sign, 1.0};
  const double scale = 1.0 / static_cast<double>(nr);
  std::vector<std::complex<double>> field(ns);
  std::vector<double> values(nr);
  for (std::size_t o = 0; o < kFieldCount; ++o) {
    // field = Σ_k K̂_k · Σ_c coef[o][c][k]·sign_c·Ŵ_c
    std::fill(field.begin(), field.end(), std::complex<double>{});
    for (std::size_t k = 0; k < kCornerCount; ++k) {
      const double a = coef[o][0][k] * sign[0], b = coef[o][1][k] * sign[1],
                   c = coef[o][2][k] * sign[2];
      if (a == 0.0 && b == 0.0 && c == 0.0) continue;
      const std::complex<double>* kk = spectra[k].data();
      const std::complex<double>*wx = load_spectra_[0].data(), *wy = load_spectra_[1].data(),
            *wn = load_spectra_[2].data();
      for (std::size_t i = 0; i < ns; ++i) field[i] += kk[i] * (a * wx[i] + b * wy[i] + c * wn[i]);
    }
    fft_->inverse(field.data(), values.data());
    std::vector<double>& dst = out[o];
    dst.assign(grid_.size(), 0.0);
    for (int iy = 0; iy < grid_.my; ++iy)
      for (int ix = 0; ix < grid_.mx; ++ix)
        dst[grid_.index(ix, iy)] = scale * values[static_cast<std::size_t>(ix + n_fast_ * iy)];
  }
}

}  // namespace rollcontact::post
