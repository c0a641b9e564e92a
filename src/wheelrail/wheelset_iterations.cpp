// The iterations of a wheel/rail case around complete solves (spec/physics.md §13.7,
// spec/wheelrail-advanced.md §2, spec-additions §A6): the wheelset height for a prescribed
// vertical force, the massless rail's deflections, and the pitch velocity for a prescribed
// longitudinal force or pitch moment.

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>

#include "geometry/hertz.hpp"
#include "rollcontact/errors.hpp"
#include "wheelrail/massless_rail.hpp"
#include "wheelrail/pitch_velocity.hpp"
#include "wheelrail/wheelset_solver_impl.hpp"

namespace rollcontact {

void WheelsetSolver::Impl::remember_approach(double approach_mm, double fz_N) {
  if (previous_approaches.size() == 2) previous_approaches.erase(previous_approaches.begin());
  previous_approaches.push_back({approach_mm, fz_N});
}

std::optional<double> WheelsetSolver::Impl::approach_from_previous_cases(double fz_N) const {
  // Hertz: approach ∝ F^(2/3) for a patch of fixed curvatures.
  const auto scaled = [fz_N](const ApproachAtForce& a) -> std::optional<double> {
    if (!(a.approach_mm > 0.0 && a.fz_N > 0.0 && fz_N > 0.0)) return std::nullopt;
    if (fz_N > 5.0 * a.fz_N || a.fz_N > 5.0 * fz_N) return std::nullopt;
    return a.approach_mm * std::cbrt((fz_N / a.fz_N) * (fz_N / a.fz_N));
  };
  if (previous_approaches.empty()) return std::nullopt;
  const std::optional<double> last = scaled(previous_approaches.back());
  if (!last || previous_approaches.size() < 2) return last;
  const std::optional<double> before = scaled(previous_approaches.front());
  if (!before) return last;
  // Along a sweep the approach drifts as the contact moves over the profiles (0.016 -> 0.020
  // mm over the first 20 cases of the left wheel): extrapolated linearly, but by no more
  // than a quarter of it, so that a jump (the contact moving onto the flange) is not repeated.
  return *last + std::clamp(*last - *before, -0.25 * *last, 0.25 * *last);
}

WheelRailSolution WheelsetSolver::Impl::solve_for_height(
    const model::WheelRailProblem& p, const wheelrail::VerticalForceSettings& st) {
  WheelRailSolution result;
  // Iterate 0: geometry only, at z_ws = 0: contact starts at the smallest gap.
  const SearchResult s0 = wheelrail::search_contact(p, *profiles, samples, 0.0);
  if (!(s0.min_gap_mm < 1e20)) {
    result.converged = false;
    result.message = "the wheel and rail profiles do not overlap laterally: no contact possible";
    return result;
  }
  const double z0 = s0.min_gap_mm;
  // The approach of the previous cases counts from the first contact between the gap's samples:
  // from the smallest sample it jumps with where the samples fall (±1.5 µm on the benchmark's
  // flange contacts, F_z ±800 N at the first guess).
  const double contact_start = s0.min_gap_between_samples_mm;
  const double k = st.spring_N_per_mm;
  if (k > 0.0 && k * z0 - st.target_N >= 0.0) {
    // The rail's spring and load lift it clear of the wheel: no contact, F_z = 0.
    return solve_at(p, st.target_N / k, p.first_of_sequence);
  }
  // Iterate 1: Hertz with the wheel's rolling curvature and the gap's lateral curvature.
  const double a1 = wheelrail::rolling_curvature_per_mm(p);
  const double b1 = std::max(s0.curvature_at_min, 1e-4);
  const double cos_min = std::max(0.5, std::cos(s0.delta_at_min_rad));
  const double hertz_force = k > 0.0 ? 1e4 : p.motion.fz_N;
  double pen = 0.0;
  try {
    pen = geometry::hertz_from_curvatures(a1, b1, geometry::HertzLoad::Force, hertz_force,
                                          contact_modulus(p.patch.bodies))
              .pen;
  } catch (const Error&) {
    pen = 0.01;
  }
  wheelrail::VerticalForceSettings settings = st;
  settings.continuous_force = p.patch.normal.pressure == model::PressureModel::ExactHalfSpace;
  // Never from loss of contact (release 25.1, wheelrail-advanced.md §6.3): at least 1 µm in.
  double z1 = std::max(z0 + pen / cos_min, z0 + 1e-3);
  // From the previous cases' approaches beyond first contact, each scaled by Hertz's F^(2/3)
  // to this force and extrapolated from the last two (wheelrail-advanced.md §6.3: not when the
  // force changed by more than a factor 5): with I ≥ 1, and with I = 0 in a case that continues
  // a sequence — a start, not the answer: where F_z(z) is continuous the answer is the same
  // within the tolerance. KPEC's and ANALYN's F_z jumps where their equivalent ellipse changes,
  // and where the answer is a bracket around such a jump the start decides its side: a KPEC
  // state with a second lobe is therefore not remembered (below), so that the case after it
  // starts from Hertz as CONTACT's does (docs/decisions.md).
  if (const std::optional<double> a = approach_from_previous_cases(st.target_N);
      a && k <= 0.0 && (p.estimate_from_previous_case || !p.first_of_sequence))
    z1 = std::max(contact_start + *a, z0 + 1e-3);
  if (k > 0.0) {
    // The massless rail with z_ws prescribed: the Hertz force C·pen^1.5 (C from 10 kN) against
    // the spring, C·((z − z0)·cos)^1.5 + k·z = target, by bisection between the start of
    // contact and the height where the spring alone balances.
    const double c = 1e4 / std::pow(pen, 1.5);
    auto g = [&](double z) { return c * std::pow((z - z0) * cos_min, 1.5) + k * z - st.target_N; };
    double lo = z0, hi = st.target_N / k;
    for (int it = 0; it < 100 && hi - lo > 1e-12; ++it)
      (g(0.5 * (lo + hi)) < 0.0 ? lo : hi) = 0.5 * (lo + hi);
    z1 = std::max(0.5 * (lo + hi), z0 + 1e-3);
    if (settings.force_scale_N <= 0.0)
      settings.force_scale_N = std::max(c * std::pow((z1 - z0) * cos_min, 1.5), 1.0);
  }
  bool first = p.first_of_sequence;
  // A conformal patch's F_z per newton of its pressure's normal force that its tangential
  // tractions add (their BAR turning), from the last full solve; NaN for planar patches.
  std::vector<double> tangential_share;
  bool rough = false;
  // The full solve at a converged normal estimate's height takes that estimate's geometry.
  GeometryAtHeight geometry;
  auto full_at = [&](double z) {
    result = solve_at(p, z, first, false, rough, &geometry);
    first = false;
    wheelrail::HeightSample h;
    h.z_mm = z;
    h.fz_N = result.force_tr.z;
    tangential_share.clear();
    for (const WheelRailPatch& w : result.patches) {
      const wheelrail::PlanarForces f = wheelrail::planar_forces(w);
      h.patches.push_back(
          {w.solution.totals.pen, w.contact_angle_rad, f.fn, f.fs, w.solution.statistics.ncon});
      double share = std::numeric_limits<double>::quiet_NaN();
      if (w.conformal.active) {
        const wheelrail::PlanarForces n = wheelrail::pressure_part(w);
        const double c = std::cos(w.contact_angle_rad), s = std::sin(w.contact_angle_rad);
        share = n.fn > 0.0 ? ((f.fn - n.fn) * c + (f.fs - n.fs) * s) / n.fn : 0.0;
      }
      tangential_share.push_back(share);
    }
    return h;
  };
  // F_z = Σ F_n cos δ + F_s sin δ with F_s = fs_ratio·F_n from the last full solve; for a
  // conformal patch the normal solve's own F_z (its pressure's BAR forces) plus the tangential
  // share, so that the estimate aims where the full solve lands.
  auto normal_at = [&](double z, const std::vector<double>& fs_ratio) {
    const WheelRailSolution r = solve_at(p, z, false, true, false, &geometry);
    wheelrail::HeightSample h;
    h.z_mm = z;
    for (std::size_t i = 0; i < r.patches.size(); ++i) {
      const WheelRailPatch& w = r.patches[i];
      const double fn = wheelrail::planar_forces(w).fn, delta = w.contact_angle_rad;
      const double fs = (i < fs_ratio.size() ? fs_ratio[i] : 0.0) * fn;
      const double share = i < tangential_share.size() ? tangential_share[i]
                                                       : std::numeric_limits<double>::quiet_NaN();
      if (w.conformal.active && !std::isnan(share))
        h.fz_N += w.force_tr.z + share * fn;
      else
        h.fz_N += fn * std::cos(delta) + fs * std::sin(delta);
      h.patches.push_back({w.solution.totals.pen, delta, fn, fs, w.solution.statistics.ncon});
    }
    return h;
  };
  const std::function<wheelrail::HeightSample(double)> rough_at = [&](double z) {
    rough = true;
    wheelrail::HeightSample h = full_at(z);
    rough = false;
    return h;
  };
  // The split iteration's normal-only estimates save the tangential solves of the exact theory.
  // With Fastsim or FaStrip (M=2, 3, 5) the tangential part costs less than the patch set-up
  // that every estimate repeats, and the estimates' tangential share lags the full solves':
  // full solves only (KPEC sweeps: 746 → 437 iterates per 101 cases, docs/decisions.md).
  const bool cheap_tangential =
      p.patch.bodies.compliance != model::TangentialCompliance::ExactHalfSpace;
  // Viscoelastic bodies (M=1): the normal problem itself depends on the rolling (the delayed
  // response is integrated along the rolling path), so there is no normal-only estimate.
  const bool rolling_normal_problem = p.patch.bodies.viscoelastic;
  const wheelrail::VerticalForceResult vf =
      p.patch.tangential.kind == model::TangentialKind::None || cheap_tangential ||
              rolling_normal_problem
          ? wheelrail::solve_vertical_force(settings, z0, z1, full_at)
          : wheelrail::solve_vertical_force_split(settings, z0, z1, full_at, normal_at, &rough_at);
  result.trace = vf.trace;
  if (vf.converged && k <= 0.0 && !kpec_second_lobe(p, result))
    remember_approach(vf.z_mm - contact_start, st.target_N);
  else
    previous_approaches.clear();
  if (!vf.converged) {
    result.converged = false;
    result.message = vf.message;
  } else if (!vf.message.empty()) {
    result.warnings.push_back(vf.message);
  }
  return result;
}

WheelRailSolution WheelsetSolver::Impl::solve_massless_rail(
    const model::WheelRailProblem& problem) {
  const model::MasslessRail& m = problem.massless_rail;
  const bool force_given = problem.vertical == model::VerticalLoading::Force;
  if (problem.patch.tangential.kind == model::TangentialKind::None)
    throw ProblemError("the massless rail (F=3) requires a tangential problem (T >= 1)");
  if (!force_given && !(m.kz_N_per_mm >= 1e-10))
    throw ProblemError(
        "the massless rail (F=3) with z_ws prescribed (N=0) needs a vertical equation: "
        "KZRAIL >= 1e-10 N/mm (a rail that rises under load has no stable height), or "
        "prescribe FZ (N=1)");
  RailDeflection d;
  d.active = true;
  d.ky_N_per_mm = m.ky_N_per_mm;
  d.fy_N = m.fy_N;
  d.kz_N_per_mm = m.kz_N_per_mm;
  d.fz_N = m.fz_N;
  double dz = 0.0;  // N=1: known directly from the prescribed force
  if (force_given) {
    if (std::abs(m.kz_N_per_mm) > 1e-10)
      dz = (problem.motion.fz_N + m.fz_N) / m.kz_N_per_mm;
    else
      d.fz_N = -problem.motion.fz_N;  // a rail without vertical spring carries FZ itself
  }
  VerticalOptions v;
  if (!force_given) {
    v.rail_kz_N_per_mm = m.kz_N_per_mm;
    v.rail_fz_N = m.fz_N;
  }
  const double eps = problem.patch.solver.tolerance;
  model::WheelRailProblem q = problem;
  q.massless_rail.enabled = false;
  q.rail_state.dz_mm = problem.rail_state.dz_mm + dz;
  WheelRailSolution result;
  int solves = 0;
  bool last_loose = false;
  auto residual = [&](double dy) {
    q.rail_state.dy_mm = problem.rail_state.dy_mm + dy;
    // Looser vertical solves while δy is still far off (spec §2.4); the profile-end check of
    // the first case applies to its first solve, as in the vertical iteration.
    v.tolerance = solves < 2 ? std::max(1e-4, 10.0 * eps) : eps;
    last_loose = v.tolerance > eps;
    q.first_of_sequence = problem.first_of_sequence && solves == 0;
    ++solves;
    result = solve_placed(q, v);
    return result.force_tr.y - m.ky_N_per_mm * dy + m.fy_N;
  };
  wheelrail::LateralRailSettings st;
  st.stiffness_N_per_mm = m.ky_N_per_mm;
  st.first_step_mm = m.dystep0_mm > 0.0 ? m.dystep0_mm : 1.0;
  st.tolerance_N = std::max(1e-6, eps * std::abs(m.fy_N));
  st.tolerance_mm = eps;
  st.max_iterations = problem.patch.solver.max_newton_iterations;
  wheelrail::LateralRailResult lateral = wheelrail::solve_lateral_rail(st, residual);
  if (last_loose) {
    // Done within the first two iterates (a stiff rail moves less than EPS): the result stands
    // with the vertical force to EPS, like any other case.
    solves = 2;
    lateral.residual_N = residual(lateral.dy_mm);
  }
  d.dy_mm = lateral.dy_mm;
  d.dz_mm = force_given ? dz : result.rail_deflection.dz_mm;
  d.residual_y_N = lateral.residual_N;
  d.residual_z_N = result.force_tr.z - d.kz_N_per_mm * d.dz_mm + d.fz_N;
  d.iterations = lateral.iterations;
  result.rail_deflection = d;
  if (!lateral.converged) {
    result.converged = false;
    result.message = lateral.message;
  } else if (!lateral.message.empty()) {
    result.warnings.push_back(lateral.message);
  }
  return result;
}

WheelRailSolution WheelsetSolver::Impl::solve_pitch_velocity(
    const model::WheelRailProblem& problem) {
  const bool moment = problem.longitudinal == model::LongitudinalLoading::Moment;
  const std::string what = moment ? "a prescribed pitch moment MY_WS (F=2)"
                                  : "a prescribed longitudinal force FX_WS (F=1)";
  if (problem.vertical != model::VerticalLoading::Force)
    throw ProblemError(what + " requires the vertical force prescribed (N=1)");
  if (problem.massless_rail.enabled)
    throw ProblemError(what + " and the massless rail (F=3) exclude each other");
  if (problem.patch.tangential.kind == model::TangentialKind::None)
    throw ProblemError(what + " requires a tangential problem");
  const double v = model::rolling_speed_mm_s(problem);
  if (!(std::abs(v) > 0.0))
    throw ProblemError(what + " requires a rolling velocity VS (roller rig: RPITCH)");
  const double eps = problem.patch.solver.tolerance;
  const double mu = std::max(problem.patch.friction.static_coefficient, 1e-3);
  model::WheelRailProblem q = problem;
  q.longitudinal = model::LongitudinalLoading::PitchVelocity;
  WheelRailSolution result;
  int solves = 0;
  auto solve = [&](double vpitch, double inner_tolerance) {
    q.motion.vpitch_rad_s = vpitch;
    q.first_of_sequence = problem.first_of_sequence && solves == 0;
    ++solves;
    VerticalOptions vo;
    vo.tolerance = inner_tolerance;
    result = solve_placed(q, vo);
    wheelrail::PitchVelocitySample sample;
    sample.usable = result.converged && std::abs(result.force_tr.z) > 0.0;
    // F=2: the moment about the axle over the wheel's radius, M_y/(r·F_z) ≈ F_x/F_z, so the
    // same saturation, slope and tolerances serve.
    const double along =
        moment ? axle_pitch_moment(result) / problem.wheelset.nominal_radius_mm : result.force_ws.x;
    sample.ratio = sample.usable ? along / result.force_tr.z : 0.0;
    sample.vertical_error = std::abs(result.force_tr.z / problem.motion.fz_N - 1.0);
    return sample;
  };
  // Start: the given VPITCH, else free rolling on the nominal radius (CONTACT starts from the
  // rolling radius at the initial contact point; linear theory's first step corrects either).
  const double nominal = problem.wheelset.nominal_radius_mm;
  const double start =
      std::abs(problem.motion.vpitch_rad_s) > 0.0 ? problem.motion.vpitch_rad_s : -v / nominal;
  wheelrail::PitchVelocitySettings st;
  st.start_rad_s = start;
  st.target = (moment ? problem.motion.my_ws_Nmm / problem.wheelset.nominal_radius_mm
                      : problem.motion.fx_ws_N) /
              problem.motion.fz_N;
  st.saturation = mu;
  st.tolerance = eps * mu;
  st.vertical_tolerance = eps;
  st.max_jump = mu;
  // At most a creepage of 1 % per step: beyond it a patch slides wholly.
  st.max_step_rad_s = 0.01 * std::abs(v) / nominal;
  st.max_iterations = problem.patch.solver.max_newton_iterations;
  // The first solve to EPS; linear theory's slope needs its patches.
  const wheelrail::PitchVelocitySample first = solve(start, eps);
  st.slope_s_per_rad = linear_pitch_slope(result, v);
  if (!(st.slope_s_per_rad > 0.0)) st.slope_s_per_rad = nominal / std::abs(v);  // no contact
  const wheelrail::PitchVelocityResult it = wheelrail::solve_pitch_velocity(st, first, solve);
  result.vpitch_rad_s = it.vpitch_rad_s;
  result.pitch_iterations = it.iterations;
  if (!it.converged) {
    result.converged = false;
    if (result.message.empty()) result.message = it.message;
  }
  return result;
}

}  // namespace rollcontact
