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
  impl_->earlier.reset();
  impl_->latest_pn.clear();
}

void PatchSolver::set_previous(Solution solution, double origin_x_mm, double origin_y_mm) {
  impl_->previous = std::move(solution);
  impl_->earlier.reset();
  impl_->latest_pn.clear();
  impl_->previous_origin_x = origin_x_mm;
  impl_->previous_origin_y = origin_y_mm;
}

}  // namespace rollcontact
