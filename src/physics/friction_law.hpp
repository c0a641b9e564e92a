#pragma once
// Friction laws: what the traction bound g [N/mm²] of an element is. The admissible tractions
// are then the disk |p_t| ≤ g (physics/friction_disk.hpp), the same for every isotropic law, so
// the tangential solvers never see the law itself. Velocity- and temperature-dependent laws
// (issue: extended physics) add implementations here; the solvers stay as they are.

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
  /// normalisation of forces by μ·F_n.
  [[nodiscard]] virtual double coefficient() const = 0;

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

/// The law that `friction` of the model describes.
std::unique_ptr<FrictionLaw> make_friction_law(const model::Friction& friction);

}  // namespace rollcontact::physics
