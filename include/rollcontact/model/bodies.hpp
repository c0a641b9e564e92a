#pragma once
// The two bodies in contact: elastic constants and the tangential compliance model.
// Units: N/mm² (MPa) for moduli, mm³/N for flexibilities.

#include <array>
#include <memory>
#include <vector>

#include "rollcontact/model/influence_table.hpp"
#include "rollcontact/model/traction_elements.hpp"

namespace rollcontact::model {

/// Linear elastic, homogeneous, isotropic half-space.
struct ElasticBody {
  double poisson_ratio = 0.28;           ///< ν [-], in [0, 0.5]
  double shear_modulus_N_mm2 = 82000.0;  ///< G [N/mm²], > 0
};

/// How the tangential problem models the bodies' compliance (spec/physics.md §5, §11).
enum class TangentialCompliance {
  ExactHalfSpace,             ///< Kalker's exact half-space theory on the grid
  FastsimOneFlexibility,      ///< Modified Fastsim with one given flexibility (CONTACT M=2)
  FastsimThreeFlexibilities,  ///< Modified Fastsim with three flexibilities from Kalker's
                              ///< coefficients (CONTACT M=3)
  FaStrip,                    ///< Modified FaStrip (CONTACT M=5)
};

/// Parameters of the simplified (Fastsim family) theories; unused for the exact theory.
struct SimplifiedParameters {
  double flexibility_mm3_N = 0.0;  ///< the one flexibility L [mm³/N] (FastsimOneFlexibility)
  /// Slope reduction of Modified Fastsim: initial slope factor k0 [-], its decay alpha_inf [-]
  /// and beta [-] (spec/physics.md §11.2: K0_MF, ALFAMF, BETAMF).
  double k0 = 1.0, alpha_inf = 1.0, beta = 0.0;
};

/// Kalker's material difference parameter K = (G/4)[(1−2ν₁)/G₁ − (1−2ν₂)/G₂] with
/// 1/G = ½(1/G₁ + 1/G₂) (dimensionless; 0 for quasi-identical bodies, which decouples the normal
/// and tangential problems), without validating the inputs. The one definition used by the
/// solver and by the readers' checks.
inline double material_difference_k(double nu1, double nu2, double g1, double g2) {
  const double g = 2.0 / (1.0 / g1 + 1.0 / g2);
  return 0.25 * g * ((1.0 - 2.0 * nu1) / g1 - (1.0 - 2.0 * nu2) / g2);
}

/// An interfacial (third-body) layer between the bodies (CONTACT M=4, physics.md §12): an
/// elastic shear compliance h/G₃ added to the tangential one, and a yield limit
/// τ_c = τ_c0 + k_τ·u*_pl on the tangential traction (u*_pl the accumulated plastic slip).
struct InterfacialLayer {
  double shear_modulus_N_mm2 = 0.0;  ///< G₃ (GG3) [N/mm²]; ≤ 0 or thickness 0: no compliance
  double thickness_mm = 0.0;         ///< h (LAYTHK) [mm]
  double yield_stress_N_mm2 = 0.0;   ///< τ_c0 (TAU_C0) [N/mm²]; ≤ 0: no plasticity
  double hardening_N_mm3 = 0.0;      ///< k_τ (K_TAU) [N/mm³]; < 0 softening

  /// h/G₃ [mm³/N]: the layer's tangential displacement per unit traction.
  [[nodiscard]] double compliance_mm3_N() const {
    return shear_modulus_N_mm2 > 0.0 && thickness_mm > 0.0 ? thickness_mm / shear_modulus_N_mm2
                                                           : 0.0;
  }
  [[nodiscard]] bool plastic() const { return yield_stress_N_mm2 > 0.0; }
};

/// The delayed response of a body modelled as a standard linear solid (CONTACT M=1,
/// spec-additions §B5): the body's ElasticBody holds the glassy (instantaneous) modulus G_g; a
/// stress applied at t = 0 and held gives the creep compliance
/// J(t) = [1 + FG·(1 − e^{−t/τ_c})]/G_g, rising to the rubbery (relaxed) 1/G_r = (1 + FG)/G_g.
struct ViscoelasticBody {
  double creep_ratio = 0.0;        ///< FG = (E_g − E_r)/E_r ≥ 0 [-]; 0: purely elastic
  double relaxation_time_s = 0.0;  ///< τ_c (TC) ≥ 0 [s]; 0: the body responds rubbery at once

  /// Relaxation length ℓ = τ_c·V [mm]: how far upstream the material remembers its loading
  /// when rolling at velocity V [mm/s].
  [[nodiscard]] double relaxation_length_mm(double velocity_mm_s) const {
    return relaxation_time_s * velocity_mm_s;
  }
};

/// CONTACT C=4 (experimental): Blanco-Lorenzo's correction of the half-space influence
/// coefficients for a contact surface whose inclination changes across the grid rows
/// (spec-additions.md §B8, wheelrail-advanced.md §1.7): the load at one element and the
/// displacement at another are turned into each other's local frames by the difference of the
/// surface inclinations there. The inclination α [rad] is the turn of the surface's local frame
/// about +x (right-hand rule; positive when the normal tips towards +y).
struct InclinationCorrection {
  /// VARIANT: 1 turns the load (Blanco), 2 as 1 without the x-n term, 3 turns the displacement
  /// (Vollebregt), 4 turns both halfway (symmetric); 0: no correction (C=2).
  int variant = 0;
  /// IF_METH = 1: the table row by row (varying curvature); 0: its least-squares straight line,
  /// α = c₀ + c₁·y (constant curvature), one set of coefficients for all rows.
  bool varying_curvature = false;
  /// The inclination table: lateral positions y [mm] of the grid (module 3: the .inp's NN
  /// pairs; module 1: the rows of a conformal patch's curved reference) and α there [rad].
  std::vector<double> y_mm, alpha_rad;

  [[nodiscard]] bool active() const noexcept { return variant != 0; }
};

struct Bodies {
  ElasticBody body1;  ///< the upper body; tractions act on it (glassy modulus if viscoelastic)
  ElasticBody body2;
  TangentialCompliance compliance = TangentialCompliance::ExactHalfSpace;
  SimplifiedParameters simplified;
  bool has_layer = false;  ///< CONTACT M=4: the interfacial layer below applies
  InterfacialLayer layer;
  /// A compressible interfacial layer (CONTACT B=1, e.g. pressure-sensitive film): its normal
  /// compliance FLXZ [mm³/N] adds u_n = FLXZ·p_n; 0: none.
  double normal_layer_flexibility_mm3_N = 0.0;
  /// CONTACT M=1: both bodies are standard linear solids (steady rolling only, χ = 0).
  bool viscoelastic = false;
  ViscoelasticBody viscous1, viscous2;
  /// CONTACT C=9: influence coefficients read from a file, used instead of the closed forms of
  /// the piecewise-constant half-space (C=2); null: the closed forms. Shared, not copied, between
  /// the cases that use one file.
  std::shared_ptr<const InfluenceTable> influence_table;
  /// CONTACT C=3: bilinear traction elements instead of piecewise constant ones (C=2).
  TractionElements traction_elements = TractionElements::piecewise_constant;
  /// CONTACT C=4: the surface inclination's correction of the coefficients; inactive: none.
  InclinationCorrection inclination;
};

}  // namespace rollcontact::model
