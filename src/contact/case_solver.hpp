#pragma once
// CaseSolver: one case of a PatchSolver — the normal problem (case_solver_normal.cpp), the
// tangential problem with the force, slip-velocity and temperature iterations
// (case_solver_tangential.cpp), and the sequence, the Panagiotopoulos loop and the totals
// (case_solver.cpp). Internal to the contact module; PatchSolver::solve() is its user.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "contact/contact_box.hpp"
#include "contact/force_iteration.hpp"
#include "contact/interfacial_layer.hpp"
#include "contact/patch_solver_impl.hpp"
#include "contact/previous_fields.hpp"
#include "contact/slip_velocity_iteration.hpp"
#include "elastic/interaction.hpp"
#include "normal/normal_solver.hpp"
#include "physics/friction_law.hpp"
#include "rollcontact/model/patch_problem.hpp"
#include "rollcontact/solution.hpp"
#include "tangential/tangential_system.hpp"

namespace rollcontact::contact {

/// The elastic energy ½Σ(p·u)·δxδy [J] from the sum Σ(p_n u_n + p_x u_x + p_y u_y) [N/mm] over
/// the elements and their area [mm²] (CONTACT's ELAST.EN; N·mm → J).
double elastic_energy_J(double sum_p_dot_u, double element_area_mm2);

/// What a tangential solution reports per contact element: the relative slip S/δq (S per
/// step; T=1: δq = 1, a distance), 0 in Plastic elements, which do not slide, and there the
/// layer's flow |Δu_pl| = |−S| (plastic_flow empty when nothing flowed).
struct ReportedSlip {
  Field sx, sy;
  Field plastic_flow;
};

/// The relative slip S/δq per contact element of `t` (S per step; T=1: δq = 1).
ReportedSlip reported_slip(const tangential::TangentialResult& t, const Field& pn, double dq);

/// Everything the normal and tangential sub-solves of one case share.
class CaseSolver {
 public:
  /// `interaction`: attenuation between IPLAN=4 rectangles, or nullptr.
  CaseSolver(const model::PatchProblem& problem, PatchSolver::Impl& st, Solution& sol,
             elastic::InteractionPtr interaction)
      : problem_(problem),
        st_(st),
        sol_(sol),
        grid_(sol.grid),
        interaction_(std::move(interaction)) {}

  void run();

