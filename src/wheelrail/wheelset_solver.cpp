// WheelsetSolver: profiles → placement → contact search → patch problems → PatchSolver per patch
// → totals, inside the vertical-force iteration when FZ is prescribed (spec/physics.md §13).

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <optional>

#include "geometry/hertz.hpp"
#include "post/subsurface.hpp"
#include "rollcontact/errors.hpp"
#include "rollcontact/wheelrail.hpp"
#include "simplified/flexibility.hpp"
#include "simplified/kalker_coefficients.hpp"
#include "wheelrail/contact_search.hpp"
#include "wheelrail/friction_variation.hpp"
#include "wheelrail/massless_rail.hpp"
#include "wheelrail/patch_setup.hpp"
#include "wheelrail/pitch_velocity.hpp"
#include "wheelrail/placed_profiles.hpp"
#include "wheelrail/vertical_force.hpp"
#include "wheelrail/wheelset_pose.hpp"

namespace rollcontact {

using wheelrail::ContactRegion;
using wheelrail::PatchSetup;
using wheelrail::PlacedProfiles;
using wheelrail::SearchResult;
using wheelrail::Vec3;
using wheelrail::WheelsetPose;

namespace {

/// How the vertical equation of one solve is posed (the massless rail changes it).
struct VerticalOptions {
  double tolerance = -1.0;  ///< of the vertical iteration; <= 0: EPS of the case
  /// N=0 with the massless rail: the rail's vertical spring kz [N/mm] and load fz [N]. The wheel
  /// height over the undeflected rail is iterated and the rail deflection δz follows. 0: none.
  double rail_kz_N_per_mm = 0.0, rail_fz_N = 0.0;
};

}  // namespace

struct WheelsetSolver::Impl {
  SolveOptions options;
  std::optional<PlacedProfiles> profiles;
  std::vector<PatchSolver> patch_solvers;  ///< one per patch position (cached operators)

  const PlacedProfiles& profiles_for(const model::WheelRailProblem& p) {
    if (!profiles || !profiles->same_curves(p)) {
      profiles.emplace(p);
      ++profiles_generation;
    }
    profiles->place(p);
    return *profiles;
  }

  PatchSolver& solver_for(std::size_t k) {
    while (patch_solvers.size() <= k) patch_solvers.emplace_back(options);
    return patch_solvers[k];
  }

  /// Places the profiles and samples the gap for the case (everything independent of z_ws);
  /// the rail samples are kept while the rail placement and DS stay the same.
  void prepare(const model::WheelRailProblem& p) {
    const PlacedProfiles& prof = profiles_for(p);
    const RailKey key{profiles_generation, p.search.ds_mm,       prof.rail_y_mm(),
                      prof.rail_z_mm(),    prof.rail_roll_rad(), prof.rail_u_mm()};
    if (!(key == rail_key) || samples.rail_z.empty()) {
      samples = wheelrail::sample_rail(p, prof);
      rail_key = key;
    }
    wheelrail::sample_wheel(p, prof, wheelrail::pose_of(p, prof, 0.0), samples);
  }

  /// Everything at one wheelset height (after prepare()); `normal_only`: the patches' normal
  /// problems alone (an estimate inside the vertical-force iteration).
  WheelRailSolution solve_at(const model::WheelRailProblem& p, double z_ws, bool check_ends,
                             bool normal_only = false);

  /// One case in the case's own frame: mirrored for a left wheel, placed, solved, mirrored back.
  WheelRailSolution solve_placed(const model::WheelRailProblem& problem, const VerticalOptions& v);
  /// One case as a right wheel (left inputs already mirrored), after prepare().
  WheelRailSolution solve_case(const model::WheelRailProblem& p, const VerticalOptions& v);
  /// The wheelset height for the vertical equation of `st` (N=1, or N=0 with the massless rail).
  WheelRailSolution solve_for_height(const model::WheelRailProblem& p,
                                     const wheelrail::VerticalForceSettings& st);
  /// F=3: the rail deflections around complete solves (spec/wheelrail-advanced.md §2).
  WheelRailSolution solve_massless_rail(const model::WheelRailProblem& problem);
  /// F=1: the pitch velocity for the prescribed FX_WS around complete N=1 solves
  /// (spec-additions §A6).
  WheelRailSolution solve_pitch_velocity(const model::WheelRailProblem& problem);

