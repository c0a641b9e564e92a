#pragma once
// How the tractions between element centres are represented in the influence coefficients
// (CONTACT's C digit, spec/physics.md §3.2-3.3, spec-additions.md §B7).

namespace rollcontact::model {

/// Piecewise constant per element (C=2) or bilinear "hat" functions centred on the element
/// centres (C=3, support 2δx × 2δy, 1 at the centre, 0 at the neighbouring centres).
/// Displacements are sampled at the element centres either way.
enum class TractionElements { piecewise_constant, bilinear };

}  // namespace rollcontact::model
