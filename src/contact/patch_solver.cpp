// PatchSolver::solve(): one patch from model::PatchProblem to Solution — the geometry, the
// case itself (contact/case_solver.hpp), subsurface stresses and the state a sequence keeps.

#include <chrono>
#include <memory>
#include <string>
#include <utility>

#include "contact/case_solver.hpp"
#include "contact/patch_solver_impl.hpp"
#include "contact/result_check.hpp"
#include "elastic/material.hpp"
#include "geometry/discretisation.hpp"
#include "post/subsurface.hpp"
#include "rollcontact/model/validation.hpp"
#include "rollcontact/solve.hpp"

namespace rollcontact {

namespace {

elastic::InteractionPtr interaction_of(geometry::PlanformParts& parts) {
  if (parts.n_parts <= 1) return nullptr;
  auto inter = std::make_shared<elastic::Interaction>();
  inter->n_parts = parts.n_parts;
  inter->part = std::move(parts.part);
  inter->factor = std::move(parts.factor);
  return inter;
}

}  // namespace

Solution PatchSolver::solve(const model::PatchProblem& problem) {
  model::validate(problem);  // every front end's values pass the same check
  Impl& st = *impl_;
  const auto start = std::chrono::steady_clock::now();
  const double built_before = st.operators.build_seconds();
  const model::Bodies& b = problem.bodies;

  Solution sol;
  sol.material = elastic::combine_bodies(b, problem.rolling.velocity_mm_per_s);
  if (b.viscoelastic) sol.viscoelastic_effective = elastic::effective_viscoelastic_constants(b);
  geometry::Discretisation disc = geometry::build_discretisation(problem, sol.material);
  sol.grid = disc.grid;
  sol.hertz = disc.hertz;
  sol.h = std::move(disc.h);
  const double geometry_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  st.operators.begin_case();
  contact::CaseSolver(problem, st, sol, interaction_of(disc.parts)).run();
  sol.solver.setup_seconds = geometry_seconds + (st.operators.build_seconds() - built_before);

  if (!problem.subsurface.empty())
    sol.subsurface = post::compute_subsurface(problem.subsurface, problem.bodies, sol);
  const std::string non_finite = first_non_finite(sol);
  if (!non_finite.empty()) {
    // Never reported as converged, and never the start of the next case.
    sol.solver.converged = false;
    sol.solver.message = "non-finite result (" + non_finite + ")";
    return sol;
  }
  st.latest_pn = sol.pn;
  st.latest_grid = sol.grid;
  st.latest_origin_x = problem.sequence.origin_x_mm;
  st.latest_origin_y = problem.sequence.origin_y_mm;
  // A problem that does not become the previous one leaves the stored state as it was.
  if (problem.sequence.becomes_previous || !st.previous) {
    if (problem.sequence.new_step && st.previous) {
      st.earlier = std::move(st.previous);
      st.earlier_origin_x = st.previous_origin_x;
      st.earlier_origin_y = st.previous_origin_y;
    }
    st.previous = sol;
    st.previous_origin_x = problem.sequence.origin_x_mm;
    st.previous_origin_y = problem.sequence.origin_y_mm;
  }
  return sol;
}

void PatchSolver::complete_elastic_energy(const model::PatchProblem& problem, Solution& s) {
  const model::PressureModel pressure = problem.normal.pressure;
  if (!problem.solver.defer_elastic_energy ||
      (pressure != model::PressureModel::Kpec && pressure != model::PressureModel::Analyn))
    return;
  const std::size_t n = s.grid.size();
  if (s.pn.size() != n) return;
  // The operator the solve used: the same grid, material and IPLAN=4 parts.
  geometry::PlanformParts parts = geometry::planform_parts(s.grid, problem.gap);
  NormalOperators& ops = impl_->operators.normal(s.grid, s.material, interaction_of(parts));
  s.un.assign(n, 0.0);
  ops.product->apply(s.pn.data(), s.un.data());
  const auto at = [](const std::vector<double>& f, std::size_t i) {
    return i < f.size() ? f[i] : 0.0;
  };
  double energy = 0.0;
  for (std::size_t i = 0; i < n; ++i)
    energy += s.pn[i] * s.un[i] + at(s.px, i) * at(s.ux, i) + at(s.py, i) * at(s.uy, i);
  s.totals.elastic_energy = contact::elastic_energy_J(energy, s.grid.element_area());
}

}  // namespace rollcontact
