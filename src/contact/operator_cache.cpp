#include "contact/operator_cache.hpp"

namespace rollcontact {

namespace ops = elastic::operators;

OperatorCache::OperatorCache(ops::FftChoice fft, OperatorCacheCapacity capacity)
    : fft_(fft),
      normal_(capacity.normal),
      tangential_(capacity.tangential),
      coarse_steady_(capacity.coarse_steady) {}

NormalOperators& OperatorCache::normal(const Grid& grid, const CombinedMaterial& material,
                                       elastic::InteractionPtr interaction) {
  const OperatorKey key{grid, material, model::TangentialKind::None, 0.0, 0.0, interaction};
  return normal_.get(key, case_number_, build_seconds_, [&](NormalOperators& e) {
    ops::assemble_normal(e, grid, material, fft_, interaction, &kernels_);
    // Viscoelastic (M=1): solved without it (normal/active_set_solver.hpp, spec-additions §B5).
    if (!material.viscoelastic())
      e.preconditioner = std::make_unique<normal::CirculantPreconditioner>(
          grid, material, fft_.backend, fft_.planning, &e.kernel);
  });
}

TangentialOperators& OperatorCache::tangential(const Grid& grid, const CombinedMaterial& material,
                                               model::TangentialKind kind, double shift_x_mm,
                                               double shift_y_mm,
                                               elastic::InteractionPtr interaction) {
  const ops::TangentialLoadingKey loading =
      ops::tangential_loading_key(kind, shift_x_mm, shift_y_mm);
  const OperatorKey key{grid,       material, loading.kind, loading.shift_x, loading.shift_y,
                        interaction};
  return tangential_.get(key, case_number_, build_seconds_, [&](TangentialOperators& e) {
    ops::assemble_tangential(e, grid, material, kind, shift_x_mm, shift_y_mm, fft_, interaction,
                             &kernels_);
    e.preconditioner = std::make_unique<tangential::TangentialPreconditioner>(e.c_xx, e.c_xy,
                                                                              e.c_yy, fft_.backend);
  });
}

CoarseSteadyOperators& OperatorCache::coarse_steady(const Grid& grid,
                                                    const CombinedMaterial& material,
                                                    double shift_x_mm, double shift_y_mm) {
  const OperatorKey key{grid,       material,   model::TangentialKind::SteadyRolling,
                        shift_x_mm, shift_y_mm, nullptr};
  return coarse_steady_.get(key, case_number_, build_seconds_, [&](CoarseSteadyOperators& e) {
    ops::assemble_steady_rolling(e, grid, material, shift_x_mm, shift_y_mm, fft_, &kernels_);
    e.preconditioner = std::make_unique<tangential::TangentialPreconditioner>(e.c_xx, e.c_xy,
                                                                              e.c_yy, fft_.backend);
  });
}

std::size_t OperatorCache::builds() const noexcept {
  return normal_.builds() + tangential_.builds() + coarse_steady_.builds();
}

std::size_t OperatorCache::size() const noexcept {
  return normal_.size() + tangential_.size() + coarse_steady_.size();
}

}  // namespace rollcontact