  wheelrail::GapSamples samples;  ///< of the current case

  /// What the rail samples depend on.
  struct RailKey {
    unsigned long generation = 0;  ///< of the profile curves
    double ds = 0.0, rail_y = 0.0, rail_z = 0.0, rail_roll = 0.0;
    double rail_u = 0.0;  ///< a sliced rail's section (S_WS)
    bool operator==(const RailKey&) const = default;
  };
  RailKey rail_key;
  unsigned long profiles_generation = 0;  ///< counts the profile curves made

  /// Transient sequences (T=1, 2; spec/wheelrail-advanced.md §5.2–5.3): what the last complete
  /// solve of a case would leave for the next case, per patch position — committed when the
  /// case is done (commit_transient), since the force iterations' trial solves must all start
  /// from the previous case.
  struct PatchState {
    Solution solution;
    double origin_x = 0.0, origin_y = 0.0;  ///< the grid's origin on the super grid [mm]
    wheelrail::SuperGridBox contact;        ///< its contact area on the super grid
  };
  std::vector<PatchState> pending;
  /// The previous case's contact area per patch position (super grid): the patches of the next
  /// case that overlap it continue its sequence.
  std::vector<std::optional<wheelrail::SuperGridBox>> previous_contact;
  void commit_transient();

  /// The last complete solve had patches whose angles the D_TURN rule turned (validated_only
  /// refuses its result: docs/decisions.md, "Variable friction (V=1, 2) and the D_TURN rule").
  bool last_solve_turned = false;
  /// The last converged vertical-force iteration: its approach z_ws − z_first-contact [mm] and
  /// its force [N] (the start of the next with I ≥ 1).
  double last_approach_mm = 0.0, last_fz_N = 0.0;

