#pragma once
// Plasticity of an interfacial layer (CONTACT M=4, spec/physics.md §12, spec-additions B4): the
// tangential traction of an element is bounded by min(μ·p_n, τ_c) with the yield limit
// τ_c = τ_c0 + k_τ·u*_pl. An element on the yield limit does not slide: the layer flows instead,
// by Δu_pl = −S (S the slip the elastic problem leaves there), in the direction of its traction.
// Mathematically it is a slipping element with bound τ_c, so the tangential solvers stay as
// they are; this file only sets the bounds and reads the plastic flow off the solution.

#include <vector>

#include "rollcontact/model/bodies.hpp"
#include "rollcontact/solution.hpp"
#include "tangential/tangential_system.hpp"

namespace rollcontact::contact {

using Field = std::vector<double>;

/// The plastic state of the layer before this case (zero without a previous case).
struct PlasticHistory {
  Field x, y;         ///< plastic displacement [mm]
  Field accumulated;  ///< u*_pl [mm]
  /// Steady rolling: no previous time; a particle accumulates the flow of the elements it has
  /// passed, from the leading edge of its row (χ = 0: high ix) up to and including its own.
  const Grid* steady_grid = nullptr;
  double chi_rad = 0.0;
};

/// Steady rolling: per element the sum of `per_step` over the row from the leading edge up to
/// and including the element (what a particle has accumulated when it reaches it).
Field accumulate_along_rows(const Grid& grid, double chi_rad, const Field& per_step);

/// τ_c per element for a plastic increment of length `increment_mm` in this case (≥ 0; a
/// softening layer does not go below zero strength).
Field yield_limits(const model::InterfacialLayer& layer, const PlasticHistory& history,
                   const Field& increment_mm);

/// Plastic flow in the elements of `tang` that slip on their yield limit (τ_c < μ·p_n): their
/// state becomes Plastic and `increment_mm` takes |S| there (0 elsewhere). Returns how many.
int mark_plastic_elements(const Field& friction_bound, const Field& yield_limit,
                          tangential::TangentialResult& tang, Field& increment_mm);

/// The layer's state after this case: history plus −S in the plastic elements, τ_c evaluated
/// with the final increments.
void record_plastic_state(const model::InterfacialLayer& layer, const PlasticHistory& history,
                          const tangential::TangentialResult& tang, Solution& sol);

}  // namespace rollcontact::contact
