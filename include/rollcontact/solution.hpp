#pragma once
// Solution: fields on the grid, totals and solver statistics of one solved case.

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "rollcontact/grid.hpp"
#include "rollcontact/model/influence_table.hpp"
#include "rollcontact/model/traction_elements.hpp"

namespace rollcontact {

/// Element division codes (spec/physics.md §6).
enum class ElementState : std::uint8_t { Exterior = 0, Adhesion = 1, Slip = 2, Plastic = 3 };

/// The delayed (viscous) part of one viscoelastic body's compliance (M=1, spec-additions §B5),
/// in the units of the combined coefficients: it adds
/// weight·∫₀^∞ e^{−σ} C_ij(ν, k; x + ℓσ) dσ / G to C_ij/G, with C_ij the half-space coefficients of
/// a body with Poisson ratio ν and coupling parameter k, seen from the observation point moved
/// upstream by ℓσ (the material there was loaded σ relaxation times ago).
struct ViscousCompliance {
  double weight = 0.0;  ///< ½·G·FG_a/G_a [-] (both bodies merged: their sum); 0: none
  double nu = 0.0;      ///< ν_a [-]
  double k = 0.0;       ///< ±½(1−2ν_a) [-] (+ body 1, − body 2; merged: 0)
  double relaxation_length_mm = 0.0;  ///< ℓ_a = τ_c·V [mm]; 0: the rubbery response at once

  friend bool operator==(const ViscousCompliance&, const ViscousCompliance&) = default;
};

/// Combined elastic constants of the two bodies (spec/physics.md §3.1).
struct CombinedMaterial {
  double g = 0.0;   ///< combined shear modulus G [N/mm²]
  double nu = 0.0;  ///< combined Poisson ratio ν [-]
  double k = 0.0;   ///< difference parameter K [-] (0 for quasi-identical bodies)
  /// Tangential compliance of an interfacial layer h/G₃ [mm³/N] (M=4), added to the diagonal
  /// of the tangential influence coefficients; 0 without a layer.
  double layer_compliance = 0.0;
  /// Normal compliance of a compressible interfacial layer FLXZ [mm³/N] (B=1), added to the
  /// diagonal of C_nn; 0 without one.
  double normal_layer_compliance = 0.0;
  /// Viscoelastic bodies (M=1): the delayed parts added to every coefficient (g, nu, k above are
  /// then the glassy constants); empty (weight 0) for elastic bodies.
  std::array<ViscousCompliance, 2> viscous{};
  /// Coefficients from a file (C=9) instead of the closed forms; g still divides them (they are
  /// tabulated without 1/G). Null: the closed forms of g, nu, k.
  std::shared_ptr<const model::InfluenceTable> table{};
  /// The traction elements of the closed forms: piecewise constant (C=2) or bilinear (C=3,
  /// elastic/bilinear_kernel.hpp). Ignored with a table.
  model::TractionElements elements = model::TractionElements::piecewise_constant;
  /// Blanco's correction (C=4, model::InclinationCorrection): its variant (0: none) and the
  /// surface's curvature dα/dy [rad/mm] of the constant-curvature method; the coefficient of an
  /// offset Δy [mm] is turned by the inclinations' difference −curvature·Δy.
  int inclination_variant = 0;
  double inclination_curvature_per_mm = 0.0;

