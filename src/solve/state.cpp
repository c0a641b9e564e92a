#include "solve/state_impl.hpp"

namespace rollcontact {

State::State() : State(SolveOptions{}) {}
State::State(SolveOptions options) : impl_(std::make_unique<Impl>()) {
  impl_->options = options;
}
State::~State() = default;
State::State(State&&) noexcept = default;
State& State::operator=(State&&) noexcept = default;

const SolveOptions& State::options() const noexcept {
  return impl_->options;
}

NormalOperators& State::Impl::normal_operators(const Grid& grid, const CombinedMaterial& material) {
  if (!normal || !normal->matches(grid, material)) {
    auto ops = std::make_unique<NormalOperators>();
    ops->grid = grid;
    ops->material = material;
    ops->kernel = elastic::make_kernel(elastic::Component::nn, grid, material);
    ops->product =
        std::make_unique<elastic::FftConvolution>(ops->kernel, options.fft, options.fft_planning);
    ops->preconditioner = std::make_unique<normal::CirculantPreconditioner>(
        grid, material, options.fft, options.fft_planning);
    normal = std::move(ops);
  }
  return *normal;
}

}  // namespace rollcontact
