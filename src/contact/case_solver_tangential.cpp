// CaseSolver, the tangential problem: Fastsim and FaStrip, the exact solvers on a box of the
// grid or the whole grid (with nested-iteration starts), the slip-velocity and temperature
// iterations of velocity- and temperature-dependent friction, and the creepage iteration for
// prescribed forces.

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "contact/case_solver.hpp"
#include "contact/nested_starts.hpp"
#include "contact/temperature_iteration.hpp"
#include "elastic/material.hpp"
#include "post/surface_temperature.hpp"
#include "rollcontact/errors.hpp"
#include "simplified/simplified_solver.hpp"
#include "tangential/kinematics.hpp"
#include "tangential/leading_edge.hpp"

namespace rollcontact::contact {

namespace {

/// The tangential problem is solved on the box around the contact when the box holds at most
/// this share of the grid's elements (contact/contact_box.hpp). Measured on the mbench sweeps
/// (whole processes, CPU time, medians of 11): 0.75 against 0.5 saves 2–9 % (right 10 kN 0.5 mm
/// position 9 %, force 3 %, 50 kN force 6 %: wheel/rail grids hold the contact with a margin
/// that leaves boxes of 0.55–0.7 of the grid); 0.99 measured the same as 0.75.
constexpr double max_contact_box_fraction = 0.75;

}  // namespace

tangential::TangentialResult CaseSolver::solve_simplified(double cksi, double ceta, double cphi) {
  const std::size_t n = grid_.size();
  if (std::none_of(sol_.pn.begin(), sol_.pn.end(), [](double p) { return p > 0.0; })) {
    // An empty contact area carries no tangential tractions (physics.md §9.1), as with the
    // exact solvers: Fastsim's flexibilities would need a patch. It happens to KPEC and ANALYN
    // iterates of the vertical-force iteration at first contact, where the interpenetration is
    // too small for any element's centre to carry pressure.
    tangential::TangentialResult empty = tangential::no_tractions(n);
    empty.converged = true;
    simplified_ux_.assign(n, 0.0);
    simplified_uy_.assign(n, 0.0);
    mu_.clear();
    return empty;
  }
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
  Field mu_memory;
  if (friction_->velocity_dependent()) {
    velocity = {friction_.get(), problem_.friction.memory_distance_mm,
                problem_.friction.memory_floor_speed_mm_s, sol_.kinematics.dt};
    c.velocity = &velocity;
    // The same particles' memory one step earlier (a shift moves none); −1 where a particle
    // enters the contact.
    if (prev_.present &&
        (kind == model::TangentialKind::TransientRolling || kind == model::TangentialKind::Shift))
      mu_memory = simplified::upstream_memory(
          grid_, prev_.mu, prev_.pn, sol_.kinematics.chi,
          kind == model::TangentialKind::Shift ? 0.0 : sol_.kinematics.dq);
    c.mu_prev = mu_memory;
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
  tangential::TangentialResult cold = tangential::no_tractions(n);
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
}  // namespace rollcontact::contact
