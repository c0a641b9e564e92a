#pragma once
// Dynamic rolling (spec/dynamic-rolling.md §5): a wheel under a sprung mass rolling along a rail,
// its vertical motion integrated in time with the wheel/rail contact solved exactly at every step
// (WheelsetSolver, the wheelset height prescribed). No penalty stiffness and no contact time
// step: the contact force is the boundary-element answer at the wheel's height.
//
// Units: mm, N, s; masses in kg at the interface (1 kg = 1e-3 N·s²/mm inside). z is downward
// (CONTACT's track frame); forces are those on the rail.

#include <functional>
#include <string>
#include <vector>

#include "rollcontact/model/wheelrail.hpp"
#include "rollcontact/solve.hpp"

namespace rollcontact::dynamics {

/// The vehicle above the contact: a sprung mass on a primary suspension on the wheel.
/// Defaults: Ma, Markine, Mashal, Ren (2018); the wheel mass is not in the paper (assumed,
/// spec/dynamic-rolling.md §2.2).
struct SprungWheel {
  double sprung_mass_kg = 10000.0;                ///< M_s
  double wheel_mass_kg = 350.0;                   ///< m_w (assumed)
  double suspension_stiffness_N_per_mm = 1150.0;  ///< k_p (1.15 MN/m)
  double suspension_damping_N_s_per_mm = 2.5;     ///< c_p (2500 N·s/m)
  double gravity_mm_per_s2 = 9810.0;
  /// Static wheel load (M_s + m_w)·g [N].
  double static_load_N() const {
    return (sprung_mass_kg + wheel_mass_kg) * 1e-3 * gravity_mm_per_s2;
  }
};

/// A local rail-height irregularity: a dip (depth > 0: the rail surface lower) of cosine shape,
/// dz(s) = depth·(1 − cos(2π(s − start)/length))/2 for start ≤ s ≤ start + length.
struct RailDip {
  double depth_mm = 0.0;  ///< 0: a smooth rail
  double start_mm = 0.0, length_mm = 100.0;
  double dz_mm(double s_mm) const;
  double slope(double s_mm) const;  ///< d(dz)/ds
};

enum class StartState {
  Equilibrium,  ///< static equilibrium: F_z = (M_s + m_w)·g, no motion
  FirstContact  ///< the wheel just touches the rail, springs at their static length: it drops
};

struct DynamicRollingSettings {
  double distance_mm = 1000.0;  ///< rolled distance
  double time_step_s = 2e-5;    ///< trapezoidal rule; ≤ 1/20 of the wheel-on-contact period
  StartState start = StartState::Equilibrium;
  double initial_vz_mm_per_s = 0.0;  ///< initial downward velocity of wheel and sprung mass
  RailDip dip;
  /// Viscous damping between wheel and rail as a fraction of the critical damping of the wheel
  /// on the contact (2·sqrt(k_c·m_w), k_c at the static load). 0: the elastic contact, which
  /// does not damp. An FE model's contact damping (LS-DYNA's VDC, in percent of critical) is the
  /// counterpart; rail pads and wheel material damping are others.
  double contact_damping_ratio = 0.0;
  /// Relative tolerance of the force in the implicit step: the contact force at the new
  /// height against its linear prediction, relative to the static load.
  double force_tolerance = 1e-4;
  int max_iterations_per_step = 8;
  /// Every n-th step is kept in the history (1: all).
  int keep_every = 1;
};

/// One time step.
struct TimeSample {
  double t_s = 0.0;
  double s_mm = 0.0;                          ///< rolled distance
  double z_sprung_mm = 0.0;                   ///< sprung mass displacement (down) from its start
  double z_ws_mm = 0.0;                       ///< wheelset height as CONTACT's Z_WS (down)
  double vz_wheel_mm_s = 0.0;                 ///< wheel velocity (down)
  double rail_dz_mm = 0.0;                    ///< the irregularity under the wheel
  double fx_N = 0.0, fy_N = 0.0, fz_N = 0.0;  ///< total force on the rail, track coordinates
  double area_mm2 = 0.0;                      ///< elements in contact × element area, all patches
  double pmax_N_mm2 = 0.0;
  int contact_elements = 0, slip_elements = 0, patches = 0;
  int solves = 0;  ///< contact solves made in this step
  bool converged = true;
};

struct DynamicRollingResult {
  std::vector<TimeSample> history;
  double static_load_N = 0.0;
  double z_ws_static_mm = 0.0;   ///< wheelset height of the static equilibrium
  double z_ws_contact_mm = 0.0;  ///< where contact starts
  /// Contact stiffness dF_z/dz at the static load [N/mm], its wheel-on-contact frequency
  /// sqrt(k/m_w)/2π [Hz] and the time step's share of that period.
  double contact_stiffness_N_per_mm = 0.0, contact_frequency_Hz = 0.0;
  int steps = 0, solves = 0;
  bool converged = true;
  std::string message;  ///< why not converged
  /// The static equilibrium's warnings (e.g. "not validated against CONTACT: …").
  std::vector<std::string> warnings;
};

/// Called every step with the sample and the fraction done; may be empty.
using Progress = std::function<void(const TimeSample&, double fraction)>;

/// Rolls `problem` (a wheel/rail case: profiles, track, materials, grid, velocities; its
/// vertical loading and FZ are replaced by the dynamic model's) along the rail. With
/// LongitudinalLoading::Force the pitch velocity is first found for FX_WS at the static load
/// and then held (the wheel's rotation is not integrated).
DynamicRollingResult run_dynamic_rolling(const model::WheelRailProblem& problem,
                                         const SprungWheel& vehicle,
                                         const DynamicRollingSettings& settings,
                                         const SolveOptions& options = {},
                                         const Progress& progress = {});

/// Summary of a force history over its last `window_s` seconds: mean, peak to peak and the
/// dominant frequency below `max_frequency_Hz` (largest DFT amplitude of the mean-free signal).
struct SignalSummary {
  double mean = 0.0, min = 0.0, max = 0.0, dominant_frequency_Hz = 0.0;
  int samples = 0;
};
SignalSummary summarise_force(const std::vector<TimeSample>& history, double window_s,
                              double max_frequency_Hz = 2000.0);

}  // namespace rollcontact::dynamics
