#include <cmath>

#include "solve/state_impl.hpp"

namespace rollcontact {

PatchSolver::PatchSolver(SolveOptions options) : impl_(std::make_unique<Impl>()) {
  impl_->options = options;
}
PatchSolver::~PatchSolver() = default;
PatchSolver::PatchSolver(PatchSolver&&) noexcept = default;
PatchSolver& PatchSolver::operator=(PatchSolver&&) noexcept = default;

const SolveOptions& PatchSolver::options() const noexcept {
  return impl_->options;
}

void PatchSolver::reset_sequence() noexcept {
  impl_->previous.reset();
}

namespace {

std::unique_ptr<NormalOperators> make_normal_operators(const Grid& grid,
                                                       const CombinedMaterial& material,
                                                       const SolveOptions& options) {
  auto ops = std::make_unique<NormalOperators>();
  ops->grid = grid;
  ops->material = material;
  ops->kernel = elastic::make_kernel(elastic::Component::nn, grid, material);
  ops->product =
      std::make_unique<elastic::FftConvolution>(ops->kernel, options.fft, options.fft_planning);
  ops->preconditioner = std::make_unique<normal::CirculantPreconditioner>(
      grid, material, options.fft, options.fft_planning);
  return ops;
}

}  // namespace

NormalOperators& PatchSolver::Impl::normal_operators(const Grid& grid,
                                                     const CombinedMaterial& material) {
  if (!normal || !same_grid_and_material(normal->grid, grid, normal->material, material))
    normal = make_normal_operators(grid, material, options);
  return *normal;
}

NormalOperators& PatchSolver::Impl::coarse_normal_operators(int level, const Grid& grid,
                                                            const CombinedMaterial& material) {
  const std::size_t k = static_cast<std::size_t>(level - 1);
  if (coarse_normal.size() <= k) coarse_normal.resize(k + 1);
  auto& ops = coarse_normal[k];
  if (!ops || !same_grid_and_material(ops->grid, grid, ops->material, material))
    ops = make_normal_operators(grid, material, options);
  return *ops;
}

namespace {

/// a − b element-wise (steady rolling: C − C′).
elastic::Kernel difference(const elastic::Kernel& a, const elastic::Kernel& b) {
  elastic::Kernel d(a.mx(), a.my());
  for (int diy = -(a.my() - 1); diy < a.my(); ++diy)
    for (int dix = -(a.mx() - 1); dix < a.mx(); ++dix)
      d.at(dix, diy) = a.at(dix, diy) - b.at(dix, diy);
  return d;
}

}  // namespace

TangentialOperators& PatchSolver::Impl::tangential_operators(const Grid& grid,
                                                             const CombinedMaterial& material,
                                                             int t, double shift_x,
                                                             double shift_y) {
  // T=1 uses C for the previous displacement (material-fixed grid): no shift.
  if (t == 1) shift_x = shift_y = 0.0;
  if (tangential &&
      same_grid_and_material(tangential->grid, grid, tangential->material, material) &&
      tangential->t == t && tangential->shift_x == shift_x && tangential->shift_y == shift_y)
    return *tangential;

  using elastic::Component;
  using elastic::make_kernel;
  auto ops = std::make_unique<TangentialOperators>();
  ops->grid = grid;
  ops->material = material;
  ops->t = t;
  ops->shift_x = shift_x;
  ops->shift_y = shift_y;
  const bool coupled = std::abs(material.k) >= 1e-6;
  const auto fft = options.fft;
  const auto planning = options.fft_planning;

  elastic::Kernel cxx = make_kernel(Component::xx, grid, material);
  elastic::Kernel cxy = make_kernel(Component::xy, grid, material);
  elastic::Kernel cyy = make_kernel(Component::yy, grid, material);
  elastic::Kernel cxn, cyn;
  if (coupled) {
    cxn = make_kernel(Component::xn, grid, material);
    cyn = make_kernel(Component::yn, grid, material);
    ops->nt_x = make_kernel(Component::nx, grid, material);
    ops->nt_y = make_kernel(Component::ny, grid, material);
    ops->nt = std::make_unique<elastic::BlockConvolution>(
        1, 2, std::vector<const elastic::Kernel*>{&ops->nt_x, &ops->nt_y}, fft, planning);
  }
  ops->c_xx = cxx;
  ops->c_xy = cxy;
  ops->c_yy = cyy;
  ops->c_nn = make_kernel(Component::nn, grid, material);
  if (coupled) {
    ops->c_xn = cxn;
    ops->c_yn = cyn;
  }
  {
    const elastic::Kernel* xn = coupled ? &ops->c_xn : nullptr;
    const elastic::Kernel* yn = coupled ? &ops->c_yn : nullptr;
    const elastic::Kernel* nx = coupled ? &ops->nt_x : nullptr;
    const elastic::Kernel* ny = coupled ? &ops->nt_y : nullptr;
    ops->full = std::make_unique<elastic::BlockConvolution>(
        3, 3,
        std::vector<const elastic::Kernel*>{&ops->c_xx, &ops->c_xy, xn, &ops->c_xy, &ops->c_yy, yn,
                                            nx, ny, &ops->c_nn},
        fft, planning);
  }
  if (t == 3) {
    // Steady rolling: A = C − C′ with C′ the coefficients seen from one step downstream.
    const auto sxx = make_kernel(Component::xx, grid, material, shift_x, shift_y);
    const auto sxy = make_kernel(Component::xy, grid, material, shift_x, shift_y);
    const auto syy = make_kernel(Component::yy, grid, material, shift_x, shift_y);
    ops->xx = difference(cxx, sxx);
    ops->xy = difference(cxy, sxy);
    ops->yy = difference(cyy, syy);
    if (coupled) {
      ops->tn_x = difference(cxn, make_kernel(Component::xn, grid, material, shift_x, shift_y));
      ops->tn_y = difference(cyn, make_kernel(Component::yn, grid, material, shift_x, shift_y));
    }
  } else {
    ops->xx = std::move(cxx);
    ops->xy = std::move(cxy);
    ops->yy = std::move(cyy);
    if (coupled) {
      ops->tn_x = cxn;
      ops->tn_y = cyn;
    }
    // Previous-time displacement of the particles now at the element centres.
    ops->prev_xx = t == 2 ? make_kernel(Component::xx, grid, material, shift_x, shift_y) : ops->xx;
    ops->prev_xy = t == 2 ? make_kernel(Component::xy, grid, material, shift_x, shift_y) : ops->xy;
    ops->prev_yy = t == 2 ? make_kernel(Component::yy, grid, material, shift_x, shift_y) : ops->yy;
    if (coupled) {
      ops->prev_xn = t == 2 ? make_kernel(Component::xn, grid, material, shift_x, shift_y) : cxn;
      ops->prev_yn = t == 2 ? make_kernel(Component::yn, grid, material, shift_x, shift_y) : cyn;
    }
    ops->prev = std::make_unique<elastic::BlockConvolution>(
        2, 3,
        std::vector<const elastic::Kernel*>{&ops->prev_xx, &ops->prev_xy,
                                            coupled ? &ops->prev_xn : nullptr, &ops->prev_xy,
                                            &ops->prev_yy, coupled ? &ops->prev_yn : nullptr},
        fft, planning);
  }
  // Approximate inverse of C_tt (for steady rolling combined with the row sums of (I − T)⁻¹).
  ops->preconditioner =
      std::make_unique<tangential::TangentialPreconditioner>(ops->c_xx, ops->c_xy, ops->c_yy, fft);
  ops->a = std::make_unique<elastic::BlockConvolution>(
      2, 2, std::vector<const elastic::Kernel*>{&ops->xx, &ops->xy, &ops->xy, &ops->yy}, fft,
      planning);
  if (coupled)
    ops->tn = std::make_unique<elastic::BlockConvolution>(
        2, 1, std::vector<const elastic::Kernel*>{&ops->tn_x, &ops->tn_y}, fft, planning);
  tangential = std::move(ops);
  return *tangential;
}

CoarseSteadyOperators& PatchSolver::Impl::coarse_steady_operators(int level, const Grid& grid,
                                                                  const CombinedMaterial& material,
                                                                  double shift_x, double shift_y) {
  const std::size_t k = static_cast<std::size_t>(level - 1);
  if (coarse_steady.size() <= k) coarse_steady.resize(k + 1);
  auto& ops = coarse_steady[k];
  if (ops && same_grid_and_material(ops->grid, grid, ops->material, material) &&
      ops->shift_x == shift_x && ops->shift_y == shift_y)
    return *ops;
  using elastic::Component;
  using elastic::make_kernel;
  ops = std::make_unique<CoarseSteadyOperators>();
  ops->grid = grid;
  ops->material = material;
  ops->shift_x = shift_x;
  ops->shift_y = shift_y;
  const elastic::Kernel cxx = make_kernel(Component::xx, grid, material);
  const elastic::Kernel cxy = make_kernel(Component::xy, grid, material);
  const elastic::Kernel cyy = make_kernel(Component::yy, grid, material);
  ops->xx = difference(cxx, make_kernel(Component::xx, grid, material, shift_x, shift_y));
  ops->xy = difference(cxy, make_kernel(Component::xy, grid, material, shift_x, shift_y));
  ops->yy = difference(cyy, make_kernel(Component::yy, grid, material, shift_x, shift_y));
  ops->preconditioner =
      std::make_unique<tangential::TangentialPreconditioner>(cxx, cxy, cyy, options.fft);
  ops->a = std::make_unique<elastic::BlockConvolution>(
      2, 2, std::vector<const elastic::Kernel*>{&ops->xx, &ops->xy, &ops->xy, &ops->yy},
      options.fft, options.fft_planning);
  return *ops;
}

}  // namespace rollcontact
