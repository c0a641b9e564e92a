// PatchSolver::solve(): one patch from model::PatchProblem to Solution — geometry, normal
// problem, tangential problem (with the force iteration and the Panagiotopoulos loop) and the
// totals.

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <memory>
#include <optional>

#include "contact/contact_box.hpp"
#include "contact/force_iteration.hpp"
#include "contact/interfacial_layer.hpp"
#include "contact/patch_solver_impl.hpp"
#include "contact/result_check.hpp"
#include "contact/slip_velocity_iteration.hpp"
#include "contact/temperature_iteration.hpp"
#include "elastic/material.hpp"
#include "geometry/discretisation.hpp"
#include "geometry/hertz.hpp"
#include "normal/active_set_solver.hpp"
#include "normal/normal_solver.hpp"
#include "physics/friction_law.hpp"
#include "post/subsurface.hpp"
#include "post/surface_temperature.hpp"
#include "rollcontact/errors.hpp"
#include "rollcontact/model/validation.hpp"
#include "rollcontact/solve.hpp"
#include "simplified/approximate_normal.hpp"
#include "simplified/prescribed_pressure.hpp"
#include "simplified/simplified_solver.hpp"
#include "tangential/kinematics.hpp"
#include "tangential/leading_edge.hpp"

namespace rollcontact {

namespace {

using Field = std::vector<double>;

/// The tangential problem is solved on the box around the contact when the box holds at most
/// this share of the grid's elements (contact/contact_box.hpp). Measured on the mbench sweeps
/// (whole processes, CPU time, medians of 11): 0.75 against 0.5 saves 2–9 % (right 10 kN 0.5 mm
/// position 9 %, force 3 %, 50 kN force 6 %: wheel/rail grids hold the contact with a margin
/// that leaves boxes of 0.55–0.7 of the grid); 0.99 measured the same as 0.75.
constexpr double max_contact_box_fraction = 0.75;
/// The normal solve's box (CaseSolver::normal_box). Measured (instructions, right 10 kN 0.5 mm
/// force sweep): 0.9 and 0.97 equal, 0.75 +1 %.
constexpr double max_normal_box_fraction = 0.9;

/// The elastic energy ½Σ(p·u)·δxδy [J] from the sum Σ(p_n u_n + p_x u_x + p_y u_y) [N/mm] over
/// the elements and their area [mm²] (CONTACT's ELAST.EN; N·mm → J).
double elastic_energy_J(double sum_p_dot_u, double element_area_mm2) {
  return 0.5e-3 * sum_p_dot_u * element_area_mm2;
}

/// Element (ix, iy) of a grid is element (ix + ox, iy + oy) of an older one.
struct ElementOffset {
  long ox = 0, oy = 0;
};
/// The offset of `grid` in `old`; `shift_x`, `shift_y` [mm]: how far this grid's coordinate
/// origin lies from the older one's in the sequence's frame. None when the element sizes
/// differ.
std::optional<ElementOffset> element_offset(const Grid& old, const Grid& grid, double shift_x,
                                            double shift_y) {
  if (std::abs(old.dx - grid.dx) > 1e-6 * grid.dx || std::abs(old.dy - grid.dy) > 1e-6 * grid.dy)
    return std::nullopt;
  return ElementOffset{std::lround((grid.xl + shift_x - old.xl) / grid.dx),
                       std::lround((grid.yl + shift_y - old.yl) / grid.dy)};
}

/// Calls visit(i, j) for every element i of `grid` whose element j = i + offset lies in `old`.
template <class Visit>
void for_each_overlap(const Grid& old, const Grid& grid, ElementOffset offset, Visit&& visit) {
  for (int iy = 0; iy < grid.my; ++iy) {
    const long jy = iy + offset.oy;
    if (jy < 0 || jy >= old.my) continue;
    for (int ix = 0; ix < grid.mx; ++ix) {
      const long jx = ix + offset.ox;
      if (jx >= 0 && jx < old.mx)
        visit(grid.index(ix, iy), static_cast<std::size_t>(jx + old.mx * jy));
    }
  }
}

/// Fields of the previous case mapped onto the current grid (same element size, integer offset);
/// zero where the old grid did not reach (physics.md §2 "Sequences").
struct PreviousFields {
  bool present = false;
  std::vector<char> covered;  ///< 1 where the previous grid reaches
  Field px, py, pn;
  Field ux, uy;                     ///< displacements (transient Fastsim)
  Field sx, sy;                     ///< slip per δq (T=1: per step)
  Field mu;                         ///< velocity-dependent friction: μ per element (else empty)
  contact::PlasticHistory plastic;  ///< interfacial layer with plasticity (else empty)
  double veloc = 1.0;               ///< rolling velocity [mm/s] of the previous case
};

/// `shift_x`, `shift_y` [mm]: how far this grid's coordinate origin lies from the previous one's
/// in the sequence's common frame (model::SequenceLink::origin_*).
PreviousFields map_previous(const Solution* prev, const Grid& grid, double shift_x,
                            double shift_y) {
  PreviousFields out;
  const std::size_t n = grid.size();
  out.px.assign(n, 0.0);
  out.py.assign(n, 0.0);
  out.pn.assign(n, 0.0);
  out.ux.assign(n, 0.0);
  out.uy.assign(n, 0.0);
  out.sx.assign(n, 0.0);
  out.sy.assign(n, 0.0);
  out.covered.assign(n, 0);
  if (prev == nullptr || prev->pn.empty()) return out;
  out.veloc = prev->kinematics.veloc;
  const bool has_mu = prev->mu.size() == prev->grid.size();
  if (has_mu) out.mu.assign(n, -1.0);  // -1: not known here (μ_static)
  const bool has_plastic = prev->plastic_accumulated.size() == prev->grid.size();
  if (has_plastic) {
    out.plastic.x.assign(n, 0.0);
    out.plastic.y.assign(n, 0.0);
    out.plastic.accumulated.assign(n, 0.0);
  }
  const Grid& old = prev->grid;
  const std::optional<ElementOffset> offset = element_offset(old, grid, shift_x, shift_y);
  if (!offset) return out;
  for_each_overlap(old, grid, *offset, [&](std::size_t i, std::size_t j) {
    out.covered[i] = 1;
    out.px[i] = prev->px[j];
    out.py[i] = prev->py[j];
    out.pn[i] = prev->pn[j];
    if (prev->ux.size() == old.size()) {
      out.ux[i] = prev->ux[j];
      out.uy[i] = prev->uy[j];
    }
    if (prev->sx.size() == old.size()) {
      out.sx[i] = prev->sx[j];
      out.sy[i] = prev->sy[j];
    }
    if (has_mu) out.mu[i] = prev->mu[j];
    if (has_plastic) {
      out.plastic.x[i] = prev->plastic_x[j];
      out.plastic.y[i] = prev->plastic_y[j];
      out.plastic.accumulated[i] = prev->plastic_accumulated[j];
    }
  });
  out.present = true;
  return out;
}

/// `f` on grid `old` mapped onto `grid` as map_previous() does; 0 where `old` does not reach.
Field map_field(const Field& f, const Grid& old, const Grid& grid, double shift_x, double shift_y) {
  Field out(grid.size(), 0.0);
  const std::optional<ElementOffset> offset = element_offset(old, grid, shift_x, shift_y);
  if (f.size() != old.size() || !offset) return out;
  for_each_overlap(old, grid, *offset, [&](std::size_t i, std::size_t j) { out[i] = f[j]; });
  return out;
}

/// SequenceLink::new_step: the start 2·last − before of the tractions and pressures where both
/// grids reach (pressures not below 0), the last elsewhere. Only the fields a start uses.
void extrapolate_start(PreviousFields& last, const PreviousFields& before) {
  if (!last.present || !before.present) return;
  for (std::size_t i = 0; i < last.px.size(); ++i) {
    if (!last.covered[i] || !before.covered[i]) continue;
    last.px[i] = 2.0 * last.px[i] - before.px[i];
    last.py[i] = 2.0 * last.py[i] - before.py[i];
    last.pn[i] = std::max(0.0, 2.0 * last.pn[i] - before.pn[i]);
  }
}

double rms_change(const Field& a, const Field& b) {
  double s = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) s += (a[i] - b[i]) * (a[i] - b[i]);
  return std::sqrt(s);
}

double norm(const Field& a) {
  double s = 0.0;
  for (double v : a) s += v * v;
  return std::sqrt(s);
}

/// Nested iteration for large grids: the same normal problem on a grid with elements twice as
/// large (h averaged over the 2×2 fine elements), solved — itself started from a coarser grid —
/// and prolongated element-wise. Returns an empty field when the grid is too small to gain.
/// The fine solve then starts close to its solution, with few active-set changes.
Field coarse_grid_start(PatchSolver::Impl& st, int level, const Grid& grid, const Field& h,
                        normal::NormalLoad load, double value, const CombinedMaterial& material,
                        const normal::NormalSettings& settings, int& iterations) {
  constexpr std::size_t min_elements = 20000;  // below this a coarse start does not pay
  if (grid.size() < min_elements || grid.mx < 16 || grid.my < 16) return {};
  if (material.table) return {};  // a file's coefficients (C=9) exist for its element size only
  const Grid coarse{(grid.mx + 1) / 2, (grid.my + 1) / 2, grid.xl,
                    grid.yl,           2.0 * grid.dx,     2.0 * grid.dy};
  Field ch(coarse.size(), geometry::excluded_distance);
  for (int jy = 0; jy < coarse.my; ++jy)
    for (int jx = 0; jx < coarse.mx; ++jx) {
      double sum = 0.0;
      int count = 0;
      for (int iy = 2 * jy; iy < std::min(2 * jy + 2, grid.my); ++iy)
        for (int ix = 2 * jx; ix < std::min(2 * jx + 2, grid.mx); ++ix) {
          const double v = h[grid.index(ix, iy)];
          if (v < geometry::excluded_distance) {
            sum += v;
            ++count;
          }
        }
      if (count > 0) ch[coarse.index(jx, jy)] = sum / count;
    }
  Field start =
      coarse_grid_start(st, level + 1, coarse, ch, load, value, material, settings, iterations);
  NormalOperators& ops = st.operators.normal(coarse, material);
  normal::NormalSolver solver(coarse, *ops.product, ops.kernel, *ops.preconditioner);
  const normal::NormalResult r = solver.solve(
      ch, load, value, settings, start.empty() ? nullptr : &start, material.nu, material.g);
  iterations += r.iterations;
  if (!r.converged) return {};  // only a starting value: fall back to the geometric estimate
  Field fine(grid.size(), 0.0);
  for (int iy = 0; iy < grid.my; ++iy)
    for (int ix = 0; ix < grid.mx; ++ix)
      if (h[grid.index(ix, iy)] < geometry::excluded_distance)
        fine[grid.index(ix, iy)] = r.pn[coarse.index(ix / 2, iy / 2)];
  return fine;
}

/// Nested iteration for steady rolling on large grids, the tangential counterpart of
/// coarse_grid_start: the semismooth Newton iteration moves the adhesion front about one element
/// per step along the rows (docs/decisions.md), so a start whose division into adhesion and slip
/// is right to within an element or two saves most fine steps. The coarse problem has elements
/// twice as large: traction bound averaged over the 2×2 fine elements (force-conserving), slip
/// per step averaged over the fine contact elements and doubled with the rolling step, and the
/// operator (C − C′) with C′ one coarse step downstream. Its solution (itself started from a
/// coarser grid) is prolongated element-wise: slipping parents give slip at the fine bound in
/// the parent's direction, adhering parents their traction within the fine bound. Returns false
/// (start unchanged) when the grid is too small to gain or the coarse solve fails.
bool steady_coarse_start(PatchSolver::Impl& st, int level, const tangential::TangentialSystem& sys,
                         double shift_x, double shift_y, const CombinedMaterial& material,
                         const tangential::TangentialSettings& settings, Field& px, Field& py,
                         int& products) {
  constexpr std::size_t min_contact = 2000;  // measured: 71×81 (3.1k) gains 42 → 32 ms
  const Grid& grid = sys.grid;
  const std::size_t ncon =
      static_cast<std::size_t>(std::count(sys.contact.begin(), sys.contact.end(), char{1}));
  if (ncon < min_contact || grid.mx < 16 || grid.my < 16) return false;
  if (material.table) return false;  // a file's coefficients (C=9) exist for its element size only
  const Grid coarse{(grid.mx + 1) / 2, (grid.my + 1) / 2, grid.xl,
                    grid.yl,           2.0 * grid.dx,     2.0 * grid.dy};
  const std::size_t nc = coarse.size();
  tangential::TangentialSystem cs;
  cs.grid = coarse;
  cs.chi = sys.chi;
  cs.contact.assign(nc, 0);
  cs.bound.assign(nc, 0.0);
  cs.bx.assign(nc, 0.0);
  cs.by.assign(nc, 0.0);
  for (int jy = 0; jy < coarse.my; ++jy)
    for (int jx = 0; jx < coarse.mx; ++jx) {
      double bound = 0.0, bx = 0.0, by = 0.0;
      int children = 0, touching = 0;
      for (int iy = 2 * jy; iy < std::min(2 * jy + 2, grid.my); ++iy)
        for (int ix = 2 * jx; ix < std::min(2 * jx + 2, grid.mx); ++ix) {
          const std::size_t i = grid.index(ix, iy);
          ++children;
          if (!sys.contact[i]) continue;
          ++touching;
          bound += sys.bound[i];
          bx += sys.bx[i];
          by += sys.by[i];
        }
      const std::size_t j = coarse.index(jx, jy);
      if (touching == 0) continue;
      cs.contact[j] = 1;
      cs.bound[j] = bound / children;
      cs.bx[j] = 2.0 * bx / touching;
      cs.by[j] = 2.0 * by / touching;
    }
  Field cpx(nc, 0.0), cpy(nc, 0.0);
  steady_coarse_start(st, level + 1, cs, 2.0 * shift_x, 2.0 * shift_y, material, settings, cpx, cpy,
                      products);
  CoarseSteadyOperators& ops =
      st.operators.coarse_steady(coarse, material, 2.0 * shift_x, 2.0 * shift_y);
  cs.a = ops.view();
  // Only a start: the division into adhesion and slip is what matters (1e-3 measured 4 % faster
  // than EPS = 1e-5 at 287×323, with the same number of fine products).
  tangential::TangentialSettings coarse_settings = settings;
  coarse_settings.eps = std::max(settings.eps, 1e-3);
  const tangential::TangentialResult r =
      tangential::solve_semismooth_newton(cs, coarse_settings, &cpx, &cpy);
  products += r.iterations;
  if (!r.converged) return false;
  for (int iy = 0; iy < grid.my; ++iy)
    for (int ix = 0; ix < grid.mx; ++ix) {
      const std::size_t i = grid.index(ix, iy), j = coarse.index(ix / 2, iy / 2);
      if (!sys.contact[i]) continue;
      const double g = sys.bound[i], pabs = std::hypot(r.px[j], r.py[j]);
      if (pabs == 0.0) {
        px[i] = py[i] = 0.0;
      } else if (r.state[j] == ElementState::Slip || pabs > g) {
        px[i] = g * r.px[j] / pabs;
        py[i] = g * r.py[j] / pabs;
      } else {
        px[i] = r.px[j];
        py[i] = r.py[j];
      }
    }
  return true;
}

/// What a tangential solution reports per contact element: the relative slip S/δq (S per
/// step; T=1: δq = 1, a distance), 0 in Plastic elements, which do not slide, and there the
/// layer's flow |Δu_pl| = |−S| (plastic_flow empty when nothing flowed).
struct ReportedSlip {
  Field sx, sy;
  Field plastic_flow;
};

ReportedSlip reported_slip(const tangential::TangentialResult& t, const Field& pn, double dq) {
  const std::size_t n = pn.size();
  ReportedSlip r;
  r.sx.assign(n, 0.0);
  r.sy.assign(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    if (pn[i] <= 0.0) continue;
    if (t.state[i] == ElementState::Plastic) {
      if (r.plastic_flow.empty()) r.plastic_flow.assign(n, 0.0);
      r.plastic_flow[i] = std::hypot(t.sx[i], t.sy[i]);
      continue;
    }
    r.sx[i] = t.sx[i] / dq;
    r.sy[i] = t.sy[i] / dq;
  }
  return r;
}

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

void CaseSolver::solve_normal(const Field& px, const Field& py) {
  const std::size_t n = grid_.size();
  const bool force_given = problem_.normal.kind == model::NormalLoadKind::Force;
  const double load_value = force_given ? problem_.normal.force_N : problem_.normal.approach_mm;
  if (force_given && !(load_value > 0.0))
    throw ProblemError(fmt::format("normal force FN = {} must be positive", load_value));
  NormalOperators& ops = st_.operators.normal(grid_, sol_.material, interaction_);

  // h* = h + u_n(p_t): the normal displacement due to the current tangential tractions (K ≠ 0).
  Field h_star = sol_.h;
  if (coupled_ && tops_ != nullptr) {
    Field un_t(n);
    const double* in[2] = {px.data(), py.data()};
    double* out[1] = {un_t.data()};
    tops_->nt->apply(in, out);
    for (std::size_t i = 0; i < n; ++i)
      if (h_star[i] < geometry::excluded_distance) h_star[i] += un_t[i];
  }

  // The problem the last normal solve of this sequence had (a full solve at the vertical-force
  // iteration's last normal estimate): its answer.
  const auto& last = st_.last_normal;
  const CombinedMaterial& mat = sol_.material;
  if (problem_.sequence.normal_from_previous && sol_.pn.empty() && last &&
      last->eps <= problem_.solver.tolerance && last->force_given == force_given &&
      last->load == load_value && last->same_operator(grid_, mat) && !interaction_ &&
      !mat.viscoelastic() && !mat.table && last->h == h_star) {
    sol_.pn = last->pn;
    normal_un_ = last->un;
    sol_.totals.pen = last->pen;
    sol_.solver.normal_residual = 0.0;
    return;
  }

  // Starting pressure: the current one in an outer loop, else the previous case's when asked
  // for, else the Hertz solution for Hertzian geometries (physics.md §7.1), else the coarse-grid
  // or geometric estimate.
  const Field* initial = nullptr;
  const Field* initial_un = nullptr;  // A·initial when known (no starting product)
  if (!sol_.pn.empty()) {
    initial = &sol_.pn;
  } else if (problem_.sequence.normal_from_previous && prev_.present &&
             std::any_of(latest_pn_.begin(), latest_pn_.end(), [](double v) { return v > 0.0; })) {
    initial = &latest_pn_;
    // The last solve's pressure on the same grid, unmoved (an iterate of the vertical-force
    // iteration a fraction of an element away): its displacement came with it.
    if (latest_is_last_normal_) initial_un = &last->un;
  } else if (problem_.sequence.normal_from_previous && prev_.present &&
             std::any_of(prev_.pn.begin(), prev_.pn.end(), [](double v) { return v > 0.0; })) {
    initial = &prev_.pn;
  }

  const normal::NormalLoad load =
      force_given ? normal::NormalLoad::Force : normal::NormalLoad::Approach;
  normal::NormalResult r;
  if (sol_.material.viscoelastic()) {
    // Viscoelastic rolling (M=1): A is not symmetric, NormCG does not apply
    // (active_set_solver.hpp).
    const Field start = initial == nullptr ? hertz_start(grid_) : Field{};
    if (!start.empty()) initial = &start;
    normal::ActiveSetNormalSolver solver(grid_, *ops.product);
    r = solver.solve(h_star, load, load_value, normal_settings(), initial, mat.nu, mat.g);
  } else {
    r = solve_normal_cg(h_star, load, load_value, initial, initial_un, ops);
  }
  st_.last_normal.reset();
  if (r.converged && !sol_.material.viscoelastic() && !interaction_ && !sol_.material.table) {
    PatchSolver::Impl::NormalAnswer& a = st_.last_normal.emplace();
    a.grid = grid_;
    a.h = h_star;
    a.pn = r.pn;
    a.un = r.un;
    a.force_given = force_given;
    a.load = load_value;
    a.g = sol_.material.g;
    a.nu = sol_.material.nu;
    a.k = sol_.material.k;
    a.pen = r.pen;
    a.eps = normal_settings().eps;
  }
  if (!sol_.material.viscoelastic()) normal_un_ = r.un;
  sol_.pn = std::move(r.pn);
  sol_.totals.pen = r.pen;
  sol_.solver.normal_iterations += r.iterations;
  sol_.solver.normal_active_set_changes += r.set_changes;
  sol_.solver.normal_products += r.products;
  sol_.solver.normal_iteration_seconds += r.iteration_seconds;
  sol_.solver.normal_residual = r.residual;
  if (!r.converged) {
    sol_.solver.converged = false;
    sol_.solver.message = r.message;
  }
}

Field CaseSolver::hertz_start(const Grid& grid) const {
  if (!sol_.hertz.present) return {};
  Field start(grid.size(), 0.0);
  for (int iy = 0; iy < grid.my; ++iy)
    for (int ix = 0; ix < grid.mx; ++ix)
      start[grid.index(ix, iy)] =
          geometry::hertz_pressure(sol_.hertz, grid.x_centre(ix), grid.y_centre(iy));
  if (std::none_of(start.begin(), start.end(), [](double v) { return v > 0.0; })) return {};
  return start;
}

normal::NormalSettings CaseSolver::normal_settings() const {
  normal::NormalSettings settings;
  // At the case's tolerance also in a rough solve: its pressure is a sample of the
  // vertical-force iteration's normal estimates (wheelrail/vertical_force.hpp).
  settings.eps = problem_.solver.tolerance;
  settings.max_iterations = problem_.solver.max_inner_iterations;
  return settings;
}

std::optional<contact::ContactBox> CaseSolver::normal_box(const Field& h, double pen,
                                                          const Field* initial) const {
  const Grid& g = grid_;
  // Where h ≥ PEN the gap h − PEN + A·p stays open whatever p ≥ 0: the contact lies in the
  // interpenetration. Wheel/rail grids hug that, but the contact covers a third to a half of
  // it (a flat lateral gap), and a starting pressure (an iterate's, the previous case's) tells
  // where: the box around its support (contact_box adds a free element each side and rounds
  // up), to be checked afterwards. Wider margins measured: more products, as few restarts.
  int ix_lo = g.mx, ix_hi = -1, iy_lo = g.my, iy_hi = -1;
  if (initial != nullptr)
    for (int iy = 0; iy < g.my; ++iy)
      for (int ix = 0; ix < g.mx; ++ix)
        if ((*initial)[g.index(ix, iy)] > 0.0) {
          ix_lo = std::min(ix_lo, ix);
          ix_hi = std::max(ix_hi, ix);
          iy_lo = std::min(iy_lo, iy);
          iy_hi = std::max(iy_hi, iy);
        }
  const bool speculative = ix_hi >= 0;
  std::vector<char> inside(h.size(), 0);
  for (int iy = 0; iy < g.my; ++iy)
    for (int ix = 0; ix < g.mx; ++ix) {
      const bool near_start =
          !speculative || (ix >= ix_lo && ix <= ix_hi && iy >= iy_lo && iy <= iy_hi);
      inside[g.index(ix, iy)] = near_start && h[g.index(ix, iy)] < pen;
    }
  return contact::contact_box(g, inside, max_normal_box_fraction);
}

normal::NormalResult CaseSolver::solve_normal_cg(const Field& h, normal::NormalLoad load,
                                                 double value, const Field* initial,
                                                 const Field* initial_un, NormalOperators& ops) {
  const CombinedMaterial& mat = sol_.material;
  const normal::NormalSettings settings = normal_settings();
  // With the approach given on a half-space whose influence coefficients are positive the
  // problem on a box that holds the contact is the same problem, with FFT products on the box
  // only (contact/contact_box.hpp). Not for a file's coefficients (no sign known) or attenuated
  // parts (IPLAN=4, not translation invariant).
  std::optional<contact::ContactBox> box;
  if (load == normal::NormalLoad::Approach && !interaction_ && !mat.table)
    box = normal_box(h, value, initial);
  const Grid& grid = box ? box->grid : grid_;
  const Field h_box = box ? contact::restrict_to_box(h, grid_, *box) : Field{};
  const Field& hb = box ? h_box : h;

  Field initial_box, initial_un_box, start;
  if (box && initial != nullptr) {
    // A displacement on the box is the whole pressure's only when the box holds all of it.
    const bool whole = initial_un != nullptr && contact::zero_outside(*initial, grid_, *box);
    if (whole) initial_un_box = contact::restrict_to_box(*initial_un, grid_, *box);
    initial_un = whole ? &initial_un_box : nullptr;
    initial_box = contact::restrict_to_box(*initial, grid_, *box);
    initial = &initial_box;
  }
  if (initial == nullptr) {
    start = hertz_start(grid);
    if (!start.empty()) initial = &start;
  }
  if (initial == nullptr) {
    int coarse_iterations = 0;
    start = coarse_grid_start(st_, 1, grid, hb, load, value, mat, settings, coarse_iterations);
    sol_.solver.normal_coarse_iterations += coarse_iterations;
    if (!start.empty()) initial = &start;
  }

  NormalOperators& bops = box ? st_.operators.normal(grid, mat) : ops;
  normal::NormalSolver solver(grid, *bops.product, bops.kernel, *bops.preconditioner,
                              bops.interaction.get());
  normal::NormalResult r =
      solver.solve(hb, load, value, settings, initial, mat.nu, mat.g, initial_un);
  if (!box) return r;

  // On the whole grid: the pressure, and its displacement (one product) for the outputs and
  // for the check that the contact indeed lies in the box.
  Field pn = contact::expand_from_box(r.pn, grid_, *box, 0.0);
  Field un(grid_.size());
  ops.product->apply(pn.data(), un.data());
  ++r.products;
  bool holds = true;
  for (int iy = 0; iy < grid_.my && holds; ++iy)
    for (int ix = 0; ix < grid_.mx && holds; ++ix) {
      const std::size_t i = grid_.index(ix, iy);
      holds = box->contains(ix, iy) || h[i] + un[i] >= value;
    }
  if (!holds) {
    // The contact reaches beyond the starting pressure's box (around the interpenetration only
    // by rounding): on the whole grid, from here.
    normal::NormalSolver full(grid_, *ops.product, ops.kernel, *ops.preconditioner,
                              ops.interaction.get());
    normal::NormalResult again = full.solve(h, load, value, settings, &pn, mat.nu, mat.g, &un);
    again.iterations += r.iterations;
    again.set_changes += r.set_changes;
    again.products += r.products;
    again.iteration_seconds += r.iteration_seconds;
    return again;
  }
  r.pn = std::move(pn);
  r.un = std::move(un);
  return r;
}

void CaseSolver::set_prescribed_pressure() {
  const model::PressureModel model = problem_.normal.pressure;
  if (model == model::PressureModel::Kpec || model == model::PressureModel::Analyn) {
    set_approximate_pressure(model == model::PressureModel::Kpec);
    return;
  }
  const HertzReport& hz = sol_.hertz;
  if (model == model::PressureModel::Sdec) {
    const auto& v = problem_.potential.values;  // AA BNEG BPOS SCALE
    if (problem_.potential.ipotcn != -6)
      throw ProblemError("SDEC pressures (B=4) need the SDEC potential contact (IPOTCN = -6)");
    sol_.pn = simplified::sdec_pressure(grid_, v[0], v[1], v[2], hz.fn);
    sol_.totals.pen = hz.pen;  // of the mean ellipse (a, b), as for B=2, 3
    return;
  }
  const bool elliptic = problem_.normal.pressure == model::PressureModel::EllipticHertzian;
  if (!hz.present)
    throw ProblemError(
        fmt::format("prescribed pressures B={} need a Hertzian potential contact (IPOTCN < 0)",
                    elliptic ? 2 : 3));
  const auto shape =
      elliptic ? simplified::PressureShape::Elliptic : simplified::PressureShape::Parabolic;
  sol_.pn = simplified::prescribed_pressure(grid_, hz, shape, hz.fn);
  sol_.totals.pen = hz.two_dimensional ? 0.0 : hz.pen;  // 2-D Hertz has no approach
}

void CaseSolver::set_approximate_pressure(bool kpec) {
  const char* name = kpec ? "KPEC (B=5)" : "ANALYN (B=6)";
  if (problem_.normal.kind != model::NormalLoadKind::Approach)
    throw ProblemError(fmt::format("{} needs a prescribed approach (N=0)", name));
  if (sol_.hertz.present)
    throw ProblemError(fmt::format("{} needs a non-Hertzian potential contact (IPOTCN > 0)", name));
  Field h_total = sol_.h;
  for (double& v : h_total)
    if (v < geometry::excluded_distance) v -= problem_.normal.approach_mm;
  simplified::ApproximateNormal r =
      kpec ? simplified::kpec_pressure(grid_, h_total, sol_.material,
                                       st_.operators.normal_kernel(grid_, sol_.material))
           : simplified::analyn_pressure(grid_, h_total, sol_.material);
  sol_.pn = std::move(r.pn);
  sol_.solver.kpec_rows_beyond_interpenetration = r.rows_beyond_interpenetration;
  approximate_ = true;
  sol_.totals.pen = problem_.normal.approach_mm;
}

double CaseSolver::total_normal_force() const {
  if (prescribed_ && !approximate_) return sol_.hertz.fn;
  double fn = 0.0;
  for (double v : sol_.pn) fn += v;
  return fn * grid_.element_area();
}

tangential::TangentialResult CaseSolver::solve_simplified(double cksi, double ceta, double cphi) {
  const model::TangentialKind kind = problem_.tangential.kind;
  simplified::SimplifiedCase c;
  c.grid = grid_;
  c.pn = sol_.pn;
  c.ellipse = sol_.hertz.present ? simplified::Ellipse{sol_.hertz.aa, sol_.hertz.bb}
                                 : simplified::equivalent_ellipse(grid_, sol_.pn);
  c.g = sol_.material.g;
  c.nu = sol_.material.nu;
  c.mu = friction_->coefficient();
  simplified::FastsimVelocityFriction velocity;
  if (friction_->velocity_dependent()) {
    velocity = {friction_.get(), problem_.friction.memory_distance_mm,
                problem_.friction.memory_floor_speed_mm_s, sol_.kinematics.dt};
    c.velocity = &velocity;
    if (kind == model::TangentialKind::TransientRolling) c.mu_prev = prev_.mu;
  }
  c.fn = total_normal_force();
  c.model = simplified::simplified_model(problem_);
  c.creepages = {cksi, ceta, cphi};
  const simplified::RigidShiftParts shift =
      simplified::rigid_shift_parts(grid_, problem_, sol_.kinematics, c.creepages);
  {
    Field wx = shift.wx, wy = shift.wy;
    for (std::size_t i = 0; i < wx.size(); ++i) {
      wx[i] += shift.spin_x[i];
      wy[i] += shift.spin_y[i];
    }
    record_rigid_slip(wx, wy);
  }
  c.shift = &shift;
  c.steady = kind == model::TangentialKind::SteadyRolling;
  c.chi = sol_.kinematics.chi;
  Field ux_prev, uy_prev;
  if (kind == model::TangentialKind::TransientRolling && prev_.present) {
    ux_prev = simplified::upstream_field(grid_, prev_.ux, c.chi, sol_.kinematics.dq);
    uy_prev = simplified::upstream_field(grid_, prev_.uy, c.chi, sol_.kinematics.dq);
    c.ux_prev = ux_prev;
    c.uy_prev = uy_prev;
  } else if (kind == model::TangentialKind::Shift && prev_.present) {
    // A shift moves no particles: each element starts from its own previous displacement.
    c.ux_prev = prev_.ux;
    c.uy_prev = prev_.uy;
  }
  simplified::SimplifiedOutcome r = simplified::solve_simplified(c);
  SimplifiedReport& rep = sol_.simplified;
  rep.present = true;
  rep.flx1 = r.flex.l1;
  rep.flx2 = r.flex.l2;
  rep.flx3 = r.flex.l3;
  rep.k_eff = r.k_eff;
  rep.a = c.ellipse.a;
  rep.b = c.ellipse.b;

  tangential::TangentialResult res;
  res.px = std::move(r.fields.px);
  res.py = std::move(r.fields.py);
  res.sx = std::move(r.fields.sx);
  res.sy = std::move(r.fields.sy);
  res.state = std::move(r.fields.state);
  res.converged = true;  // a direct method: one pass
  simplified_ux_ = std::move(r.fields.ux);
  simplified_uy_ = std::move(r.fields.uy);
  mu_ = std::move(r.fields.mu);
  return res;
}

/// (u_x, u_y) += C·(p_x, p_y, p_n) with the unshifted coefficients (C_tn only when coupled).
void CaseSolver::add_unshifted_displacement(const Field& px, const Field& py, const Field& pn,
                                            Field& ux, Field& uy) const {
  const std::size_t n = grid_.size();
  Field tx(n), ty(n);
  const double* in_t[2] = {px.data(), py.data()};
  double* out[2] = {tx.data(), ty.data()};
  tops_->a->apply(in_t, out);
  for (std::size_t i = 0; i < n; ++i) {
    ux[i] += tx[i];
    uy[i] += ty[i];
  }
  if (!coupled_) return;
  const double* in_n[1] = {pn.data()};
  tops_->tn->apply(in_n, out);
  for (std::size_t i = 0; i < n; ++i) {
    ux[i] += tx[i];
    uy[i] += ty[i];
  }
}

/// b = the slip per step at p_t = 0: rigid shift, the pressure's tangential displacement (K ≠ 0)
/// and, for shifts and transient rolling, minus the previous-time displacement of the particles;
/// with the leading-edge correction of physics.md §9.4 for transient steps longer than δx.
void CaseSolver::assemble_slip_at_zero_traction(tangential::TangentialSystem& sys, double cksi,
                                                double ceta, double cphi) {
  using namespace tangential;
  const std::size_t n = grid_.size();
  const model::TangentialKind kind = problem_.tangential.kind;
  const RigidShift w = rigid_shift(grid_, problem_, sol_.kinematics, cksi, ceta, cphi);
  sys.bx = w.wx;
  sys.by = w.wy;
  record_rigid_slip(w.wx, w.wy);
  if (coupled_) {
    // Tangential displacement per step due to the pressure (C_tn, or (C − C′)_tn when steady).
    Field ux(n), uy(n);
    const double* in[1] = {sol_.pn.data()};
    double* out[2] = {ux.data(), uy.data()};
    tops_->tn->apply(in, out);
    for (std::size_t i = 0; i < n; ++i) {
      sys.bx[i] += ux[i];
      sys.by[i] += uy[i];
    }
  }
  Field prev_ux(n, 0.0), prev_uy(n, 0.0);
  if (kind != model::TangentialKind::SteadyRolling && prev_.present) {
    // Displacement of the same particles at the previous time.
    // Exact for any step with the shifted coefficients C′, also where the particles have
    // left the grid (docs/decisions.md: CONTACT interpolates for fractional steps).
    const double* in[3] = {prev_.px.data(), prev_.py.data(), prev_.pn.data()};
    double* out[2] = {prev_ux.data(), prev_uy.data()};
    tops_->prev->apply(in, out);
    for (std::size_t i = 0; i < n; ++i) {
      sys.bx[i] -= prev_ux[i];
      sys.by[i] -= prev_uy[i];
    }
  }
  if (kind != model::TangentialKind::TransientRolling) return;
  const std::vector<LeadingEdgeEntry> entries =
      leading_edge_entries(grid_, sys.contact, sol_.kinematics.chi, sol_.kinematics.dq);
  if (entries.empty()) return;
  // The previous displacement where the particles entered: C (unshifted) at the edge element.
  Field edge_ux(n, 0.0), edge_uy(n, 0.0);
  if (prev_.present) add_unshifted_displacement(prev_.px, prev_.py, prev_.pn, edge_ux, edge_uy);
  for (const LeadingEdgeEntry& e : entries) {
    const std::size_t i = e.element;
    sys.bx[i] += (e.factor - 1.0) * w.wx[i] + prev_ux[i] - edge_ux[e.edge];
    sys.by[i] += (e.factor - 1.0) * w.wy[i] + prev_uy[i] - edge_uy[e.edge];
  }
}

std::vector<char> CaseSolver::contact_set() const {
  std::vector<char> contact(grid_.size(), 0);
  for (std::size_t i = 0; i < contact.size(); ++i) contact[i] = sol_.pn[i] > 0.0;
  return contact;
}

contact::TangentialSolveWithFriction CaseSolver::warm_started_solve(double cksi, double ceta,
                                                                    double cphi, Field& start_x,
                                                                    Field& start_y) {
  return [this, cksi, ceta, cphi, &start_x, &start_y](const Field& mu) {
    tangential::TangentialResult t = solve_tangential(cksi, ceta, cphi, &start_x, &start_y, &mu);
    sol_.solver.tangential_iterations += t.iterations;
    start_x = t.px;
    start_y = t.py;
    return t;
  };
}

tangential::TangentialResult CaseSolver::adopt_friction_iteration(
    contact::FrictionIterationOutcome& r) {
  sol_.solver.slip_velocity_passes += r.passes;
  sol_.solver.slip_velocity_trace = std::move(r.trace);
  mu_ = std::move(r.mu);
  tangential::TangentialResult tang = std::move(r.tangential);
  tang.iterations = 0;  // counted per pass by warm_started_solve
  if (!r.converged && tang.converged) {
    tang.converged = false;
    tang.message = r.message;
  }
  return tang;
}

contact::FrictionMemoryInput CaseSolver::friction_memory(const std::vector<char>& contact) const {
  contact::FrictionMemoryInput memory;
  memory.grid = &grid_;
  memory.contact = &contact;
  memory.law = friction_.get();
  memory.memory_distance_mm = problem_.friction.memory_distance_mm;
  memory.memory_floor_speed_mm_s = problem_.friction.memory_floor_speed_mm_s;
  memory.dt_s = sol_.kinematics.dt;
  memory.steady = problem_.tangential.kind == model::TangentialKind::SteadyRolling;
  memory.chi_rad = sol_.kinematics.chi;
  memory.previous_mu = prev_.mu.empty() ? nullptr : &prev_.mu;
  return memory;
}

tangential::TangentialResult CaseSolver::solve_velocity_dependent(double cksi, double ceta,
                                                                  double cphi, const Field& px,
                                                                  const Field& py) {
  const std::size_t n = grid_.size();
  const EffectiveKinematics& k = sol_.kinematics;
  const std::vector<char> contact = contact_set();
  const contact::FrictionMemoryInput memory = friction_memory(contact);

  Field speed(n, 0.0);
  switch (problem_.solver.initial_slip_velocity) {
    case model::InitialSlipVelocity::Previous:  // |S|/δt = |s|·δq/δt = |s|·V of that case
      if (prev_.present)
        for (std::size_t i = 0; i < n; ++i)
          speed[i] = std::hypot(prev_.sx[i], prev_.sy[i]) * prev_.veloc;
      break;
    case model::InitialSlipVelocity::Zero:
      break;
    case model::InitialSlipVelocity::RollingVelocity:
      speed.assign(n, k.veloc);
      break;
  }
  contact::SlipVelocitySettings settings;
  settings.relaxation = problem_.solver.slip_velocity_relaxation;
  settings.max_passes = problem_.solver.max_slip_velocity_passes;
  Field start_x = px, start_y = py;
  contact::SlipVelocityOutcome r = contact::solve_with_slip_velocity(
      memory, speed, settings, warm_started_solve(cksi, ceta, cphi, start_x, start_y));
  return adopt_friction_iteration(r);
}

Field CaseSolver::body1_temperature(const tangential::TangentialResult& t) const {
  Solution s;  // the fields §15 reads, from the provisional tangential solution
  s.grid = grid_;
  s.pn = sol_.pn;
  s.px = t.px;
  s.py = t.py;
  s.state = t.state;
  s.kinematics = sol_.kinematics;
  ReportedSlip slip = reported_slip(t, sol_.pn, s.kinematics.dq);
  s.sx = std::move(slip.sx);
  s.sy = std::move(slip.sy);
  return post::surface_temperatures(problem_.heat, s, true, slip.plastic_flow).temp1;
}

tangential::TangentialResult CaseSolver::solve_temperature_dependent(double cksi, double ceta,
                                                                     double cphi, const Field& px,
                                                                     const Field& py) {
  const std::size_t n = grid_.size();
  const std::vector<char> contact = contact_set();
  // Start from the temperatures without frictional heat (bulk, and the contact temperature in
  // the contact): a solution with every element adhering.
  tangential::TangentialResult cold;
  cold.px.assign(n, 0.0);
  cold.py.assign(n, 0.0);
  cold.sx.assign(n, 0.0);
  cold.sy.assign(n, 0.0);
  cold.state.assign(n, ElementState::Exterior);
  for (std::size_t i = 0; i < n; ++i)
    if (contact[i]) cold.state[i] = ElementState::Adhesion;
  contact::TemperatureIterationSettings settings;
  settings.relaxation = problem_.solver.slip_velocity_relaxation;
  settings.max_passes = problem_.solver.max_slip_velocity_passes;
  Field start_x = px, start_y = py;
  contact::TemperatureIterationOutcome r = contact::solve_with_temperature(
      friction_memory(contact), body1_temperature(cold), settings,
      warm_started_solve(cksi, ceta, cphi, start_x, start_y),
      [&](const tangential::TangentialResult& t) { return body1_temperature(t); });
  return adopt_friction_iteration(r);
}

tangential::TangentialResult CaseSolver::solve_tangential(double cksi, double ceta, double cphi,
                                                          const Field* px0, const Field* py0,
                                                          const Field* mu) {
  using namespace tangential;
  const std::size_t n = grid_.size();
  TangentialSystem sys;
  sys.grid = grid_;
  sys.chi = sol_.kinematics.chi;
  sys.a = tops_->view();
  sys.contact = contact_set();
  const std::vector<double>& rows = problem_.friction.row_coefficients;
  if (mu != nullptr) {
    sys.bound.assign(n, 0.0);
    for (std::size_t i = 0; i < n; ++i)
      if (sys.contact[i]) sys.bound[i] = (*mu)[i] * sol_.pn[i];
  } else if (!rows.empty()) {
    // V=3: Coulomb's bound with the coefficient of the element's grid row.
    if (rows.size() != static_cast<std::size_t>(grid_.my))
      throw ProblemError(fmt::format(
          "variable friction V=3 gives {} rows of friction coefficients for a grid of MY = {}",
          rows.size(), grid_.my));
    sys.bound.assign(n, 0.0);
    for (int iy = 0; iy < grid_.my; ++iy)
      for (int ix = 0; ix < grid_.mx; ++ix) {
        const std::size_t i = grid_.index(ix, iy);
        if (sys.contact[i]) sys.bound[i] = rows[static_cast<std::size_t>(iy)] * sol_.pn[i];
      }
  } else {
    friction_->traction_bounds(sol_.pn, sys.bound);
  }
  assemble_slip_at_zero_traction(sys, cksi, ceta, cphi);
  if (!layer_plastic_) return run_tangential_solver(sys, px0, py0);

  // Interfacial layer with plasticity: bound min(μ·p_n, τ_c). With hardening or softening
  // (k_τ ≠ 0) τ_c depends on this case's plastic flow: a fixed point on the increments, which
  // contracts by |k_τ|/(element stiffness), small for any real layer.
  const model::InterfacialLayer& layer = problem_.bodies.layer;
  const Field friction_bound = sys.bound;
  Field increment(n, 0.0);
  TangentialResult tang;
  constexpr int max_passes = 50;
  for (int pass = 1; pass <= max_passes; ++pass) {
    const Field tau = contact::yield_limits(layer, plastic_history_, increment);
    for (std::size_t i = 0; i < n; ++i) sys.bound[i] = std::min(friction_bound[i], tau[i]);
    tang = run_tangential_solver(sys, px0, py0);
    Field next;
    contact::mark_plastic_elements(friction_bound, tau, tang, next);
    double change = 0.0, size = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      change = std::max(change, std::abs(next[i] - increment[i]));
      size = std::max(size, next[i]);
    }
    increment = std::move(next);
    if (layer.hardening_N_mm3 == 0.0 || !tang.converged ||
        change <= problem_.solver.tolerance * size)
      return tang;
  }
  tang.converged = false;
  tang.message = fmt::format(
      "the yield limit of the hardening layer (K_TAU) did not settle in {} passes", max_passes);
  return tang;
}

