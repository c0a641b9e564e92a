#pragma once
// The friction law at the interface. Today Coulomb's law; velocity- and temperature-dependent
// laws are further alternatives (issue: extended physics).

namespace rollcontact::model {

/// Coulomb friction: the traction bound is μ·p_n with μ the static coefficient while adhering.
/// The kinetic coefficient is carried for reports; Coulomb's law of the exact solvers uses the
/// static one (as CONTACT does with L=0, where both are equal).
struct CoulombFriction {
  double static_coefficient = 0.3;   ///< μ_s [-], ≥ 0
  double kinetic_coefficient = 0.3;  ///< μ_k [-], ≥ 0
};

using Friction = CoulombFriction;

}  // namespace rollcontact::model
