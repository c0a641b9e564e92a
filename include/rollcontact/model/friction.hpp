#pragma once
// The friction law at the interface (spec/physics.md §10): Coulomb's law, or a coefficient that
// falls with the local slip velocity s_a [mm/s] (CONTACT's L = 2, 3, 4) or changes with the
// surface temperature of body 1 [°C] (L = 6), with friction memory.

#include <array>
#include <vector>

namespace rollcontact::model {

/// How μ depends on the slip velocity s_a (physics.md §10.1).
enum class FrictionLawKind {
  Coulomb,              ///< L = 0: μ = static coefficient
  LinearFalling,        ///< L = 2: FKIN + Σ F_k·max(0, 1 − s_a/(2·S_k))
  RationalFalling,      ///< L = 3: FKIN + F_1/(1 + s_a/S_1) + F_2/(1 + (s_a/S_2)²)
  ExponentialFalling,   ///< L = 4: FKIN + Σ F_k·2^(−s_a/S_k)
  TemperatureDependent  ///< L = 6: FREF + DFHEAT·clamp((T − TREF)/DTHEAT, 0, 1)
};

/// One falling term of L = 2, 3, 4: its height F_k [-] and slip velocity S_k [mm/s] (SABSH).
struct FallingTerm {
  double coefficient = 0.0;
  double speed_mm_s = 1e-4;
};

/// L = 6 (physics.md §10.1, spec-additions B2): μ(T) rises (or falls, ΔF < 0) linearly from
/// FREF at T_ref to FREF + ΔF at T_ref + ΔT, constant outside; T is body 1's surface temperature.
struct TemperatureTerm {
  double reference_temperature_C = 0.0;  ///< TREF [°C]
  double change = 0.0;                   ///< DFHEAT [-]
  double temperature_span_C = 1.0;       ///< DTHEAT [°C], > 0
};

/// Coulomb friction (the first two members, so that {μ_s, μ_k} stays Coulomb's law), or a
/// velocity-dependent law. For the falling laws static_coefficient is μ(s_a = 0) = FKIN + F_1 +
/// F_2: it scales the relative forces (FX/FSTAT/FN) and is the coefficient of adhering elements.
struct Friction {
  double static_coefficient = 0.3;   ///< μ_s [-], ≥ 0
  double kinetic_coefficient = 0.3;  ///< μ_k [-], ≥ 0 (FKIN of the falling laws)
  FrictionLawKind law = FrictionLawKind::Coulomb;
  std::array<FallingTerm, 2> terms{};  ///< L = 2, 3, 4 only
  TemperatureTerm temperature{};       ///< L = 6 only (FREF is static_coefficient)
  /// Friction memory (§10.2): μ relaxes towards μ(s_a) over the sliding distance
  /// memory_distance_mm, with slip velocities below memory_floor_speed_mm_s counted as that.
  double memory_distance_mm = 0.0;
  double memory_floor_speed_mm_s = 0.0;
  /// CONTACT's V=3 (experimental, module 3): a Coulomb coefficient per grid row iy = 0..MY−1,
  /// in place of static_coefficient in that row's traction bound. Empty: one coefficient.
  /// Forces are still normalised by static_coefficient (the first row's, as CONTACT prints).
  std::vector<double> row_coefficients{};

  [[nodiscard]] bool velocity_dependent() const {
    return law != FrictionLawKind::Coulomb && law != FrictionLawKind::TemperatureDependent;
  }
  [[nodiscard]] bool temperature_dependent() const {
    return law == FrictionLawKind::TemperatureDependent;
  }
};

using CoulombFriction = Friction;

}  // namespace rollcontact::model