tangential::TangentialResult CaseSolver::run_tangential_solver(
    const tangential::TangentialSystem& sys, const Field* px0, const Field* py0) {
  // IPLAN=4 attenuates between parts of the grid: its operators are not translation invariant.
  const std::optional<contact::ContactBox> box =
      interaction_ ? std::nullopt
                   : contact::contact_box(sys.grid, sys.contact, max_contact_box_fraction);
  if (!box) return solve_on_grid(sys, px0, py0);
  const auto& k = sol_.kinematics;
  const TangentialOperators& ops =
      st_.operators.tangential(box->grid, sol_.material, problem_.tangential.kind,
                               k.dq * std::cos(k.chi), k.dq * std::sin(k.chi));
  const tangential::TangentialSystem sub = contact::restrict_to_box(sys, *box, ops.view());
  Field bx0, by0;
  if (px0 != nullptr) bx0 = contact::restrict_to_box(*px0, sys.grid, *box);
  if (py0 != nullptr) by0 = contact::restrict_to_box(*py0, sys.grid, *box);
  const tangential::TangentialResult r =
      solve_on_grid(sub, px0 ? &bx0 : nullptr, py0 ? &by0 : nullptr);
  return contact::expand_from_box(r, sys.grid, *box);
}

tangential::TangentialResult CaseSolver::solve_on_grid(const tangential::TangentialSystem& sys,
                                                       const Field* px0, const Field* py0) {
  using namespace tangential;
  const std::size_t n = sys.grid.size();
  const Grid& grid = sys.grid;
  const model::TangentialKind kind = problem_.tangential.kind;
  TangentialSettings settings;
  // With prescribed forces the Newton loop stops at |ΔF/(μFN)| ≤ EPS; the tangential solutions
  // it differentiates must be an order more accurate, or their noise stalls it.
  const double eps = std::max(problem_.solver.tolerance, problem_.solver.rough_tolerance);
  settings.eps =
      problem_.tangential.prescribed == model::TangentialPrescribed::Creepages ? eps : 0.1 * eps;
  settings.max_iterations = problem_.solver.max_inner_iterations;
  settings.slip_of_last_iterate = rough_;  // a rough solve's slip is not read
  TangentialSolverKind method = select_solver(problem_);
  if (method == TangentialSolverKind::SteadyGS) {
    // SteadyGS needs a free trailing column (the inflow of the previous-time field).
    const int trailing = std::cos(sys.chi) > 0.0 ? 0 : grid.mx - 1;
    bool blocked = false;
    for (int iy = 0; iy < grid.my && !blocked; ++iy)
      blocked = sys.contact[grid.index(trailing, iy)] != 0;
    if (blocked) {
      method = TangentialSolverKind::ConvexGS;
      notes_.push_back("contact in the trailing column: using ConvexGS instead of SteadyGS");
    }
  }
  if (problem_.solver.relaxation_adhesion > 0.0)
    settings.omega_h = problem_.solver.relaxation_adhesion;
  if (problem_.solver.relaxation_slip > 0.0) settings.omega_s = problem_.solver.relaxation_slip;
  // CONTACT's TangCG (T=1,2) and SteadyGS (T=3) roles are both taken by the semismooth Newton
  // iteration (docs/decisions.md); ConvexGS stays the Gauss–Seidel iteration. Should Newton
  // fail, the preconditioned Jacobi iteration (and after it ConvexGS) starts from its result.
  if (method == TangentialSolverKind::ConvexGS) return solve_convex_gs(sys, settings, px0, py0);
  Field start_x, start_y;
  const bool cold =
      (px0 == nullptr ||
       std::all_of(px0->begin(), px0->end(), [](double v) { return v == 0.0; })) &&
      (py0 == nullptr || std::all_of(py0->begin(), py0->end(), [](double v) { return v == 0.0; }));
  if (kind == model::TangentialKind::SteadyRolling && cold) {
    start_x.assign(n, 0.0);
    start_y.assign(n, 0.0);
    int coarse_products = 0;
    if (steady_coarse_start(st_, 1, sys, tops_->shift_x, tops_->shift_y, sol_.material, settings,
                            start_x, start_y, coarse_products)) {
      px0 = &start_x;
      py0 = &start_y;
    }
    sol_.solver.tangential_coarse_iterations += coarse_products;
  }
  TangentialResult newton = solve_semismooth_newton(sys, settings, px0, py0);
  if (newton.converged) return newton;
  notes_.push_back(newton.message + "; continuing with the preconditioned Jacobi iteration");
  TangentialResult jacobi = solve_preconditioned_jacobi(sys, settings, &newton.px, &newton.py);
  jacobi.iterations += newton.iterations;
  return jacobi;
}

