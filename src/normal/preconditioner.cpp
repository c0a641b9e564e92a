#include "normal/preconditioner.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

#include "elastic/bilinear_kernel.hpp"
#include "elastic/influence.hpp"

namespace rollcontact::normal {

void IdentityPreconditioner::apply(const double* r, double* z) {
  std::copy(r, r + n_, z);
}

double IdentityPreconditioner::apply_dot(const double* r, double* z) {
  double dot = 0.0;
  for (std::size_t i = 0; i < n_; ++i) {
    z[i] = r[i];
    dot += r[i] * r[i];
  }
  return dot;
}

CirculantPreconditioner::CirculantPreconditioner(const Grid& grid, const CombinedMaterial& material,
                                                 FftBackendKind backend, FftPlanning planning,
                                                 const elastic::Kernel* kernel)
    : mx_(grid.mx),
      my_(grid.my),
      nx_(core::good_fft_size(grid.mx)),
      ny_(core::good_fft_size(grid.my)),
      engine_(core::make_fft_engine(backend, nx_, ny_, planning)) {
  // Offsets beyond the kernel from the closed forms of the same traction elements.
  const auto coefficient = material.elements == model::TractionElements::bilinear
                               ? &elastic::bilinear_coefficient
                               : &elastic::influence_coefficient;
  // Wrapped kernel: offset i is represented by the nearest periodic image (|i| ≤ n/2).
  double* work = engine_->real_data();
  for (int j = 0; j < ny_; ++j) {
    const int oy = j <= ny_ / 2 ? j : j - ny_;
    for (int i = 0; i < nx_; ++i) {
      const int ox = i <= nx_ / 2 ? i : i - nx_;
      const bool tabulated =
          kernel != nullptr && std::abs(ox) < kernel->mx() && std::abs(oy) < kernel->my();
      work[static_cast<std::size_t>(i) + static_cast<std::size_t>(nx_) * j] =
          tabulated ? kernel->at(ox, oy)
                    : coefficient(elastic::Component::nn, ox * grid.dx, oy * grid.dy, grid.dx,
                                  grid.dy, material.nu, 0.0) /
                          material.g;
    }
  }
  const double diagonal = work[0];
  engine_->execute_forward(ny_);
  // The symbol of a symmetric kernel is real. The wrapped (Strang) circulant may have small or
  // negative eigenvalues at the highest frequencies; bound them below by a fraction of the
  // diagonal coefficient, which is the symbol's typical size there.
  const double floor = 0.25 * diagonal;
  const double scale = 1.0 / (static_cast<double>(nx_) * static_cast<double>(ny_));
  const std::complex<double>* spectrum = engine_->spectrum_data();
  std::vector<std::complex<double>> inverse_symbol(engine_->spectrum_size());
  for (std::size_t k = 0; k < inverse_symbol.size(); ++k)
    inverse_symbol[k] = scale / std::max(spectrum[k].real(), floor);
  // Where the backend has one, apply in single precision: an approximate inverse needs no more
  // than a few digits (CG iteration counts unchanged), and the transforms are ≈ 30 % cheaper.
  // The double engine then only made the symbol: no convolution plans for it. Not on small
  // grids, where starting FFTW's single-precision planner (≈ 0.4 ms a process) costs more than
  // the cheaper transforms save.
  constexpr int min_single_size = 128 * 128;
  if (nx_ * ny_ >= min_single_size)
    single_ = core::make_single_circulant(backend, nx_, ny_, planning);
  if (single_) {
    std::vector<double> real_symbol(inverse_symbol.size());
    for (std::size_t k = 0; k < real_symbol.size(); ++k) real_symbol[k] = inverse_symbol[k].real();
    single_->set_symbol(real_symbol.data());
    engine_.reset();  // not needed any more
    return;
  }
  engine_->set_convolution_symbol(inverse_symbol.data());
  // The row-pruned transforms are planned now, not in apply().
  std::fill_n(work, engine_->real_size(), 0.0);
  engine_->prepare_transforms(my_, my_);
}

void CirculantPreconditioner::convolve(const double* r) {
  // Transform in the engine's own arrays: rows ≥ my are declared zero (row-pruned transforms),
  // so only the padding columns of the first my rows need clearing, and no full-array copies are
  // made (at 575×647 those copies cost about a quarter of the transforms).
  const std::size_t nx = static_cast<std::size_t>(nx_), mx = static_cast<std::size_t>(mx_);
  double* work = engine_->real_data();
  for (int iy = 0; iy < my_; ++iy) {
    double* dst = work + nx * static_cast<std::size_t>(iy);
    std::copy_n(r + mx * static_cast<std::size_t>(iy), mx, dst);
    std::fill(dst + mx, dst + nx, 0.0);
  }
  engine_->execute_convolution(my_, my_);
}

void CirculantPreconditioner::apply(const double* r, double* z) {
  if (single_) {
    single_->apply_dot(r, z, mx_, my_);
    return;
  }
  convolve(r);
  const std::size_t nx = static_cast<std::size_t>(nx_), mx = static_cast<std::size_t>(mx_);
  const double* work = engine_->real_data();
  for (int iy = 0; iy < my_; ++iy)
    std::copy_n(work + nx * static_cast<std::size_t>(iy), mx,
                z + mx * static_cast<std::size_t>(iy));
}

double CirculantPreconditioner::apply_dot(const double* r, double* z) {
  if (single_) return single_->apply_dot(r, z, mx_, my_);
  convolve(r);
  const std::size_t nx = static_cast<std::size_t>(nx_), mx = static_cast<std::size_t>(mx_);
  const double* work = engine_->real_data();
  // Four partial sums, as in FftConvolution::apply_dot (one is bound by the addition latency).
  double dot[4] = {0.0, 0.0, 0.0, 0.0};
  for (int iy = 0; iy < my_; ++iy) {
    const double* src = work + nx * static_cast<std::size_t>(iy);
    const double* rr = r + mx * static_cast<std::size_t>(iy);
    double* zr = z + mx * static_cast<std::size_t>(iy);
    std::size_t ix = 0;
    for (; ix + 4 <= mx; ix += 4) {
      for (std::size_t l = 0; l < 4; ++l) {
        zr[ix + l] = src[ix + l];
        dot[l] += rr[ix + l] * src[ix + l];
      }
    }
    for (; ix < mx; ++ix) {
      zr[ix] = src[ix];
      dot[0] += rr[ix] * src[ix];
    }
  }
  return (dot[0] + dot[1]) + (dot[2] + dot[3]);
}

}  // namespace rollcontact::normal