  bool viscoelastic() const noexcept {
    return viscous[0].weight != 0.0 || viscous[1].weight != 0.0;
  }
  /// The coefficients are turned: a correction with a curvature (a zero curvature leaves them
  /// those of the plain half-space, bit for bit).
  bool inclination_corrected() const noexcept {
    return inclination_variant != 0 && inclination_curvature_per_mm != 0.0;
  }
};

/// Hertz solution used for Hertzian potential-contact options (IPOTCN < 0).
struct HertzReport {
  bool present = false;
  bool two_dimensional = false;
  double a1 = 0.0, b1 = 0.0;  ///< curvatures [1/mm]
  double aa = 0.0, bb = 0.0;  ///< semi-axes [mm] (2-D: half length a, half width b)
  double rho = 0.0;           ///< effective radius of curvature [mm]
  double cp = 0.0;            ///< sqrt(a b) [mm]
  double pen = 0.0;           ///< approach [mm]
  double fn = 0.0;            ///< normal force [N]
  double pmax = 0.0;          ///< maximum pressure [N/mm²]
  double scale = 1.0;         ///< potential contact / Hertz area
};

/// Rolling direction, step and velocity actually used (after CONTACT's adjustments).
struct EffectiveKinematics {
  double chi = 0.0;    ///< rolling direction [rad]
  double dq = 1.0;     ///< rolling step [mm] (T=0,1: 1)
  double veloc = 1.0;  ///< rolling velocity [mm/s] (T=0,1: 1)
  double dt = 1.0;     ///< time step dq/veloc [s]
};

/// Sensitivities of the forces (spec/outputs.md §3.4); zero = not computed.
struct Sensitivities {
  double dfn_dpen = 0.0;
  double dfx_dksi = 0.0, dfx_deta = 0.0, dfy_dksi = 0.0, dfy_deta = 0.0;  ///< of F/(μ FN)
};

/// Totals (spec/outputs.md §4). Forces act on body 1.
struct Totals {
  double fn = 0.0, fx = 0.0, fy = 0.0;  ///< [N]
  double mz = 0.0;                      ///< torsional moment about the grid origin [N mm]
  double pen = 0.0;                     ///< approach [mm]
  double pmax = 0.0;                    ///< maximum pressure [N/mm²]
  double creep_x = 0.0, creep_y = 0.0, spin = 0.0;  ///< effective creepages (T=2,3)
  double shift_x = 0.0, shift_y = 0.0;              ///< effective shifts (T=1) [mm]
  double elastic_energy = 0.0;                      ///< [J] (= 1e-3 N·mm)
  double frictional_power = 0.0;                    ///< [W]; T=1: frictional work per step [J]
  double contact_area = 0.0;                        ///< [mm²]
  /// Surface temperature (H ≥ 1): the maxima of TEMP1, TEMP2 over the contact [°C]; the report's
  /// MAX(T1,T2) is the larger. 0 without the temperature calculation.
  double max_temp1 = 0.0, max_temp2 = 0.0;
};

/// Element counts (CONTACT STATISTICS block).
struct Statistics {
  int npot = 0, ncon = 0, nadh = 0, nslip = 0, nplast = 0;
  int inorm = 0;  ///< normal outer iterations (Panagiotopoulos passes)
  int itang = 0;  ///< tangential outer iterations
};

/// What the solvers did. converged == false means the numbers must not be trusted.
struct SolverReport {
  bool converged = true;
  std::string message;        ///< why not converged / warnings
  int normal_iterations = 0;  ///< total CG iterations of the normal solver
  int normal_active_set_changes = 0;
  int normal_coarse_iterations = 0;  ///< CG iterations on coarser grids (nested-iteration start)
  int normal_products = 0;           ///< influence-matrix products (FFT convolutions) used
  double normal_iteration_seconds = 0.0;  ///< wall time of the fine-grid CG iterations [s]
  /// Wall time of the case's set-up [s]: discretisation (grid, undeformed distance) and the
  /// operators built for it (influence kernels, FFT plans, preconditioners, coarse levels).
  /// Operators reused from an earlier case cost nothing here.
  double setup_seconds = 0.0;
  double normal_residual = 0.0;  ///< final relative change ||Δp||/||p||
  /// Tangential iterations: products with the tangential operator (semismooth Newton) or
  /// sweeps (Gauss–Seidel), summed over the creepage Newton loop.
  int tangential_iterations = 0;
  /// The same on coarser grids (nested-iteration start of steady rolling), each a quarter or
  /// less of a fine one.
  int tangential_coarse_iterations = 0;
  int newton_iterations = 0;
  /// Passes of the slip-velocity fixed point (velocity-dependent friction) or of the
  /// temperature fixed point (temperature-dependent friction), and its trace.
  int slip_velocity_passes = 0;
  std::vector<std::string> slip_velocity_trace;
  /// KPEC (B=5): rows of the gap's interpenetration beyond the equivalent ellipse, where the
  /// ellipse correction is clamped (a second lobe; simplified::ApproximateNormal); else 0.
  int kpec_rows_beyond_interpenetration = 0;
};

/// Effective parameters of the simplified theory (M=2,3,5; spec/physics.md §11.2), for reports.
struct SimplifiedReport {
  bool present = false;
  double flx1 = 0.0, flx2 = 0.0, flx3 = 0.0;  ///< flexibilities after blending [mm³/N] (M=2: FLX)
  double k_eff = 1.0;                         ///< slope reduction factor k [-] (in effect: L/k)
  double a = 0.0, b = 0.0;                    ///< semi-axes of the (equivalent) ellipse [mm]
};

/// A maximum (or minimum) over the points of a subsurface block and where it occurs [mm].
struct SubsurfaceExtreme {
  double value = 0.0;
  double x = 0.0, y = 0.0, z = 0.0;
};

/// Subsurface displacements and stresses of one block of points (spec/physics.md §16). Points
/// are the tensor product of the coordinate lists, index ix + nx·(iy + ny·iz) (x fastest, then
/// y, then z). z ≥ 0 lies in body 1, z < 0 in body 2; values are in the global (x, y, z) frame
/// (z into body 1), displacements of the body the point lies in. Stresses [N/mm²] are positive
/// in tension.
struct SubsurfaceResult {
  std::vector<double> x, y, z;               ///< coordinates [mm]
  std::vector<double> ux, uy, uz;            ///< displacements [mm]
  std::vector<double> sighyd, sigvm, sigtr;  ///< tr σ/3, von Mises √(3J₂), Tresca σ₁−σ₃
  std::vector<double> sig1, sig2, sig3;      ///< principal stresses, σ₁ ≥ σ₂ ≥ σ₃
  std::vector<double> sxx, sxy, sxz, syy, syz, szz;  ///< stress tensor
  /// Report maxima (spec/outputs.md §3.7); ABSMAX keeps the sign of the value.
  SubsurfaceExtreme absmax_sighyd, max_sigvm, max_sigtr, max_sig1, min_sig3;
  SubsurfaceExtreme absmax_sxx, absmax_syy, absmax_szz;
  std::size_t size() const noexcept { return x.size() * y.size() * z.size(); }
};

/// The solved case. Fields have grid.size() entries in element order ix + mx*iy.
struct Solution {
  Grid grid;
  CombinedMaterial material;
  /// Viscoelastic bodies (M=1): the effective constants NUV, GV, AKV (P§3.1 with the rubbery
  /// compliance of a body with TC = 0, spec-additions §B5); g = 0 otherwise.
  CombinedMaterial viscoelastic_effective;
  HertzReport hertz;
  std::vector<double> h;           ///< undeformed distance without approach [mm] (1e30: excluded)
  std::vector<double> pn;          ///< normal pressure [N/mm²]
  std::vector<double> px, py;      ///< tangential tractions [N/mm²]
  std::vector<double> un, ux, uy;  ///< displacement differences [mm]
  std::vector<double> sx, sy;      ///< slip (velocity / δq, or distance for T=1)
  /// The rigid slip the tangential problem posed per element: W/δq [-] (T=2,3; with the spin
  /// taken half-way along the step, FACPHI) or the rigid shift [mm] (T=1); empty for T=0.
  std::vector<double> wx, wy;
  /// Coefficient of friction per element in effect (velocity-dependent laws only, else empty).
  std::vector<double> mu;
  /// Interfacial layer with plasticity (M=4, TAU_C0 > 0), else empty: the yield limit τ_c
  /// [N/mm²], the plastic displacement (u_pl,x, u_pl,y) [mm] and its accumulated length u*_pl
  /// [mm], all carried to the next case of a sequence.
  std::vector<double> yield_limit, plastic_x, plastic_y, plastic_accumulated;
  std::vector<ElementState> state;
  /// Surface temperatures of body 1 and body 2 [°C] (spec/physics.md §15; H ≥ 1, else empty).
  std::vector<double> temp1, temp2;
  EffectiveKinematics kinematics;
  Sensitivities sensitivities;
  Totals totals;
  Statistics statistics;
  SolverReport solver;
  std::vector<std::string> warnings;  ///< silent adjustments made (echoed in reports)
  SimplifiedReport simplified;        ///< M=2,3,5 only (present)
  /// S >= 1: subsurface displacements and stresses, one entry per block of points.
  std::vector<SubsurfaceResult> subsurface;
};

}  // namespace rollcontact