 private:
  /// The sequence's remembered state on this grid: prev_ (the previous solution, extrapolated
  /// at a new step of steady rolling) and latest_pn_; returns the previous solution or nullptr.
  const Solution* map_sequence(model::TangentialKind kind);
  void solve_normal(const Field& px, const Field& py);
  normal::NormalSettings normal_settings() const;
  /// The Hertz solution's pressures on `grid` for Hertzian geometries (physics.md §7.1), empty
  /// when the geometry is not Hertzian or no element is loaded.
  Field hertz_start(const Grid& grid) const;
  /// NormCG for h (the whole grid) from `initial` (or the Hertz, coarse-grid or geometric
  /// start), on a box of the grid where the contact is known to lie inside it.
  normal::NormalResult solve_normal_cg(const Field& h, normal::NormalLoad load, double value,
                                       const Field* initial, const Field* initial_un,
                                       NormalOperators& ops);
  /// The box for the normal solve with the approach given: around the interpenetration, and
  /// within that around the starting pressure when there is one (to be checked afterwards).
  std::optional<contact::ContactBox> normal_box(const Field& h, double pen,
                                                const Field* initial) const;
  void set_prescribed_pressure();
  /// KPEC (kpec) or ANALYN for the prescribed approach on the case's grid.
  void set_approximate_pressure(bool kpec);
  /// FN [N]: the sum of the pressures (also KPEC, ANALYN), or the prescribed force itself with
  /// B=2,3 (whose discrete pressures sum to FN only up to the discretisation error).
  double total_normal_force() const;
  /// Fastsim/FaStrip; a velocity-dependent law is solved element by element inside Fastsim.
  tangential::TangentialResult solve_simplified(double cksi, double ceta, double cphi);
  /// `mu`: the coefficient per element (velocity-dependent friction), nullptr: the law's bound.
  tangential::TangentialResult solve_tangential(double cksi, double ceta, double cphi,
                                                const Field* px0, const Field* py0,
                                                const Field* mu = nullptr);
  /// The exact tangential problem with a velocity-dependent friction law: the slip-velocity
  /// fixed point of physics.md §10.3 around solve_tangential(); tractions start from px, py.
  /// The solver for `sys` (physics.md §9.1), started from px0, py0: on the box around the
  /// contact where that is small enough (contact/contact_box.hpp), else on the grid.
  tangential::TangentialResult run_tangential_solver(const tangential::TangentialSystem& sys,
                                                     const Field* px0, const Field* py0);
  /// The solver for `sys` on its own grid.
  tangential::TangentialResult solve_on_grid(const tangential::TangentialSystem& sys,
                                             const Field* px0, const Field* py0);
  tangential::TangentialResult solve_velocity_dependent(double cksi, double ceta, double cphi,
                                                        const Field& px, const Field& py);
  /// Temperature-dependent friction (L = 6): the temperature fixed point of physics.md §10.3
  /// around solve_tangential(); tractions start from px, py.
  tangential::TangentialResult solve_temperature_dependent(double cksi, double ceta, double cphi,
                                                           const Field& px, const Field& py);
  /// Body 1's surface temperature [°C] that the tangential solution `t` produces (§15).
  Field body1_temperature(const tangential::TangentialResult& t) const;
  /// What solve_velocity_dependent and solve_temperature_dependent share: memory of §10.2,
  /// the tangential solve of one pass (started from the previous pass's tractions, which
  /// start_x, start_y carry) and taking over the last pass as the case's result.
  contact::FrictionMemoryInput friction_memory(const std::vector<char>& contact) const;
  contact::TangentialSolveWithFriction warm_started_solve(double cksi, double ceta, double cphi,
                                                          Field& start_x, Field& start_y);
  tangential::TangentialResult adopt_friction_iteration(contact::FrictionIterationOutcome& r);
  /// 1 for the elements in contact (p_n > 0).
  std::vector<char> contact_set() const;
  /// Keeps the rigid shift per step W [mm] of the problem posed as the solution's rigid slip
  /// W/δq (T=1: the shift itself), for the O = 5 element tables.
  void record_rigid_slip(const Field& wx, const Field& wy) {
    const bool rolling = problem_.tangential.kind == model::TangentialKind::TransientRolling ||
                         problem_.tangential.kind == model::TangentialKind::SteadyRolling;
    const double per = rolling && sol_.kinematics.dq > 0.0 ? 1.0 / sol_.kinematics.dq : 1.0;
    sol_.wx.resize(wx.size());
    sol_.wy.resize(wy.size());
    for (std::size_t i = 0; i < wx.size(); ++i) {
      sol_.wx[i] = per * wx[i];
      sol_.wy[i] = per * wy[i];
    }
  }
  void assemble_slip_at_zero_traction(tangential::TangentialSystem& sys, double cksi, double ceta,
                                      double cphi);
  void add_unshifted_displacement(const Field& px, const Field& py, const Field& pn, Field& ux,
                                  Field& uy) const;
  /// The creepage iteration for prescribed forces (F=1, 2), started from the previous case
  /// `prev` (creepages and Jacobian) where the sequence continues, else afresh.
  ForceIterationInput force_iteration_input(const Solution* prev) const;
  void compute_totals(const tangential::TangentialResult* tang);
  /// H ≥ 1: TEMP1, TEMP2 and their maxima from the final solution (physics.md §15).
  void compute_temperatures();

  const model::PatchProblem& problem_;
  PatchSolver::Impl& st_;
  Solution& sol_;
  const Grid& grid_;
  elastic::InteractionPtr interaction_;
  bool coupled_ = false;
  bool prescribed_ = false;   ///< B=2,3,5,6: normal problem skipped
  bool approximate_ = false;  ///< B=5,6: KPEC or ANALYN pressures (FN is their sum)
  bool simplified_ = false;   ///< M=2,3,5: Fastsim / FaStrip instead of the exact theory
  bool rough_ = false;        ///< SolverOptions::rough_tolerance applies: an iterate's solve
  Field simplified_ux_, simplified_uy_;
  std::unique_ptr<physics::FrictionLaw> friction_;
  PreviousFields prev_;
  /// The last solve's pressure on this grid (SequenceLink::normal_from_previous), or empty.
  Field latest_pn_;
  /// latest_pn_ is, element for element, the pressure of st_.last_normal (whose un = A·pn).
  bool latest_is_last_normal_ = false;
  /// A·p_n of the normal answer (NormCG's final product), the displacement compute_totals()
  /// would compute again for a patch without tangential operators; empty when not known.
  Field normal_un_;
  Field mu_;                    ///< velocity-dependent friction: μ per element of the last solve
  bool layer_plastic_ = false;  ///< M=4 with TAU_C0 > 0
  contact::PlasticHistory plastic_history_;
  Field plastic_flow_;  ///< |Δu_pl| [mm] of this step in Plastic elements (empty: none)
  TangentialOperators* tops_ = nullptr;
  std::vector<std::string> notes_;
};

}  // namespace rollcontact::contact