ForceIterationInput CaseSolver::force_iteration_input(const Solution* prev) const {
  const model::TangentialLoading& t = problem_.tangential;
  const bool both = t.prescribed == model::TangentialPrescribed::Forces;
  ForceIterationInput in;
  in.unknowns = both ? 2 : 1;
  in.target_x = t.force_x_over_mu_fn;
  in.target_y = t.force_y_over_mu_fn;
  in.fixed_eta = t.creepage.lateral;
  const bool restart = !problem_.sequence.force_iteration_from_previous || !prev;
  in.start_ksi = restart ? 1e-6 : prev->totals.creep_x + prev->totals.shift_x;
  in.start_eta =
      both ? (restart ? 0.0 : prev->totals.creep_y + prev->totals.shift_y) : t.creepage.lateral;
  if (!restart) {
    const Sensitivities& d = prev->sensitivities;
    in.start_jacobian = {d.dfx_dksi, d.dfx_deta, d.dfy_dksi, d.dfy_deta};
  }
  in.eps = problem_.solver.tolerance;
  in.max_iterations = problem_.solver.max_newton_iterations;
  return in;
}

const Solution* CaseSolver::map_sequence(model::TangentialKind kind) {
  const Solution* prev =
      problem_.sequence.continue_previous && st_.previous && !st_.previous->pn.empty()
          ? &*st_.previous
          : nullptr;
  // Steady rolling by the simplified theory, with pressures that need no normal iteration and a
  // friction law without memory, reads nothing of the previous solution (no start, no previous
  // time step): its fields are not mapped (every solve of a KPEC sweep mapped eight fields).
  const bool reads_previous =
      !(simplified_ && prescribed_ && kind == model::TangentialKind::SteadyRolling &&
        !friction_->velocity_dependent() && !friction_->temperature_dependent());
  if (!reads_previous) {
    prev_ = PreviousFields{};
    return prev;
  }
  prev_ = map_previous(prev, grid_, problem_.sequence.origin_x_mm - st_.previous_origin_x,
                       problem_.sequence.origin_y_mm - st_.previous_origin_y);
  // Steady rolling remembers the previous solution only as a start (transient rolling and
  // shifts as the previous time step, which must stay what it was).
  if (problem_.sequence.new_step && prev != nullptr && st_.earlier &&
      kind == model::TangentialKind::SteadyRolling)
    extrapolate_start(prev_, map_previous(&*st_.earlier, grid_,
                                          problem_.sequence.origin_x_mm - st_.earlier_origin_x,
                                          problem_.sequence.origin_y_mm - st_.earlier_origin_y));
  // A new step starts from the extrapolated previous steps; the iterates of a step from the
  // last of them, full solve or normal estimate.
  if (problem_.sequence.normal_from_previous && prev != nullptr && !problem_.sequence.new_step &&
      !st_.latest_pn.empty()) {
    const double sx = problem_.sequence.origin_x_mm - st_.latest_origin_x;
    const double sy = problem_.sequence.origin_y_mm - st_.latest_origin_y;
    latest_pn_ = map_field(st_.latest_pn, st_.latest_grid, grid_, sx, sy);
    // Element for element the last normal solve's pressure (same grid, no offset): A·p is that
    // solve's displacement.
    const std::optional<ElementOffset> o = element_offset(st_.latest_grid, grid_, sx, sy);
    const auto& last = st_.last_normal;
    latest_is_last_normal_ = o && o->ox == 0 && o->oy == 0 && last &&
                             st_.latest_grid.mx == grid_.mx && st_.latest_grid.my == grid_.my &&
                             last->same_operator(grid_, sol_.material) && last->pn == st_.latest_pn;
  }
  return prev;
}

