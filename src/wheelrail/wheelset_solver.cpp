// WheelsetSolver: profiles → placement → contact search → patch problems → PatchSolver per patch
// → totals, inside the vertical-force iteration when FZ is prescribed (spec/physics.md §13).
// This file: one case at one wheelset height, its placement (left wheels mirrored) and the
// public entry; the iterations around it are in wheelset_iterations.cpp.

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "elastic/material.hpp"
#include "post/subsurface.hpp"
#include "rollcontact/errors.hpp"
#include "wheelrail/friction_variation.hpp"
#include "wheelrail/wheelset_solver_impl.hpp"

namespace rollcontact {

namespace {

/// V=1: the friction at the rail surface inclination of the reference point (of the right-wheel
/// computation), on a conformal patch at each row's inclination (wheelrail-advanced.md §3.3:
/// module 3's friction per row); V=2: at the wheelset's place along the track, S_WS.
void vary_friction(const model::WheelRailProblem& p, PatchSetup& setup) {
  model::Friction& f = setup.problem.friction;
  if (p.friction_variation.along == model::FrictionVariation::Along::TrackPosition) {
    f = wheelrail::friction_at(p.friction_variation, p.motion.s_mm);
    return;
  }
  if (!setup.curved) {
    // The patch's contact angle in the wheel-profile frame (CONTACT: the reference marker's
    // roll there; a turned angle counts as turned): varfric case 4 FSTAT 0.2076 as printed,
    // case 3's tread patch 0.258 at its turned angle.
    f = wheelrail::friction_at(p.friction_variation, setup.frame.delta_rad - p.motion.roll_rad -
                                                         p.wheel_deviation.droll_rad);
    return;
  }
  const std::vector<double>& alpha = setup.curved->alpha;
  f = wheelrail::friction_at(p.friction_variation, alpha.front());
  f.row_coefficients.clear();
  for (double a : alpha)
    f.row_coefficients.push_back(
        wheelrail::friction_at(p.friction_variation, a).static_coefficient);
}

/// The half-space theory assumes small strains: an approach beyond a tenth of the patch's radius
/// sqrt(area/π) (the sweeps of bench/wheelrail_sweep.py, 10 and 50 kN per wheel: at most 4 %)
/// is worth a warning — a wheelset height or load typed wrongly gives forces of giganewtons,
/// reported as converged.
void warn_large_approach(WheelRailSolution& s) {
  constexpr double kLargeStrain = 0.1;
  for (std::size_t k = 0; k < s.patches.size(); ++k) {
    const Totals& t = s.patches[k].solution.totals;
    const double radius = std::sqrt(t.contact_area / std::numbers::pi);
    if (radius > 0.0 && t.pen > kLargeStrain * radius)
      s.warnings.push_back(fmt::format(
          "patch {}: the approach PEN = {:.4g} mm is {:.0f} % of the patch's radius ({:.4g} mm): "
          "far beyond the small strains of the half-space theory (the Manchester benchmark's "
          "patches at up to 50 kN per wheel: at most 4 %); "
          "check Z_WS, FZ and the profiles",
          k + 1, t.pen, 100.0 * t.pen / radius, radius));
  }
}

/// A feature whose results are known to differ from CONTACT's: refused when the problem asks
/// for validated results only, otherwise solved with a warning that says so.
void unvalidated(const model::WheelRailProblem& p, const std::string& what,
                 std::vector<std::string>& warnings) {
  if (p.validated_only)
    throw NotValidatedError("not supported yet: module 1 " + what +
                            " (not validated against CONTACT; solved with a warning on request)");
  const std::string warning = "not validated against CONTACT: " + what;
  if (std::find(warnings.begin(), warnings.end(), warning) == warnings.end())
    warnings.push_back(warning);
}

}  // namespace

WheelRailSolution WheelsetSolver::Impl::solve_at(const model::WheelRailProblem& p, double z_ws,
                                                 bool check_ends, bool normal_only, bool rough,
                                                 GeometryAtHeight* geometry) {
  using Clock = std::chrono::steady_clock;
  const auto since = [](Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
  };
  auto start = Clock::now();
  const PlacedProfiles& prof = *profiles;
  const WheelsetPose pose = wheelrail::pose_of(p, prof, z_ws);
  const bool reuse = geometry != nullptr && geometry->valid && geometry->z_ws_mm == z_ws;
  if (geometry != nullptr && !reuse) {
    geometry->valid = false;
    geometry->search = wheelrail::search_contact(p, prof, samples, z_ws);
    geometry->setups.clear();
    geometry->setup_notes.clear();
  }
  std::optional<SearchResult> own_search;
  if (geometry == nullptr) own_search = wheelrail::search_contact(p, prof, samples, z_ws);
  const SearchResult& search = geometry != nullptr ? geometry->search : *own_search;
  if (check_ends && !search.patches.empty() && search.minimum_at_profile_end)
    throw GeometryError(
        "the deepest interpenetration lies at an end of the rail profile: the wheel is misplaced "
        "on the rail (check Y_WS, the gauge and the profiles' orientation)");
  WheelRailSolution out;
  out.z_ws_mm = z_ws;
  // The wheel's combined constants (the report's MATERIAL CONSTANTS); the inclination
  // correction (C=4) belongs to each patch, whose rows give its table (setup_patch).
  model::Bodies bodies = p.patch.bodies;
  bodies.inclination = {};
  out.material = elastic::combine_bodies(bodies, std::abs(model::rolling_speed_mm_s(p)));
  if (!normal_only) {
    last_solve_turned = false;
    approximate_problems.clear();  // this solve's patches replace the last full solve's
    for (const ContactRegion& r : search.patches) last_solve_turned |= r.angle_turned;
  }
  Vec3 total_tr{}, total_ws{}, moment_tr{}, moment_ws{};
  describe_markers(p, prof, pose, out);
  const bool transient = wheelrail::on_super_grid(p);
  if (transient && !normal_only) pending.clear();
  const bool new_step = !normal_only && new_step_pending;
  if (!normal_only) new_step_pending = false;
  for (std::size_t k = 0; k < search.patches.size(); ++k) {
    const wheelrail::SuperGridBox* before =
        transient && k < previous_contact.size() && previous_contact[k] ? &*previous_contact[k]
                                                                        : nullptr;
    PatchSetup setup;
    std::vector<std::string> notes;
    if (reuse) {
      setup = geometry->setups[k];
      notes = geometry->setup_notes[k];
    } else {
      setup = wheelrail::setup_patch(p, prof, pose, search.patches[k], notes, before);
      if (geometry != nullptr) {
        geometry->setups.push_back(setup);
        geometry->setup_notes.push_back(notes);
      }
    }
    out.warnings.insert(out.warnings.end(), notes.begin(), notes.end());
    if (p.friction_variation.along != model::FrictionVariation::Along::None)
      vary_friction(p, setup);
    // Steady rolling: the previous solve of this patch position (the last iterate, the last
    // case) is the start of the iterations; a normal-only estimate does not replace it.
    model::SequenceLink& link = setup.problem.sequence;
    if (transient) {
      // The previous case's tractions (P = 0, 1) on the super grid, for every trial solve of
      // the case; the case's result becomes the previous one when it is done.
      link.continue_previous = p.patch.sequence.continue_previous && setup.continued;
      link.normal_from_previous = false;
      link.becomes_previous = false;
    } else {
      link.continue_previous =
          setup.problem.tangential.kind == model::TangentialKind::SteadyRolling;
      link.normal_from_previous = link.continue_previous;
      link.becomes_previous = !normal_only;
      link.new_step = new_step;
    }
    if (normal_only) setup.problem.tangential.kind = model::TangentialKind::None;
    if (rough) setup.problem.solver.rough_tolerance = kRoughTolerance;
    // Subsurface stresses of the final patches only (WheelsetSolver::solve), not of every
    // iterate of the force iterations: they cost more than the contact problem itself.
    setup.problem.subsurface.clear();
    // KPEC/ANALYN: the elastic energy of the result that stands only (complete_energies()),
    // not a half-space product in each of the iteration's trial solves.
    setup.problem.solver.defer_elastic_energy = true;
    const model::PressureModel pressure = setup.problem.normal.pressure;
    if (!normal_only &&
        (pressure == model::PressureModel::Kpec || pressure == model::PressureModel::Analyn))
      approximate_problems.push_back(setup.problem);
    geometry_seconds += since(start);
    start = Clock::now();
    if (pressure == model::PressureModel::Analyn && search.patches[k].regions > 1)
      unvalidated(p,
                  "ANALYN (B=6) on a patch combined from several interpenetration regions "
                  "(mbench_a22_kpec case 6 differs in MN)",
                  out.warnings);
    Solution sol = solver_for(k).solve(setup.problem);
    patch_solve_seconds += since(start);
    patch_setup_seconds += sol.solver.setup_seconds;
    start = Clock::now();
    if (!sol.solver.converged) {
      out.converged = false;
      out.message = fmt::format("patch {}: {}", k + 1, sol.solver.message);
    }
    if (transient && !normal_only)
      pending.push_back({sol, setup.origin_x_mm, setup.origin_y_mm, contact_box(sol, setup)});
    WheelRailPatch w = describe_patch(p, prof, pose, setup, std::move(sol));
    w.friction = setup.problem.friction;
    w.conformal.row_friction = w.friction.row_coefficients;
    total_tr = total_tr + Vec3{w.force_tr.x, w.force_tr.y, w.force_tr.z};
    total_ws = total_ws + Vec3{w.force_ws.x, w.force_ws.y, w.force_ws.z};
    moment_tr = moment_tr + Vec3{w.moment_tr.x, w.moment_tr.y, w.moment_tr.z};
    moment_ws = moment_ws + Vec3{w.moment_ws.x, w.moment_ws.y, w.moment_ws.z};
    out.patches.push_back(std::move(w));
  }
  if (geometry != nullptr && !reuse) {
    geometry->valid = true;
    geometry->z_ws_mm = z_ws;
  }
  out.force_tr = to_public(total_tr);
  out.force_ws = to_public(total_ws);
  out.moment_tr = to_public(moment_tr);
  out.moment_ws = to_public(moment_ws);
  geometry_seconds += since(start);
  return out;
}

void WheelsetSolver::Impl::commit_transient() {
  // Patch positions of this case become the previous ones; the others end their sequence.
  for (std::size_t k = 0; k < std::max(pending.size(), previous_contact.size()); ++k) {
    PatchSolver& solver = solver_for(k);
    if (k < pending.size() && pending[k].contact.x_lo <= pending[k].contact.x_hi) {
      solver.set_previous(std::move(pending[k].solution), pending[k].origin_x, pending[k].origin_y);
      if (previous_contact.size() <= k) previous_contact.resize(k + 1);
      previous_contact[k] = pending[k].contact;
    } else {
      solver.reset_sequence();
      if (k < previous_contact.size()) previous_contact[k].reset();
    }
  }
  pending.clear();
}

WheelsetSolver::WheelsetSolver(SolveOptions options) : impl_(std::make_unique<Impl>()) {
  impl_->options = options;
}
WheelsetSolver::~WheelsetSolver() = default;
WheelsetSolver::WheelsetSolver(WheelsetSolver&&) noexcept = default;
WheelsetSolver& WheelsetSolver::operator=(WheelsetSolver&&) noexcept = default;

WheelRailSolution WheelsetSolver::Impl::solve_placed(const model::WheelRailProblem& problem,
                                                     const VerticalOptions& v) {
  const model::WheelRailProblem p = as_right_side(problem);
  const auto start = std::chrono::steady_clock::now();
  prepare(p);
  geometry_seconds +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  WheelRailSolution result = solve_case(p, v);
  if (problem.side == model::WheelSide::Left) mirror_to_left(result);
  return result;
}

WheelRailSolution WheelsetSolver::Impl::solve_case(const model::WheelRailProblem& p,
                                                   const VerticalOptions& v) {
  WheelRailSolution result;
  const bool rail_spring =
      p.vertical == model::VerticalLoading::Position && v.rail_kz_N_per_mm > 0.0;
  if (p.vertical == model::VerticalLoading::Position && !rail_spring) {
    result = solve_at(p, p.motion.z_mm, p.first_of_sequence);
  } else {
    wheelrail::VerticalForceSettings st;
    st.target_N = p.motion.fz_N;
    st.tolerance = v.tolerance > 0.0 ? v.tolerance : p.patch.solver.tolerance;
    st.max_iterations = p.patch.solver.max_newton_iterations;
    if (rail_spring) {
      // F_z(z_shift) − kz·(z_ws − z_shift) + fz = 0 for the wheel height z_shift over the
      // undeflected rail; the rail then sinks by δz = z_ws − z_shift under the wheel at z_ws.
      st.spring_N_per_mm = v.rail_kz_N_per_mm;
      st.target_N = v.rail_kz_N_per_mm * p.motion.z_mm - v.rail_fz_N;
    }
    result = solve_for_height(p, st);
    if (rail_spring) {
      // The same geometry, shifted by δz: solved once more in its true place (the outputs hold
      // positions in the track), starting from the iteration's last tractions.
      const double dz = p.motion.z_mm - result.z_ws_mm;
      model::WheelRailProblem q = p;
      q.rail_state.dz_mm += dz;
      prepare(q);
      WheelRailSolution placed = solve_at(q, p.motion.z_mm, false);
      placed.trace = std::move(result.trace);
      placed.warnings.insert(placed.warnings.begin(), result.warnings.begin(),
                             result.warnings.end());
      if (!result.converged) {
        placed.converged = false;
        placed.message = result.message;
      }
      result = std::move(placed);
      result.rail_deflection.dz_mm = dz;
    }
  }
  complete_energies(result);
  // Judged on the state that stands: an iterate of the vertical-force iteration may pass through
  // such a state (mbench_a22_kpec c2 does where the deepest point changes lobes) and leave it.
  if (kpec_second_lobe(p, result))
    unvalidated(p,
                "KPEC (B=5) where the gap interpenetrates beyond the equivalent ellipse (a "
                "second lobe; mbench_a22_kpec case 1 differs)",
                result.warnings);
  return result;
}

bool kpec_second_lobe(const model::WheelRailProblem& p, const WheelRailSolution& s) {
  return p.patch.normal.pressure == model::PressureModel::Kpec &&
         std::any_of(s.patches.begin(), s.patches.end(), [](const WheelRailPatch& w) {
           return w.solution.solver.kpec_rows_beyond_interpenetration > 0;
         });
}

namespace {

/// A roller must have a radius, and an internal one must be wider than the wheel inside it.
void check_roller(const model::WheelRailProblem& p) {
  if (!p.roller.enabled) return;
  const double r = p.roller.nominal_radius_mm;
  if (!std::isfinite(r) || std::abs(r) < 1.0)
    throw ProblemError(fmt::format(
        "roller rig: the roller radius NOMRADR = {:g} mm must be at least 1 mm in magnitude", r));
  if (!p.rail.slices.u.empty())
    throw NotSupportedError(
        "not supported yet: module 1 rail slices on a roller rig (a roller profile varying "
        "around the roller)");
  if (r < 0.0 && -r <= p.wheelset.nominal_radius_mm)
    throw ProblemError(fmt::format(
        "roller rig: an internal roller (NOMRADR = {:g} mm < 0) must be wider than the wheel "
        "inside it (NOMRADW = {:g} mm)",
        r, p.wheelset.nominal_radius_mm));
}

}  // namespace

WheelRailSolution WheelsetSolver::solve(const model::WheelRailProblem& problem) {
  check_roller(problem);
  std::vector<std::string> before;  // warnings known before the solve
  if (!problem.wheel.slices.slices.empty())
    unvalidated(problem,
                "variable wheel profiles (wheel slices: where the contact meets a wheel flat's "
                "edges its location differs from CONTACT's by up to 0.08 mm; wheelflat: 15 of "
                "26 cases beyond the 5e-3 mm tolerance)",
                before);
  impl_->geometry_seconds = impl_->patch_solve_seconds = impl_->patch_setup_seconds = 0.0;
  impl_->last_solve_turned = false;
  if (problem.vertical == model::VerticalLoading::Force && !(problem.motion.fz_N >= 1e-9)) {
    // CONTACT's early return (spec/wheelrail-advanced.md §6.3): a wheel without load is not in
    // contact; z_ws = 0 and no forces, nothing solved. An MBS code lifting a wheel gets this.
    WheelRailSolution none;
    none.vpitch_rad_s = problem.motion.vpitch_rad_s;
    if (wheelrail::on_super_grid(problem)) {  // no contact: the patches' sequences end
      impl_->pending.clear();
      impl_->commit_transient();
    }
    none.warnings.push_back(fmt::format(
        "FZ = {:g} N < 1e-9 N: no contact computed (z_ws = 0, zero forces)", problem.motion.fz_N));
    return none;
  }
  impl_->new_step_pending = true;
  WheelRailSolution result = problem.longitudinal != model::LongitudinalLoading::PitchVelocity
                                 ? impl_->solve_pitch_velocity(problem)
                             : problem.massless_rail.enabled ? impl_->solve_massless_rail(problem)
                                                             : impl_->solve_placed(problem, {});
  if (wheelrail::on_super_grid(problem)) impl_->commit_transient();
  if (impl_->last_solve_turned)
    unvalidated(problem,
                "patches between D_SEP and D_TURN (their reference angles turned towards each "
                "other; in mbench_a22_varfric case 3 the forces agree, the turned angles are "
                "3e-4 rad off, as they move by 11 rad per mm of z_ws)",
                result.warnings);
  result.warnings.insert(result.warnings.begin(), before.begin(), before.end());
  warn_large_approach(result);
  if (problem.longitudinal == model::LongitudinalLoading::PitchVelocity)
    result.vpitch_rad_s = problem.motion.vpitch_rad_s;
  if (!problem.patch.subsurface.empty()) {
    const auto start = std::chrono::steady_clock::now();
    for (WheelRailPatch& w : result.patches)
      w.solution.subsurface =
          post::compute_subsurface(problem.patch.subsurface, problem.patch.bodies, w.solution);
    impl_->patch_solve_seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  result.geometry_seconds = impl_->geometry_seconds;
  result.patch_solve_seconds = impl_->patch_solve_seconds;
  result.patch_setup_seconds = impl_->patch_setup_seconds;
  return result;
}

}  // namespace rollcontact
