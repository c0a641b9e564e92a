#pragma once
// Subsurface displacements and stresses of a solved module-3 case (spec/physics.md §16).

#include <vector>

#include "rollcontact/model/bodies.hpp"
#include "rollcontact/model/geometry.hpp"
#include "rollcontact/solution.hpp"

namespace rollcontact::post {

/// Evaluates every block of `blocks` at the tractions of `solution` by superposition of the
/// closed-form rectangle solutions over the loaded grid nodes: directly (cost: points × loaded
/// nodes), or — for blocks of element centres large enough to pay — by FFT convolutions per
/// depth (post/subsurface_lattice, the same sums to rounding). Points with z ≥ 0 use body 1
/// (G₁, ν₁) under the tractions as solved; z < 0 use body 2 (G₂, ν₂) under the opposite
/// tractions. Returns one result per block.
std::vector<SubsurfaceResult> compute_subsurface(const std::vector<model::SubsurfaceBlock>& blocks,
                                                 const model::Bodies& bodies,
                                                 const Solution& solution);

}  // namespace rollcontact::post
