#include "contact/patch_solver_impl.hpp"

namespace rollcontact {

PatchSolver::PatchSolver(SolveOptions options) : impl_(std::make_unique<Impl>(options)) {}
PatchSolver::~PatchSolver() = default;
PatchSolver::PatchSolver(PatchSolver&&) noexcept = default;
PatchSolver& PatchSolver::operator=(PatchSolver&&) noexcept = default;

const SolveOptions& PatchSolver::options() const noexcept {
  return impl_->options;
}

void PatchSolver::reset_sequence() noexcept {
  impl_->previous.reset();
}

}  // namespace rollcontact
