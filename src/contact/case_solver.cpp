// CaseSolver: the sequence (the previous case on this grid), the Panagiotopoulos loop of
// normal and tangential problems, and the totals.

#include "contact/case_solver.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "elastic/material.hpp"
#include "post/surface_temperature.hpp"
#include "rollcontact/errors.hpp"
#include "tangential/kinematics.hpp"

namespace rollcontact::contact {

namespace {

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

}  // namespace

/// The elastic energy ½Σ(p·u)·δxδy [J] from the sum Σ(p_n u_n + p_x u_x + p_y u_y) [N/mm] over
/// the elements and their area [mm²] (CONTACT's ELAST.EN; N·mm → J).
double elastic_energy_J(double sum_p_dot_u, double element_area_mm2) {
  return 0.5e-3 * sum_p_dot_u * element_area_mm2;
}

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
  // What this case reads beside the pressures: tractions as a start or the previous step,
  // displacements of the previous step (transient Fastsim, shifts), slips for the slip speed of
  // velocity-dependent friction.
  FieldsToMap what;
  what.tractions = kind != model::TangentialKind::None;
  what.displacements =
      kind == model::TangentialKind::TransientRolling || kind == model::TangentialKind::Shift;
  what.slips = what.tractions && friction_->velocity_dependent();
  prev_ = map_previous(prev, grid_, problem_.sequence.origin_x_mm - st_.previous_origin_x,
                       problem_.sequence.origin_y_mm - st_.previous_origin_y, what);
  // Steady rolling remembers the previous solution only as a start (transient rolling and
  // shifts as the previous time step, which must stay what it was).
  if (problem_.sequence.new_step && prev != nullptr && st_.earlier &&
      kind == model::TangentialKind::SteadyRolling)
    extrapolate_start(
        prev_,
        map_previous(&*st_.earlier, grid_, problem_.sequence.origin_x_mm - st_.earlier_origin_x,
                     problem_.sequence.origin_y_mm - st_.earlier_origin_y, what));
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
}  // namespace rollcontact::contact
