#pragma once
// Advice for explicit finite-element contact with penalty springs (LS-DYNA's standard penalty
// contact and central differences), after Ma, Markine, Mashal & Ren, Proc IMechE Part F 232(6)
// 2018, eqs 2–10: the Courant step of the mesh, the penalty stiffness and contact time step of a
// contact node, the stability verdict, the penalty oscillator that shows it, and the pressure
// error the penalty compliance causes, computed with rollcontact's compressible layer (B=1).
// docs/fe-advice.md has the equations, assumptions and a worked table.
//
// Units: CONTACT's mm, N, s throughout, with the mass unit that makes them consistent, the
// tonne t = N·s²/mm (LS-DYNA users know this as the mm–t–s system). Moduli and pressures are in
// N/mm² (= MPa), densities in t/mm³ (7900 kg/m³ = 7.9e-9 t/mm³), stiffnesses in N/mm
// (1 N/mm = 1000 N/m), compliances in mm³/N. Pure functions over plain data; invalid values
// throw InvalidValueError (rollcontact/errors.hpp) naming the field.

#include <span>
#include <vector>

namespace rollcontact::fe_advice {

// ---- Material and mesh (eqs 4, 6) -------------------------------------------------------------

/// Linear elastic material of the FE bodies (the paper's steel by default).
struct FeMaterial {
  double young_N_mm2 = 210000.0;  ///< E [N/mm²]
  double poisson = 0.3;           ///< ν [-], in [0, 0.5)
  double density_t_mm3 = 7.9e-9;  ///< ρ [t/mm³] (7900 kg/m³)
};

/// Throws InvalidValueError unless E > 0, 0 ≤ ν < 0.5 and ρ > 0 (all finite).
void check_material(const FeMaterial& material);

/// Bulk modulus K = E/(3(1 − 2ν)) [N/mm²].
[[nodiscard]] double bulk_modulus_N_mm2(const FeMaterial& material);

/// Dilatational (P-) wave speed c = √(E(1 − ν)/(ρ(1 + ν)(1 − 2ν))) [mm/s].
[[nodiscard]] double dilatational_wave_speed_mm_s(const FeMaterial& material);

/// LS-DYNA's default time-step scale factor TSSFAC applied to the Courant step.
inline constexpr double default_time_step_scale = 0.9;

/// Courant step of a solid element of characteristic length `element_size_mm` (a cube's edge),
/// scaled by `time_step_scale`: Δt_e = TSSFAC·C_d/c [s] (eq 4).
[[nodiscard]] double courant_time_step_s(double element_size_mm, const FeMaterial& material,
                                         double time_step_scale = default_time_step_scale);

// ---- One contact node: penalty spring, mass, damping (eqs 5–9) --------------------------------

/// Penalty stiffness of a contact segment, eq 6: k = α·K·A²/V = α·K·C_d for a cube [N/mm].
[[nodiscard]] double penalty_stiffness_N_mm(double penalty_factor, double bulk_modulus_N_mm2,
                                            double element_size_mm);

/// Default nodal mass factor β in m = β·ρ·C_d³: ¼, the reduced mass m₁m₂/(m₁ + m₂) of two
/// surface nodes of a regular hex mesh joined by the penalty spring, each ½ρC_d³ (four elements
/// give it an eighth of their mass each); docs/fe-advice.md.
inline constexpr double default_nodal_mass_factor = 0.25;

/// Oscillating mass of a contact node m = β·ρ·C_d³ [t].
[[nodiscard]] double nodal_mass_t(double element_size_mm, double density_t_mm3,
                                  double mass_factor = default_nodal_mass_factor);

/// Damping ratio of the contact damper, eq 7: ξ = VDC/100 (VDC in percent of critical) [-].
[[nodiscard]] double damping_ratio_from_vdc(double vdc_percent);

/// Reduction of the contact time step by damping, eq 9: √(1 + ξ²) − ξ [-] (1 for ξ = 0).
[[nodiscard]] double damping_reduction_factor(double damping_ratio);

/// Contact time step without damping, eq 8: 2√(m/k) [s].
[[nodiscard]] double contact_time_step_undamped_s(double mass_t, double stiffness_N_mm);

/// Contact time step with damping ratio ξ, eq 9: 2√(m/k)·(√(1 + ξ²) − ξ) [s], the exact
/// stability limit of central differences for m ẍ + c ẋ + k x = 0 with the damping force taken
/// from the velocity of the previous half step (as an explicit code does).
[[nodiscard]] double contact_time_step_s(double mass_t, double stiffness_N_mm,
                                         double damping_ratio);

/// Eq 10: the calculation step does not exceed the contact step.
[[nodiscard]] bool contact_stable(double calc_time_step_s, double contact_time_step_s);

/// The penalty spring of one node spread over its tributary area C_d² acts as an interface
/// compliance L = C_d²/k [mm³/N]: a uniform pressure p compresses it by L·p.
[[nodiscard]] double interface_compliance_mm3_N(double element_size_mm, double stiffness_N_mm);

// ---- The penalty oscillator (spec dynamic-rolling.md §5.5) ------------------------------------

/// A contact node of mass m on the (closed) penalty spring k with the damper c = 2ξ√(km).
struct PenaltyOscillator {
  double mass_t = 0.0;
  double stiffness_N_mm = 0.0;
  double damping_ratio = 0.0;  ///< ξ [-]
};

/// What a central-difference run of the oscillator showed.
struct OscillatorRun {
  int steps = 0;
  /// Amplitude factor per time step of the slowest-decaying (or fastest-growing) mode, measured
  /// from the envelope of the response after the start-up transient [-].
  double growth_per_step = 0.0;
  /// The same per natural period 2π√(m/k) of the undamped oscillator [-].
  double growth_per_period = 0.0;
  /// The analytic spectral radius of the scheme (central_difference_spectral_radius) [-].
  double spectral_radius = 0.0;
  bool bounded = false;  ///< growth_per_step ≤ 1 (within rounding)
};

/// Integrates m ẍ + c ẋ + k x = 0 with eq 2 (velocities at half steps, the damping force from
/// v_{n−½}) from an initial penetration at rest, for `steps` steps (≥ 100). The linear
/// oscillator stands for a contact held closed (a constant pressing load moves the equilibrium,
/// not the stability).
[[nodiscard]] OscillatorRun run_penalty_oscillator(const PenaltyOscillator& oscillator,
                                                   double time_step_s, int steps = 20000,
                                                   double initial_penetration_mm = 1e-3);

/// Largest |z| of the scheme's characteristic equation
/// z² + (Ω² + 2ξΩ − 2) z + (1 − 2ξΩ) = 0, Ω = ω·Δt: ≤ 1 exactly when Ω ≤ 2(√(1+ξ²) − ξ).
[[nodiscard]] double central_difference_spectral_radius(double omega_dt, double damping_ratio);

// ---- Stability advice over penalty factors ----------------------------------------------------

/// The FE model around one contact: mesh, time step and contact damping.
struct FeContactSettings {
  FeMaterial material;
  double element_size_mm = 1.0;      ///< C_d of the contact surface elements
  double smallest_element_mm = 0.0;  ///< element that sets the Courant step; 0: element_size_mm
  double time_step_scale = default_time_step_scale;  ///< TSSFAC
  double calc_time_step_s = 0.0;  ///< Δt_calc given; 0: TSSFAC × Courant(smallest element)
  double nodal_mass_factor = default_nodal_mass_factor;  ///< β in m = β·ρ·C_d³
  double vdc_percent = 80.0;  ///< contact damping VDC [% of critical] (the paper's reference)
};

/// Throws InvalidValueError for a non-positive size, factor or step, a negative VDC, or a bad
/// material.
void check_settings(const FeContactSettings& settings);

/// Δt_calc: the given one, else TSSFAC × the Courant step of the smallest element [s].
[[nodiscard]] double calculation_time_step_s(const FeContactSettings& settings);

/// The numbers of one penalty factor.
struct StabilityAdvice {
  double penalty_factor = 0.0;                ///< α [-]
  double stiffness_N_mm = 0.0;                ///< k, eq 6
  double mass_t = 0.0;                        ///< m
  double damping_ratio = 0.0;                 ///< ξ, eq 7
  double contact_time_step_undamped_s = 0.0;  ///< eq 8
  double contact_time_step_s = 0.0;           ///< eq 9
  double calc_time_step_s = 0.0;              ///< Δt_calc
  bool stable_undamped = false;               ///< eq 10 with the eq 8 step
  bool stable = false;                        ///< eq 10 with the eq 9 step
  double layer_compliance_mm3_N = 0.0;        ///< L = C_d²/k
};

/// Eqs 6–10 for penalty factor α (> 0); checks the settings.
[[nodiscard]] StabilityAdvice stability_advice(const FeContactSettings& settings,
                                               double penalty_factor);

/// The penalty factor at which Δt_cont = Δt_calc (Δt_cont ∝ α^−½): larger factors are
/// unstable by eq 10, with the eq 9 step (`damped`) or the eq 8 step.
[[nodiscard]] double stability_boundary_penalty_factor(const FeContactSettings& settings,
                                                       bool damped);

/// The paper's sweep α = 0.1·2^m, m = −1 … 12 (0.05 … 409.6).
[[nodiscard]] std::vector<double> penalty_factor_sweep();

// ---- Pressure error of the penalty compliance -------------------------------------------------

/// A frictionless normal contact of two equal half-spaces with the quadratic gap
/// h = A·x² + B·y² (x rolling, y lateral) under a normal force. The defaults stand for the paper's
/// case (S1002 on 54E1, 100 kN): A = 1/(2·460 mm) from the wheel's rolling radius on a straight
/// rail, B = 4e-4 /mm for the nearly conformal tread on the R300 crown, giving a Hertzian
/// patch of 191 mm² (11.2 mm × 21.7 mm; CONTACT: 191 mm², ≈ 11 × 23 mm) with pmax 786 N/mm².
struct NormalContactCase {
  double normal_force_N = 1.0e5;
  double curvature_x_1_mm = 1.0 / 920.0;  ///< A [1/mm]
  double curvature_y_1_mm = 4.0e-4;       ///< B [1/mm]
  FeMaterial material;                    ///< E, ν of both bodies (ρ unused)
  double grid_step_mm = 0.25;             ///< element size of the boundary-element grid
};

/// Throws InvalidValueError for a non-positive force, curvature or grid step, or a bad material.
void check_contact_case(const NormalContactCase& contact);

/// Peak pressure, area and approach of a solved or analytic normal contact.
struct NormalContactResult {
  double layer_compliance_mm3_N = 0.0;  ///< L; 0: the exact contact without layer
  double pmax_N_mm2 = 0.0;
  double area_mm2 = 0.0;
  double approach_mm = 0.0;
  int contact_elements = 0;  ///< 0 for the analytic solution
  bool converged = false;
};

/// Solves `contact` once per compliance with rollcontact's exact normal solver (module 3, B=1
/// layer with FLXZ = L; L = 0: no layer) on a grid that is enlarged until the contact stays
/// inside it. Throws SolverError when a case does not converge.
[[nodiscard]] std::vector<NormalContactResult> solve_normal_contacts(
    const NormalContactCase& contact, std::span<const double> layer_compliances_mm3_N);

/// The Winkler limit L → ∞ where the layer alone carries the load: p = (δ − h)/L, so
/// δ = √(2·L·√(AB)·FN/π), pmax = δ/L and area = π·δ/√(AB) (elasticity of the bodies ignored).
[[nodiscard]] NormalContactResult winkler_paraboloid(const NormalContactCase& contact,
                                                     double layer_compliance_mm3_N);

}  // namespace rollcontact::fe_advice