void CaseSolver::run() {
  const std::size_t n = grid_.size();
  const model::TangentialKind kind = problem_.tangential.kind;
  const bool tangential = kind != model::TangentialKind::None;
  const model::TangentialPrescribed prescribed = problem_.tangential.prescribed;
  const model::Creepages& creepage = problem_.tangential.creepage;
  prescribed_ = problem_.normal.pressure != model::PressureModel::ExactHalfSpace;
  simplified_ = problem_.bodies.compliance != model::TangentialCompliance::ExactHalfSpace;
  rough_ = problem_.solver.rough_tolerance > problem_.solver.tolerance;
  // The simplified theory has no normal-tangential coupling.
  coupled_ = !simplified_ && elastic::is_coupled(sol_.material);
  friction_ = physics::make_friction_law(problem_.friction);
  sol_.kinematics = tangential::effective_kinematics(problem_, grid_, &notes_);

  const Solution* prev = map_sequence(kind);
  layer_plastic_ = problem_.bodies.has_layer && problem_.bodies.layer.plastic() && !simplified_;
  if (layer_plastic_) {
    if (kind == model::TangentialKind::TransientRolling &&
        problem_.bodies.layer.hardening_N_mm3 != 0.0)
      throw NotSupportedError(
          "a hardening or softening interfacial layer (K_TAU != 0) in transient rolling");
    if (kind == model::TangentialKind::SteadyRolling) {
      plastic_history_ = {};
      plastic_history_.steady_grid = &grid_;
      plastic_history_.chi_rad = sol_.kinematics.chi;
    } else {
      plastic_history_ = prev_.plastic;
      if (plastic_history_.accumulated.empty()) plastic_history_.accumulated.assign(n, 0.0);
    }
  }
  if (tangential && !simplified_) {
    const auto& k = sol_.kinematics;
    tops_ = &st_.operators.tangential(grid_, sol_.material, kind, k.dq * std::cos(k.chi),
                                      k.dq * std::sin(k.chi), interaction_);
  }

  Field px(n, 0.0), py(n, 0.0);
  // Warm start of the tangential tractions from the previous case on the same grid.
  if (prev_.present && tangential) {
    px = prev_.px;
    py = prev_.py;
  }
  const int max_outer = coupled_ && !prescribed_ && tangential
                            ? std::max(1, problem_.solver.max_normal_tangential_passes)
                            : 1;
  tangential::TangentialResult tang;
  ForceIterationResult creep{creepage.longitudinal, creepage.lateral, 0, true, {}, {}};
  int outer = 0;
  for (outer = 1; outer <= max_outer; ++outer) {
    const Field pn_old = sol_.pn.empty() ? Field(n, 0.0) : sol_.pn, px_old = px, py_old = py;
    // Johnson's process (MAXOUT = 1): the normal problem sees no tangential tractions.
    if (prescribed_)
      set_prescribed_pressure();
    else
      solve_normal(max_outer > 1 ? px : Field(n, 0.0), max_outer > 1 ? py : Field(n, 0.0));
    if (!tangential) break;
    auto evaluate = [&](double cksi, double ceta) {
      const double cphi = creepage.spin_rad_per_mm;
      if (simplified_)
        tang = solve_simplified(cksi, ceta, cphi);
      else if (friction_->velocity_dependent())
        tang = solve_velocity_dependent(cksi, ceta, cphi, px, py);
      else if (friction_->temperature_dependent())
        tang = solve_temperature_dependent(cksi, ceta, cphi, px, py);
      else
        tang = solve_tangential(cksi, ceta, cphi, &px, &py);
      sol_.solver.tangential_iterations += tang.iterations;
      px = tang.px;
      py = tang.py;
      double fx = 0.0, fy = 0.0;
      for (std::size_t i = 0; i < n; ++i) {
        fx += tang.px[i];
        fy += tang.py[i];
      }
      const double fn = total_normal_force();
      const double mu = friction_->coefficient();
      const double scale = mu * fn > 0.0 ? 1.0 / (mu * fn) : 0.0;
      return std::array<double, 2>{fx * grid_.element_area() * scale,
                                   fy * grid_.element_area() * scale};
    };
    if (prescribed == model::TangentialPrescribed::Creepages) {
      evaluate(creepage.longitudinal, creepage.lateral);
    } else {
      creep = force_iteration(force_iteration_input(prev), evaluate);
      sol_.solver.newton_iterations += creep.iterations;
      sol_.sensitivities.dfx_dksi = creep.jacobian[0];
      sol_.sensitivities.dfx_deta = creep.jacobian[1];
      sol_.sensitivities.dfy_dksi = creep.jacobian[2];
      sol_.sensitivities.dfy_deta = creep.jacobian[3];
      if (!creep.converged) {
        sol_.solver.converged = false;
        sol_.solver.message = creep.message;
      }
    }
    if (!tang.converged) {
      sol_.solver.converged = false;
      sol_.solver.message = tang.message;
    }
    if (max_outer == 1) break;
    const double change =
        std::sqrt(std::pow(rms_change(sol_.pn, pn_old), 2) + std::pow(rms_change(px, px_old), 2) +
                  std::pow(rms_change(py, py_old), 2));
    const double size =
        std::sqrt(std::pow(norm(sol_.pn), 2) + std::pow(norm(px), 2) + std::pow(norm(py), 2));
    if (change <= 5.0 * problem_.solver.tolerance * size) break;
  }
  if (outer > max_outer) {
    outer = max_outer;
    sol_.solver.converged = false;
    sol_.solver.message = fmt::format(
        "the normal-tangential (Panagiotopoulos) loop did not converge in MAXOUT = {} passes",
        max_outer);
  }
  sol_.statistics.inorm = prescribed_ ? 0 : outer;
  sol_.statistics.itang = tangential ? outer : 0;
  // With velocity-dependent friction ITANG counts the slip-velocity passes, as in CONTACT.
  if (tangential && sol_.solver.slip_velocity_passes > 0)
    sol_.statistics.itang = sol_.solver.slip_velocity_passes;

  if (tangential) {
    if (kind == model::TangentialKind::Shift) {
      sol_.totals.shift_x = creep.ksi;
      sol_.totals.shift_y = creep.eta;
    } else {
      sol_.totals.creep_x = creep.ksi;
      sol_.totals.creep_y = creep.eta;
      sol_.totals.spin = creepage.spin_rad_per_mm;
    }
    compute_totals(&tang);
  } else {
    compute_totals(nullptr);
  }
  if (problem_.heat.enabled) compute_temperatures();
  for (auto& note : notes_) sol_.warnings.push_back(std::move(note));
}

