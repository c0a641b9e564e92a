#pragma once
// Friction laws: what the traction bound g [N/mm²] of an element is. The admissible tractions
// are then the disk |p_t| ≤ g (physics/friction_disk.hpp), the same for every isotropic law, so
// the tangential solvers never see the law itself. Velocity- and temperature-dependent laws
// (issue: extended physics) add implementations here; the solvers stay as they are.

#include <array>
#include <memory>
#include <vector>

#include "rollcontact/model/friction.hpp"

namespace rollcontact::physics {

class FrictionLaw {
 public:
  virtual ~FrictionLaw() = default;

  /// The traction bound g [N/mm²] of an element with pressure `pressure_N_mm2` (≥ 0).
  [[nodiscard]] virtual double traction_bound(double pressure_N_mm2) const = 0;

  /// One coefficient of friction for the simplified theories (Fastsim, FaStrip) and the
  /// normalisation of forces by μ·F_n (the static value for velocity-dependent laws).
  [[nodiscard]] virtual double coefficient() const = 0;

  /// μ at slip velocity `slip_speed_mm_s` ≥ 0 (physics.md §10.1); Coulomb: coefficient().
  [[nodiscard]] virtual double coefficient_at(double slip_speed_mm_s) const {
    (void)slip_speed_mm_s;
    return coefficient();
  }

  /// True when μ depends on the slip velocity (the solution needs the fixed point of §10.3).
  [[nodiscard]] virtual bool velocity_dependent() const { return false; }

  /// True when μ depends on the surface temperature of body 1 (L = 6: the temperature fixed
  /// point of §10.3).
  [[nodiscard]] virtual bool temperature_dependent() const { return false; }

  /// μ at body 1's surface temperature `temperature_C` [°C]; coefficient() unless L = 6.
  [[nodiscard]] virtual double coefficient_at_temperature(double temperature_C) const {
    (void)temperature_C;
    return coefficient();
  }

  /// g for every element of `pressure_N_mm2` (g = 0 where the pressure is not positive).
  void traction_bounds(const std::vector<double>& pressure_N_mm2, std::vector<double>& bound) const;
};

/// Coulomb's law g = μ·p_n with μ the static coefficient (CONTACT's L = 0, where μ_s = μ_k).
class CoulombLaw final : public FrictionLaw {
 public:
  explicit CoulombLaw(double coefficient) : mu_(coefficient) {}
  [[nodiscard]] double traction_bound(double pressure_N_mm2) const override {
    return mu_ * pressure_N_mm2;
  }
  [[nodiscard]] double coefficient() const override { return mu_; }

 private:
  double mu_;
};

/// Friction falling with the slip velocity (CONTACT's L = 2, 3, 4): μ(s_a) = FKIN + the two
/// falling terms of physics.md §10.1, from μ_static = FKIN + F_1 + F_2 at s_a = 0 towards FKIN.
class FallingFrictionLaw final : public FrictionLaw {
 public:
  explicit FallingFrictionLaw(const model::Friction& friction);
  [[nodiscard]] double traction_bound(double pressure_N_mm2) const override {
    return static_coefficient_ * pressure_N_mm2;
  }
  [[nodiscard]] double coefficient() const override { return static_coefficient_; }
  [[nodiscard]] double coefficient_at(double slip_speed_mm_s) const override;
  [[nodiscard]] bool velocity_dependent() const override { return true; }

 private:
  model::FrictionLawKind kind_;
  double kinetic_;
  std::array<model::FallingTerm, 2> terms_;
  double static_coefficient_;
};

/// Temperature-dependent friction (CONTACT's L = 6): μ(T) = FREF + ΔF·clamp((T − T_ref)/ΔT, 0, 1).
/// Its static value FREF bounds the tractions until a temperature is known.
class TemperatureFrictionLaw final : public FrictionLaw {
 public:
  explicit TemperatureFrictionLaw(const model::Friction& friction)
      : reference_(friction.static_coefficient), term_(friction.temperature) {}
  [[nodiscard]] double traction_bound(double pressure_N_mm2) const override {
    return reference_ * pressure_N_mm2;
  }
  [[nodiscard]] double coefficient() const override { return reference_; }
  [[nodiscard]] bool temperature_dependent() const override { return true; }
  [[nodiscard]] double coefficient_at_temperature(double temperature_C) const override;

 private:
  double reference_;
  model::TemperatureTerm term_;
};

/// The law that `friction` of the model describes.
std::unique_ptr<FrictionLaw> make_friction_law(const model::Friction& friction);

}  // namespace rollcontact::physics
