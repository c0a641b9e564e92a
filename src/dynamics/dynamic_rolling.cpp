// The dynamic-rolling driver: the static equilibrium (and the pitch velocity for FX_WS) with the
// wheel/rail solver, then time steps of the two-mass model with the contact solved at the
// wheel's height at every iterate.

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "dynamics/two_mass_step.hpp"
#include "rollcontact/dynamics.hpp"
#include "rollcontact/errors.hpp"
#include "rollcontact/wheelrail.hpp"

namespace rollcontact::dynamics {

namespace {

constexpr double kg_to_N_s2_per_mm = 1e-3;

TwoMassSystem two_mass_system(const SprungWheel& v) {
  TwoMassSystem s;
  s.sprung_mass = v.sprung_mass_kg * kg_to_N_s2_per_mm;
  s.wheel_mass = v.wheel_mass_kg * kg_to_N_s2_per_mm;
  s.stiffness = v.suspension_stiffness_N_per_mm;
  s.damping = v.suspension_damping_N_s_per_mm;
  s.gravity = v.gravity_mm_per_s2;
  return s;
}

void check(const SprungWheel& v, const DynamicRollingSettings& st,
           const model::WheelRailProblem& p) {
  auto positive = [](double x, const char* what) {
    if (!(x > 0.0 && std::isfinite(x)))
      throw ProblemError(fmt::format("dynamic rolling: {} must be positive, not {}", what, x));
  };
  positive(v.sprung_mass_kg, "the sprung mass [kg]");
  positive(v.wheel_mass_kg, "the wheel mass [kg]");
  positive(v.suspension_stiffness_N_per_mm, "the suspension stiffness [N/mm]");
  positive(v.gravity_mm_per_s2, "gravity [mm/s2]");
  positive(st.distance_mm, "the distance [mm]");
  positive(st.time_step_s, "the time step [s]");
  if (p.roller.enabled)
    throw ProblemError(
        "dynamic rolling: the model runs the wheel along a track; a roller rig (C1=4, 5) is not "
        "part of it");
  positive(std::abs(p.motion.vs_mm_s), "the rolling speed VS [mm/s]");
  if (v.suspension_damping_N_s_per_mm < 0.0 || st.contact_damping_ratio < 0.0)
    throw ProblemError("dynamic rolling: damping must not be negative");
  if (p.massless_rail.enabled)
    throw ProblemError("dynamic rolling: the massless rail (F=3) is not part of the model yet");
}

/// What one contact solve says, and the sample it makes.
void describe(const WheelRailSolution& s, TimeSample& out) {
  out.fx_N = s.force_tr.x;
  out.fy_N = s.force_tr.y;
  out.fz_N = s.force_tr.z;
  out.patches = static_cast<int>(s.patches.size());
  out.area_mm2 = out.pmax_N_mm2 = 0.0;
  out.contact_elements = out.slip_elements = 0;
  for (const WheelRailPatch& w : s.patches) {
    const Statistics& st = w.solution.statistics;
    out.contact_elements += st.ncon;
    out.slip_elements += st.nslip;
    out.area_mm2 += st.ncon * w.dx_mm * w.ds_mm;
    out.pmax_N_mm2 = std::max(out.pmax_N_mm2, w.solution.totals.pmax);
  }
  out.converged = s.converged;
}

}  // namespace

DynamicRollingResult run_dynamic_rolling(const model::WheelRailProblem& problem,
                                         const SprungWheel& vehicle,
                                         const DynamicRollingSettings& st,
                                         const SolveOptions& options, const Progress& progress) {
  check(vehicle, st, problem);
  DynamicRollingResult out;
  WheelsetSolver solver(options);
  TwoMassSystem sys = two_mass_system(vehicle);
  out.static_load_N = vehicle.static_load_N();

  // The static equilibrium: FZ = (M_s + m_w)·g, and VPITCH for a prescribed FX_WS.
  model::WheelRailProblem p = problem;
  p.vertical = model::VerticalLoading::Force;
  p.motion.fz_N = out.static_load_N;
  p.first_of_sequence = true;
  const WheelRailSolution equilibrium = solver.solve(p);
  ++out.solves;
  if (!equilibrium.converged)
    throw SolverError("dynamic rolling: the static equilibrium did not converge: " +
                      equilibrium.message);
  out.warnings = equilibrium.warnings;
  out.z_ws_static_mm = equilibrium.z_ws_mm;
  out.z_ws_contact_mm =
      equilibrium.trace.empty() ? equilibrium.z_ws_mm : equilibrium.trace.front().z_ws_mm;
  p.longitudinal = model::LongitudinalLoading::PitchVelocity;
  p.motion.vpitch_rad_s = equilibrium.vpitch_rad_s;
  p.vertical = model::VerticalLoading::Position;
  p.first_of_sequence = false;

  const double v = std::abs(p.motion.vs_mm_s);
  double s_mm = 0.0;
  WheelRailSolution last;
  auto contact = [&](double z_w, double v_w) {
    p.motion.z_mm = z_w;
    p.motion.vz_mm_s = v_w;
    p.motion.s_mm = problem.motion.s_mm + s_mm;
    // The wheel turns as it rolls: what an out-of-round wheel (slices) brings under the axle;
    // a body of revolution does not notice.
    p.motion.pitch_rad = problem.motion.pitch_rad + p.motion.vpitch_rad_s * (s_mm / v);
    p.rail_state.dz_mm = problem.rail_state.dz_mm + st.dip.dz_mm(s_mm);
    p.rail_state.vz_mm_s = problem.rail_state.vz_mm_s + v * st.dip.slope(s_mm);
    last = solver.solve(p);
    ++out.solves;
    return last.force_tr.z;
  };

  // Contact stiffness at the static load (reported; the first step's secant guess).
  const double dz = 1e-4;
  const double f_plus = contact(out.z_ws_static_mm + dz, 0.0);
  out.contact_stiffness_N_per_mm = (f_plus - equilibrium.force_tr.z) / dz;
  out.contact_frequency_Hz =
      std::sqrt(std::max(out.contact_stiffness_N_per_mm, 0.0) / sys.wheel_mass) / (2.0 * M_PI);
  sys.contact_damping = 2.0 * st.contact_damping_ratio *
                        std::sqrt(std::max(out.contact_stiffness_N_per_mm, 0.0) * sys.wheel_mass);

  TwoMassState state;
  state.z_s = state.z_w =
      st.start == StartState::Equilibrium ? out.z_ws_static_mm : out.z_ws_contact_mm;
  double fz = contact(state.z_w, 0.0);
  state.v_s = state.v_w = st.initial_vz_mm_per_s;
  set_accelerations(sys, fz, v * st.dip.slope(0.0), state);
  TimeSample sample;
  describe(last, sample);
  sample.z_ws_mm = state.z_w;
  sample.vz_wheel_mm_s = state.v_w;
  out.history.push_back(sample);

  StepSettings step;
  step.dt = st.time_step_s;
  step.force_tolerance = st.force_tolerance * out.static_load_N;
  step.max_iterations = st.max_iterations_per_step;
  double stiffness = out.contact_stiffness_N_per_mm;
  const int steps = static_cast<int>(std::ceil(st.distance_mm / (v * st.time_step_s)));
  const double z_sprung_start = state.z_s;
  for (int n = 1; n <= steps; ++n) {
    s_mm = v * st.time_step_s * n;
    step.rail_velocity = v * st.dip.slope(s_mm);
    const StepResult r = trapezoidal_step(sys, state, fz, stiffness, step, contact);
    state = r.next;
    fz = r.fz;
    stiffness = r.stiffness > 0.0 ? r.stiffness : out.contact_stiffness_N_per_mm;
    ++out.steps;
    TimeSample ts;
    describe(last, ts);
    ts.t_s = st.time_step_s * n;
    ts.s_mm = s_mm;
    ts.z_sprung_mm = state.z_s - z_sprung_start;
    ts.z_ws_mm = state.z_w;
    ts.vz_wheel_mm_s = state.v_w;
    ts.rail_dz_mm = st.dip.dz_mm(s_mm);
    ts.solves = r.solves;
    ts.converged = ts.converged && r.converged;
    if (!ts.converged && out.converged) {
      out.converged = false;
      out.message = fmt::format("step {} (t = {:.6f} s): {}", n, ts.t_s,
                                r.converged ? last.message
                                            : "the contact force did not meet its linear "
                                              "prediction within the step's iterations");
    }
    if (n % std::max(st.keep_every, 1) == 0 || n == steps) out.history.push_back(ts);
    if (progress) progress(ts, static_cast<double>(n) / steps);
  }
  return out;
}

}  // namespace rollcontact::dynamics