void CaseSolver::compute_totals(const tangential::TangentialResult* tang) {
  const std::size_t n = grid_.size();
  const double area = grid_.element_area();
  Solution& s = sol_;
  s.px = tang ? tang->px : Field(n, 0.0);
  s.py = tang ? tang->py : Field(n, 0.0);
  s.mu = mu_;
  if (layer_plastic_ && tang != nullptr)
    contact::record_plastic_state(problem_.bodies.layer, plastic_history_, *tang, s);
  if (tang != nullptr) {
    ReportedSlip slip = reported_slip(*tang, s.pn, s.kinematics.dq);
    s.sx = std::move(slip.sx);
    s.sy = std::move(slip.sy);
    plastic_flow_ = std::move(slip.plastic_flow);
  } else {
    s.sx.assign(n, 0.0);
    s.sy.assign(n, 0.0);
  }
  s.state.assign(n, ElementState::Exterior);
  s.ux.assign(n, 0.0);
  s.uy.assign(n, 0.0);
  s.un.assign(n, 0.0);
  // The normal displacements are known unless the pressure is prescribed outright (B=2-4): the
  // exact normal solve gives them, and KPEC/ANALYN pressures (B=5, 6) are scaled to the approach
  // through them (their product deferred on request, SolverOptions::defer_elastic_energy). The
  // energy counts them and Fastsim's own u = L·p: CONTACT's ELAST.EN (docs/decisions.md).
  const bool normal_known = !prescribed_ || (approximate_ && !problem_.solver.defer_elastic_energy);
  const auto normal_displacements = [&] {
    if (normal_un_.size() == n) {
      s.un = std::move(normal_un_);  // the same product of the same pressure, made already
    } else {
      NormalOperators& ops = st_.operators.normal(grid_, s.material, interaction_);
      ops.product->apply(s.pn.data(), s.un.data());
    }
  };
  if (simplified_ && tang != nullptr) {
    s.ux = simplified_ux_;
    s.uy = simplified_uy_;
    if (normal_known) normal_displacements();
  } else if (rough_) {
    // A rough solve only informs the next step (SolverOptions::rough_tolerance): no
    // displacements beyond the normal solve's own, no elastic energy.
    if (normal_un_.size() == n) s.un = std::move(normal_un_);
  } else if (tops_ != nullptr && !coupled_ && normal_un_.size() == n) {
    // Without couplings C is block-diagonal: u_n is the normal solve's, u_t = C_tt·p_t (two
    // transform pairs instead of the 3×3 product's three).
    s.un = std::move(normal_un_);
    const double* in[2] = {s.px.data(), s.py.data()};
    double* out[2] = {s.ux.data(), s.uy.data()};
    tops_->tangential_product().apply(in, out);
  } else if (tops_ != nullptr) {
    const double* in[3] = {s.px.data(), s.py.data(), s.pn.data()};
    double* out[3] = {s.ux.data(), s.uy.data(), s.un.data()};
    tops_->full_product().apply(in, out);
  } else if (normal_known) {
    normal_displacements();
  }

  Totals& t = s.totals;
  Statistics& st = s.statistics;
  st = Statistics{0, 0, 0, 0, 0, st.inorm, st.itang};
  st.npot = static_cast<int>(n);
  double energy = 0.0, power = 0.0;
  t.fn = t.fx = t.fy = t.mz = t.pmax = 0.0;
  for (int iy = 0; iy < grid_.my; ++iy) {
    for (int ix = 0; ix < grid_.mx; ++ix) {
      const std::size_t i = grid_.index(ix, iy);
      t.fn += s.pn[i];
      t.fx += s.px[i];
      t.fy += s.py[i];
      t.mz += grid_.x_centre(ix) * s.py[i] - grid_.y_centre(iy) * s.px[i];
      energy += s.pn[i] * s.un[i] + s.px[i] * s.ux[i] + s.py[i] * s.uy[i];
      if (s.pn[i] <= 0.0) continue;
      ++st.ncon;
      t.pmax = std::max(t.pmax, s.pn[i]);
      if (tang) {
        s.state[i] = tang->state[i];
        // S per step [mm] (Plastic elements: the work of the layer's flow −S).
        power += tang->sx[i] * s.px[i] + tang->sy[i] * s.py[i];
      } else {
        s.state[i] = ElementState::Adhesion;  // CONTACT prints '*' without a tangential problem
      }
      if (s.state[i] == ElementState::Slip)
        ++st.nslip;
      else if (s.state[i] == ElementState::Plastic)
        ++st.nplast;
      else if (s.state[i] == ElementState::Adhesion)
        ++st.nadh;
    }
  }
  t.fn = total_normal_force();
  t.fx *= area;
  t.fy *= area;
  t.mz *= area;
  t.contact_area = st.ncon * area;
  // Not defined with prescribed pressures (u_n unknown).
  t.elastic_energy = !normal_known || rough_ ? 0.0 : elastic_energy_J(energy, area);
  t.frictional_power = 1e-3 * power * area / s.kinematics.dt;  // N·mm/s → W (T=1: J per step)
}

