#pragma once
// The friction of one wheel/rail patch when it varies with the contact's place (physics.md §10.4,
// CONTACT's V=1, 2 in module 1): Coulomb coefficients interpolated linearly between the control
// points, constant outside them.

#include "rollcontact/model/wheelrail.hpp"

namespace rollcontact::wheelrail {

/// The coefficients at `key` (contact angle [rad] for V=1, track position [mm] for V=2).
model::Friction friction_at(const model::FrictionVariation& variation, double key);

}  // namespace rollcontact::wheelrail