  /// Wall time of the current case [s] (see WheelRailSolution).
  double geometry_seconds = 0.0, patch_solve_seconds = 0.0;
};

namespace {

Vector3 to_public(Vec3 v) {
  return {v.x, v.y, v.z};
}

/// Combined contact modulus E* = G/(1 − ν) of the two bodies (physics.md §3.1).
double contact_modulus(const model::Bodies& b) {
  const double inv_g =
      0.5 * (1.0 / b.body1.shear_modulus_N_mm2 + 1.0 / b.body2.shear_modulus_N_mm2);
  const double nu_g = 0.5 * (b.body1.poisson_ratio / b.body1.shear_modulus_N_mm2 +
                             b.body2.poisson_ratio / b.body2.shear_modulus_N_mm2);
  const double g = 1.0 / inv_g, nu = nu_g * g;
  return g / (1.0 - nu);
}

/// Centre of pressure of a solution in its own grid coordinates [mm] (0, 0 without pressure).
std::pair<double, double> pressure_centre(const Solution& s) {
  double sum = 0.0, sx = 0.0, sy = 0.0;
  for (int iy = 0; iy < s.grid.my; ++iy)
    for (int ix = 0; ix < s.grid.mx; ++ix) {
      const double p = s.pn.empty() ? 0.0 : s.pn[s.grid.index(ix, iy)];
      sum += p;
      sx += p * s.grid.x_centre(ix);
      sy += p * s.grid.y_centre(iy);
    }
  return sum > 0.0 ? std::pair{sx / sum, sy / sum} : std::pair{0.0, 0.0};
}

WheelRailPatch describe_patch(const model::WheelRailProblem& p, const PlacedProfiles& prof,
                              const WheelsetPose& pose, const PatchSetup& s, Solution sol) {
  WheelRailPatch w;
  const Vec3 ref = s.frame.origin;
  const double d = s.frame.delta_rad;
  w.reference_tr = to_public(ref);
  w.contact_angle_rad = d;
  // Rail-profile coordinates: undo the rail's shift and roll.
  // A roller's reference lies below its principal profile when x ≠ 0; the profile point is the
  // one at the same lateral position.
  const double z_profile = prof.roller() ? prof.rail_at_track_y(ref.y).z : ref.z;
  const double ry = ref.y - prof.rail_y_mm(), rz = z_profile - prof.rail_z_mm();
  const double a = prof.rail_roll_rad();
  w.y_rail_mm = std::cos(a) * ry + std::sin(a) * rz;
  w.z_rail_mm = -std::sin(a) * ry + std::cos(a) * rz;
  w.s_rail_mm = prof.rail().at_y(ry).s;
  w.delta_rail_rad = d - a;
  const Vec3 q = pose.rotation.transposed_times(ref - pose.centre);
  w.reference_ws = to_public(q);
  // Wheel-profile coordinates: in the wheel's own frame (turned on a flexible wheelset).
  const Vec3 qw = pose.wheel_rotation.transposed_times(ref - pose.wheel_centre);
  w.reference_wheel = {qw.x, qw.y - prof.wheel_y_offset_mm(), qw.z - prof.wheel_r0_mm()};
  w.s_wheel_mm = prof.wheel().at_y(w.reference_wheel.y).s;
  w.delta_wheel_rad = d - p.motion.roll_rad - p.wheel_deviation.droll_rad;
  w.xi = s.kinematics.xi;
  w.eta = s.kinematics.eta;
  w.phi_per_mm = s.kinematics.phi_per_mm;
  w.chi_rad = s.kinematics.chi_rad;
  w.dq_mm = s.kinematics.dq_mm;
  w.veloc_mm_s = s.kinematics.veloc_mm_s;
  w.dx_mm = s.dx_mm;
  w.ds_mm = s.ds_mm;
  const double fn = sol.totals.fn, fx = sol.totals.fx, fs = sol.totals.fy;
  const Vec3 f_tr{fx, fs * std::cos(d) - fn * std::sin(d), fn * std::cos(d) + fs * std::sin(d)};
  w.force_tr = to_public(f_tr);
  w.force_ws = to_public(pose.rotation.transposed_times(f_tr));
  // Moments (physics.md §13.6): (r_ref − r_marker) × F + R_ref·(0, 0, MN), MN about the normal.
  const Vec3 mn = sol.totals.mz * Vec3{0.0, -std::sin(d), std::cos(d)};
  const Vec3 rail_marker{0.0, prof.rail_y_mm(), prof.rail_z_mm()};
  const Vec3 wheel_marker = pose.centre + pose.rotation * wheelrail::wheel_marker_ws(p, prof);
  w.moment_tr = to_public(cross(ref - rail_marker, f_tr) + mn);
  w.moment_ws = to_public(pose.rotation.transposed_times(cross(ref - wheel_marker, f_tr) + mn));
  const auto [xc, yc] = pressure_centre(sol);
  w.pressure_centre_x_mm = ref.x + xc;
  w.pressure_centre_y_mm = ref.y + std::cos(d) * yc;
  w.solution = std::move(sol);
  return w;
}

/// The rail and wheel markers of the placement (physics.md §13.2).
void describe_markers(const model::WheelRailProblem& p, const PlacedProfiles& prof,
                      const WheelsetPose& pose, WheelRailSolution& out) {
  out.rail_marker_tr = {{0.0, prof.rail_y_mm(), prof.rail_z_mm()}, prof.rail_roll_rad(), 0.0};
  const Vec3 w = wheelrail::wheel_marker_ws(p, prof);
  const model::WheelDeviation& d = p.wheel_deviation;
  out.wheel_marker_ws = {to_public(w), d.droll_rad, d.dyaw_rad};
  out.wheel_marker_tr = {to_public(pose.centre + pose.rotation * w),
                         p.motion.roll_rad + d.droll_rad, p.motion.yaw_rad + d.dyaw_rad};
}

/// A left wheel is computed as a right one; its lateral components change sign.
void mirror_to_left(WheelRailSolution& s) {
  auto flip = [](Vector3& v) { v.y = -v.y; };
  // A moment is an axial vector: mirrored in y its x and z components change sign.
  auto flip_moment = [](Vector3& m) {
    m.x = -m.x;
    m.z = -m.z;
  };
  auto flip_marker = [&](ProfileMarker& m) {
    flip(m.position);
    m.roll_rad = -m.roll_rad;
    m.yaw_rad = -m.yaw_rad;
  };
  flip(s.force_tr);
  flip(s.force_ws);
  flip_moment(s.moment_tr);
  flip_moment(s.moment_ws);
  flip_marker(s.rail_marker_tr);
  flip_marker(s.wheel_marker_tr);
  flip_marker(s.wheel_marker_ws);
  for (WheelRailPatch& w : s.patches) {
    flip(w.reference_tr);
    flip(w.reference_wheel);
    flip(w.reference_ws);
    flip(w.force_tr);
    flip(w.force_ws);
    flip_moment(w.moment_tr);
    flip_moment(w.moment_ws);
    w.delta_rail_rad = -w.delta_rail_rad;
    w.delta_wheel_rad = -w.delta_wheel_rad;
    w.pressure_centre_y_mm = -w.pressure_centre_y_mm;
    w.contact_angle_rad = -w.contact_angle_rad;
    w.y_rail_mm = -w.y_rail_mm;
    w.eta = -w.eta;
    w.phi_per_mm = -w.phi_per_mm;
    Totals& t = w.solution.totals;
    t.fy = -t.fy;
    t.mz = -t.mz;
    t.creep_y = -t.creep_y;
    t.spin = -t.spin;
  }
}

/// The contact area of a patch's solution on the super grid (its elements with pressure).
wheelrail::SuperGridBox contact_box(const Solution& s, const PatchSetup& setup) {
  wheelrail::SuperGridBox b{1e300, -1e300, 1e300, -1e300};
  for (int iy = 0; iy < s.grid.my; ++iy)
    for (int ix = 0; ix < s.grid.mx; ++ix) {
      if (s.pn.empty() || !(s.pn[s.grid.index(ix, iy)] > 0.0)) continue;
      const double x = s.grid.x_centre(ix) + setup.origin_x_mm;
      const double y = s.grid.y_centre(iy) + setup.origin_y_mm;
      b = {std::min(b.x_lo, x), std::max(b.x_hi, x), std::min(b.y_lo, y), std::max(b.y_hi, y)};
    }
  return b;
}

/// The pitch moment on the rail about the wheelset's axle, in wheelset coordinates [N·mm]: the
/// moment about the wheel marker m plus m × F (F=2's MY_WS). The marker lies about the wheel's
/// radius below the axle, so M_y ≈ r·F_x(ws).
double axle_pitch_moment(const WheelRailSolution& s) {
  const Vector3& m = s.wheel_marker_ws.position;
  return s.moment_ws.y + m.z * s.force_ws.x - m.x * s.force_ws.z;
}

/// Linear theory's d(F_x/F_z)/dVPITCH [s/rad] (spec-additions §A6): Σ G·a·b·C11·r/|V| over the
/// patches (a, b the equivalent ellipse of each patch's contact, G and ν its combined constants),
/// r the distance of the contact point below the axle, over F_z.
double linear_pitch_slope(const WheelRailSolution& s, double v) {
  double slope = 0.0;
  for (const WheelRailPatch& w : s.patches) {
    const Solution& sol = w.solution;
    if (sol.pn.empty()) continue;
    const simplified::Ellipse e = simplified::equivalent_ellipse(sol.grid, sol.pn);
    if (!(e.a > 0.0 && e.b > 0.0)) continue;
    const double c11 = simplified::kalker_coefficients(e.a / e.b, sol.material.nu).c11;
    slope += sol.material.g * e.a * e.b * c11 * std::abs(w.reference_ws.z) / std::abs(v);
  }
  return slope / std::max(std::abs(s.force_tr.z), 1.0);
}

}  // namespace

WheelRailSolution WheelsetSolver::Impl::solve_at(const model::WheelRailProblem& p, double z_ws,
                                                 bool check_ends, bool normal_only) {
  using Clock = std::chrono::steady_clock;
  const auto since = [](Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
  };
  auto start = Clock::now();
  const PlacedProfiles& prof = *profiles;
  const WheelsetPose pose = wheelrail::pose_of(p, prof, z_ws);
  const SearchResult search = wheelrail::search_contact(p, prof, samples, z_ws);
  if (check_ends && !search.patches.empty() && search.minimum_at_profile_end)
    throw GeometryError(
        "the deepest interpenetration lies at an end of the rail profile: the wheel is misplaced "
        "on the rail (check Y_WS, the gauge and the profiles' orientation)");
  WheelRailSolution out;
  out.z_ws_mm = z_ws;
  if (!normal_only) {
    last_solve_turned = false;
    for (const ContactRegion& r : search.patches) last_solve_turned |= r.angle_turned;
  }
  Vec3 total_tr{}, total_ws{}, moment_tr{}, moment_ws{};
  describe_markers(p, prof, pose, out);
  const bool transient = wheelrail::on_super_grid(p);
  if (transient && !normal_only) pending.clear();
  for (std::size_t k = 0; k < search.patches.size(); ++k) {
    const wheelrail::SuperGridBox* before =
        transient && k < previous_contact.size() && previous_contact[k] ? &*previous_contact[k]
                                                                        : nullptr;
    PatchSetup setup =
        wheelrail::setup_patch(p, prof, pose, search.patches[k], out.warnings, before);
    if (p.friction_variation.along != model::FrictionVariation::Along::None) {
      // V=1: the rail surface inclination at the reference point (of the right-wheel
      // computation); V=2: the contact's place along the track.
      const bool by_angle =
          p.friction_variation.along == model::FrictionVariation::Along::RailInclination;
      const double key = by_angle ? std::atan(prof.rail_at_track_y(setup.frame.origin.y).dz_dy)
                                  : p.motion.s_mm + setup.frame.origin.x;
      setup.problem.friction = wheelrail::friction_at(p.friction_variation, key);
    }
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
    }
    if (normal_only) setup.problem.tangential.kind = model::TangentialKind::None;
    // Subsurface stresses of the final patches only (WheelsetSolver::solve), not of every
    // iterate of the force iterations: they cost more than the contact problem itself.
    setup.problem.subsurface.clear();
    geometry_seconds += since(start);
    start = Clock::now();
    const model::PressureModel pressure = setup.problem.normal.pressure;
    if (p.validated_only && pressure == model::PressureModel::Analyn &&
        search.patches[k].regions > 1)
      throw NotSupportedError(
          "not supported yet: module 1 ANALYN (B=6) on a patch combined from several "
          "interpenetration regions (not yet validated: mbench_a22_kpec case 6 differs in MN)");
    Solution sol = solver_for(k).solve(setup.problem);
    patch_solve_seconds += since(start);
    start = Clock::now();
    if (!sol.solver.converged) {
      out.converged = false;
      out.message = fmt::format("patch {}: {}", k + 1, sol.solver.message);
    }
    if (transient && !normal_only)
      pending.push_back({sol, setup.origin_x_mm, setup.origin_y_mm, contact_box(sol, setup)});
    WheelRailPatch w = describe_patch(p, prof, pose, setup, std::move(sol));
    w.friction = setup.problem.friction;
    total_tr = total_tr + Vec3{w.force_tr.x, w.force_tr.y, w.force_tr.z};
    total_ws = total_ws + Vec3{w.force_ws.x, w.force_ws.y, w.force_ws.z};
    moment_tr = moment_tr + Vec3{w.moment_tr.x, w.moment_tr.y, w.moment_tr.z};
    moment_ws = moment_ws + Vec3{w.moment_ws.x, w.moment_ws.y, w.moment_ws.z};
    out.patches.push_back(std::move(w));
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

namespace {

/// A left wheel's inputs are given in its mirrored frame (y towards its field side); the
/// geometry is computed for a right wheel, so the lateral inputs change sign here and the
/// lateral outputs in mirror_to_left().
model::WheelRailProblem as_right_side(model::WheelRailProblem p) {
  if (p.side != model::WheelSide::Left) return p;
  model::WheelsetState& m = p.motion;
  m.y_mm = -m.y_mm;
  m.roll_rad = -m.roll_rad;
  m.yaw_rad = -m.yaw_rad;
  m.vy_mm_s = -m.vy_mm_s;
  m.vroll_rad_s = -m.vroll_rad_s;
  m.vyaw_rad_s = -m.vyaw_rad_s;
  // The wheel's deviations are signed like the rail's (positive towards +y of the track).
  model::WheelDeviation& w = p.wheel_deviation;
  w.dy_mm = -w.dy_mm;
  w.droll_rad = -w.droll_rad;
  w.dyaw_rad = -w.dyaw_rad;
  w.vy_mm_s = -w.vy_mm_s;
  w.vroll_rad_s = -w.vroll_rad_s;
  w.vyaw_rad_s = -w.vyaw_rad_s;
  model::RailState& r = p.rail_state;
  r.dy_mm = -r.dy_mm;
  r.droll_rad = -r.droll_rad;
  r.vy_mm_s = -r.vy_mm_s;
  r.vroll_rad_s = -r.vroll_rad_s;
  p.track.rail_y0_mm = -p.track.rail_y0_mm;
  p.track.curvature_per_mm = -p.track.curvature_per_mm;
  return p;
}

}  // namespace

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
  // Never from loss of contact (release 25.1, wheelrail-advanced.md §6.3): at least 1 µm in.
  double z1 = std::max(z0 + pen / cos_min, z0 + 1e-3);
  // I ≥ 1: from the previous case's approach beyond first contact, scaled by Hertz's F^(2/3)
  // (wheelrail-advanced.md §6.3: not when the force changed by more than a factor 5).
  if (p.estimate_from_previous_case && k <= 0.0 && last_approach_mm > 0.0 && last_fz_N > 0.0 &&
      st.target_N > 0.0 && st.target_N < 5.0 * last_fz_N && last_fz_N < 5.0 * st.target_N)
    z1 = std::max(z0 + last_approach_mm * std::cbrt(std::pow(st.target_N / last_fz_N, 2.0)),
                  z0 + 1e-3);
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
  auto full_at = [&](double z) {
    result = solve_at(p, z, first);
    first = false;
    wheelrail::HeightSample h;
    h.z_mm = z;
    h.fz_N = result.force_tr.z;
    for (const WheelRailPatch& w : result.patches)
      h.patches.push_back(
          {w.solution.totals.pen, w.contact_angle_rad, w.solution.totals.fn, w.solution.totals.fy});
    return h;
  };
  // F_z = Σ F_n cos δ + F_s sin δ with F_s = fs_ratio·F_n from the last full solve.
  auto normal_at = [&](double z, const std::vector<double>& fs_ratio) {
    const WheelRailSolution r = solve_at(p, z, false, true);
    wheelrail::HeightSample h;
    h.z_mm = z;
    for (std::size_t i = 0; i < r.patches.size(); ++i) {
      const WheelRailPatch& w = r.patches[i];
      const double fn = w.solution.totals.fn, delta = w.contact_angle_rad;
      const double fs = (i < fs_ratio.size() ? fs_ratio[i] : 0.0) * fn;
      h.fz_N += fn * std::cos(delta) + fs * std::sin(delta);
      h.patches.push_back({w.solution.totals.pen, delta, fn, fs});
    }
    return h;
  };
  const wheelrail::VerticalForceResult vf =
      p.patch.tangential.kind == model::TangentialKind::None
          ? wheelrail::solve_vertical_force(settings, z0, z1, full_at)
          : wheelrail::solve_vertical_force_split(settings, z0, z1, full_at, normal_at);
  result.trace = vf.trace;
  if (vf.converged && k <= 0.0) {
    last_approach_mm = vf.z_mm - z0;
    last_fz_N = st.target_N;
  }
  if (!vf.converged) {
    result.converged = false;
    result.message = vf.message;
  } else if (!vf.message.empty()) {
    result.warnings.push_back(vf.message);
  }
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
  // Judged on the state that stands: an iterate of the vertical-force iteration may pass through
  // such a state (mbench_a22_kpec c2 does where the deepest point changes lobes) and leave it.
  if (p.validated_only && p.patch.normal.pressure == model::PressureModel::Kpec)
    for (const WheelRailPatch& w : result.patches)
      if (w.solution.solver.kpec_rows_beyond_interpenetration > 0)
        throw NotSupportedError(
            "not supported yet: module 1 KPEC (B=5) where the gap interpenetrates beyond the "
            "equivalent ellipse (a second lobe; not yet validated: mbench_a22_kpec case 1 "
            "differs)");
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
  impl_->geometry_seconds = impl_->patch_solve_seconds = 0.0;
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
  WheelRailSolution result = problem.longitudinal != model::LongitudinalLoading::PitchVelocity
                                 ? impl_->solve_pitch_velocity(problem)
                             : problem.massless_rail.enabled ? impl_->solve_massless_rail(problem)
                                                             : impl_->solve_placed(problem, {});
  if (wheelrail::on_super_grid(problem)) impl_->commit_transient();
  if (problem.validated_only && impl_->last_solve_turned)
    throw NotSupportedError(
        "not supported yet: module 1 patches between D_SEP and D_TURN (their reference angles "
        "turned towards each other; not yet validated: mbench_a22_varfric case 3 differs)");
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
  return result;
}

}  // namespace rollcontact