void CaseSolver::compute_temperatures() {
  const bool rolling = problem_.tangential.kind == model::TangentialKind::SteadyRolling;
  post::SurfaceTemperatures t =
      post::surface_temperatures(problem_.heat, sol_, rolling, plastic_flow_);
  sol_.temp1 = std::move(t.temp1);
  sol_.temp2 = std::move(t.temp2);
  sol_.totals.max_temp1 = t.max1;
  sol_.totals.max_temp2 = t.max2;
}

}  // namespace

namespace {

elastic::InteractionPtr interaction_of(geometry::PlanformParts& parts) {
  if (parts.n_parts <= 1) return nullptr;
  auto inter = std::make_shared<elastic::Interaction>();
  inter->n_parts = parts.n_parts;
  inter->part = std::move(parts.part);
  inter->factor = std::move(parts.factor);
  return inter;
}

}  // namespace

Solution PatchSolver::solve(const model::PatchProblem& problem) {
  model::validate(problem);  // every front end's values pass the same check
  Impl& st = *impl_;
  const auto start = std::chrono::steady_clock::now();
  const double built_before = st.operators.build_seconds();
  const model::Bodies& b = problem.bodies;

  Solution sol;
  sol.material = elastic::combine_bodies(b, problem.rolling.velocity_mm_per_s);
  if (b.viscoelastic) sol.viscoelastic_effective = elastic::effective_viscoelastic_constants(b);
  geometry::Discretisation disc = geometry::build_discretisation(problem, sol.material);
  sol.grid = disc.grid;
  sol.hertz = disc.hertz;
  sol.h = std::move(disc.h);
  const double geometry_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  st.operators.begin_case();
  CaseSolver(problem, st, sol, interaction_of(disc.parts)).run();
  sol.solver.setup_seconds = geometry_seconds + (st.operators.build_seconds() - built_before);

  if (!problem.subsurface.empty())
    sol.subsurface = post::compute_subsurface(problem.subsurface, problem.bodies, sol);
  const std::string non_finite = first_non_finite(sol);
  if (!non_finite.empty()) {
    // Never reported as converged, and never the start of the next case.
    sol.solver.converged = false;
    sol.solver.message = "non-finite result (" + non_finite + ")";
    return sol;
  }
  st.latest_pn = sol.pn;
  st.latest_grid = sol.grid;
  st.latest_origin_x = problem.sequence.origin_x_mm;
  st.latest_origin_y = problem.sequence.origin_y_mm;
  // A problem that does not become the previous one leaves the stored state as it was.
  if (problem.sequence.becomes_previous || !st.previous) {
    if (problem.sequence.new_step && st.previous) {
      st.earlier = std::move(st.previous);
      st.earlier_origin_x = st.previous_origin_x;
      st.earlier_origin_y = st.previous_origin_y;
    }
    st.previous = sol;
    st.previous_origin_x = problem.sequence.origin_x_mm;
    st.previous_origin_y = problem.sequence.origin_y_mm;
  }
  return sol;
}

void PatchSolver::complete_elastic_energy(const model::PatchProblem& problem, Solution& s) {
  const model::PressureModel pressure = problem.normal.pressure;
  if (!problem.solver.defer_elastic_energy ||
      (pressure != model::PressureModel::Kpec && pressure != model::PressureModel::Analyn))
    return;
  const std::size_t n = s.grid.size();
  if (s.pn.size() != n) return;
  // The operator the solve used: the same grid, material and IPLAN=4 parts.
  geometry::PlanformParts parts = geometry::planform_parts(s.grid, problem.gap);
  NormalOperators& ops = impl_->operators.normal(s.grid, s.material, interaction_of(parts));
  s.un.assign(n, 0.0);
  ops.product->apply(s.pn.data(), s.un.data());
  const auto at = [](const std::vector<double>& f, std::size_t i) {
    return i < f.size() ? f[i] : 0.0;
  };
  double energy = 0.0;
  for (std::size_t i = 0; i < n; ++i)
    energy += s.pn[i] * s.un[i] + at(s.px, i) * at(s.ux, i) + at(s.py, i) * at(s.uy, i);
  s.totals.elastic_energy = elastic_energy_J(energy, s.grid.element_area());
}

}  // namespace rollcontact
