#pragma once
// Thermal properties of the two bodies for the surface temperature of steady rolling
// (CONTACT H ≥ 1, spec/physics.md §15, spec-additions B3). Units: °C, J/(kg °C), W/(mm °C),
// kg/mm³ — CONTACT's input units.

#include <cmath>

namespace rollcontact::model {

/// One body as a conducting half-space at its bulk temperature.
struct ThermalBody {
  double bulk_temperature_C = 0.0;     ///< T₀ (BKTEMP) [°C]
  double heat_capacity_J_kgC = 450.0;  ///< c_p (HEATCP) [J/(kg °C)], > 0
  double conductivity_W_mmC = 50e-3;   ///< λ (LAMBDA) [W/(mm °C)], > 0
  double density_kg_mm3 = 7.85e-6;     ///< ρ (DENS) [kg/mm³], > 0

  /// Thermal effusivity β = 1000·√(λρc_p) [mW·√s/(mm² °C)]: the factor 1000 turns W into mW,
  /// so that a heat flux in N/mm²·mm/s (= mW/mm²) divided by β·√(V [mm/s]) and multiplied by
  /// √(distance [mm]) is a temperature in °C.
  [[nodiscard]] double effusivity() const {
    return 1000.0 * std::sqrt(conductivity_W_mmC * density_kg_mm3 * heat_capacity_J_kgC);
  }
};

/// The temperature calculation: present in a PatchProblem when `enabled`.
struct SurfaceHeat {
  bool enabled = false;
  ThermalBody body1, body2;
  /// β_pl: the fraction of the plastic work in an interfacial layer (M=4) that becomes heat
  /// [0, 1] (BETAPL).
  double plastic_heat_fraction = 0.0;
};

}  // namespace rollcontact::model
