#pragma once
// The state of a WheelsetSolver between cases and the steps of a case (private to
// src/wheelrail): wheelset_solver.cpp runs one case at one height and places it,
// wheelset_iterations.cpp iterates the height, the rail deflections and the pitch velocity,
// wheelset_results.cpp turns patch solutions into the wheel/rail outputs.

#include <optional>
#include <string>
#include <vector>

#include "rollcontact/wheelrail.hpp"
#include "wheelrail/contact_search.hpp"
#include "wheelrail/patch_setup.hpp"
#include "wheelrail/placed_profiles.hpp"
#include "wheelrail/vertical_force.hpp"
#include "wheelrail/wheelset_pose.hpp"
#include "wheelrail/wheelset_results.hpp"

namespace rollcontact {

using wheelrail::as_right_side;
using wheelrail::axle_pitch_moment;
using wheelrail::contact_box;
using wheelrail::contact_modulus;
using wheelrail::ContactRegion;
using wheelrail::describe_markers;
using wheelrail::describe_patch;
using wheelrail::linear_pitch_slope;
using wheelrail::mirror_to_left;
using wheelrail::PatchSetup;
using wheelrail::PlacedProfiles;
using wheelrail::SearchResult;
using wheelrail::to_public;
using wheelrail::Vec3;
using wheelrail::WheelsetPose;

/// A KPEC state whose gap interpenetrates beyond the equivalent ellipse (a second lobe): refused
/// unless unvalidated results are asked for, and never the start of the next case of a sweep.
bool kpec_second_lobe(const model::WheelRailProblem& p, const WheelRailSolution& s);

/// How the vertical equation of one solve is posed (the massless rail changes it).
struct VerticalOptions {
  double tolerance = -1.0;  ///< of the vertical iteration; <= 0: EPS of the case
  /// N=0 with the massless rail: the rail's vertical spring kz [N/mm] and load fz [N]. The wheel
  /// height over the undeflected rail is iterated and the rail deflection δz follows. 0: none.
  double rail_kz_N_per_mm = 0.0, rail_fz_N = 0.0;
};

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
  /// problems alone (an estimate inside the vertical-force iteration); `rough`: the patches
  /// solved to kRoughTolerance (a full solve that only informs the vertical-force iteration's
  /// first round).
  ///
  /// `geometry`, if given, keeps the contact search and the patches' set-up of the last height
  /// it was given for the same problem: within one vertical-force iteration the full solve
  /// follows the normal estimate at the same height (bit for bit), whose geometry it reuses.
  struct GeometryAtHeight {
    bool valid = false;
    double z_ws_mm = 0.0;
    SearchResult search;
    std::vector<PatchSetup> setups;                     ///< as setup_patch() made them
    std::vector<std::vector<std::string>> setup_notes;  ///< the warnings it gave, per patch
  };
  WheelRailSolution solve_at(const model::WheelRailProblem& p, double z_ws, bool check_ends,
                             bool normal_only = false, bool rough = false,
                             GeometryAtHeight* geometry = nullptr);
  /// The relative tolerance of a rough solve. The first full solve lies where the Hertz
  /// estimate put it, 10–30 % off the load, and a second round with the share of a full solve
  /// near the answer follows in almost every case; F_s and F_n to about 1 % change little in
  /// that (mbench force sweeps at 0.5 mm: the same numbers of full solves, normal solves within
  /// 5 %, as at the case's tolerance; tangential products −20 to −35 %, normal −7 to −11 %;
  /// 1e-3 for the tangential problems saved two thirds of that).
  static constexpr double kRoughTolerance = 1e-2;

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
  /// KPEC/ANALYN: the patch problems of the last full solve, whose results stand when the
  /// iteration ends; their u_n and elastic energy are made then (complete_energies()).
  std::vector<model::PatchProblem> approximate_problems;
  void complete_energies(WheelRailSolution& result) {
    if (approximate_problems.size() != result.patches.size()) return;
    for (std::size_t k = 0; k < result.patches.size(); ++k)
      solver_for(k).complete_elastic_energy(approximate_problems[k], result.patches[k].solution);
    approximate_problems.clear();
  }
  /// The last two converged vertical-force iterations of consecutive cases, the last at the
  /// back: approach z_ws − z_first-contact [mm] and force [N] (the next case's start).
  struct ApproachAtForce {
    double approach_mm = 0.0, fz_N = 0.0;
  };
  std::vector<ApproachAtForce> previous_approaches;
  void remember_approach(double approach_mm, double fz_N);
  /// The approach at `fz_N` from previous_approaches (nothing without a usable one).
  std::optional<double> approach_from_previous_cases(double fz_N) const;

  /// No full solve of the current case yet: its first starts a new step of the patches'
  /// sequences (SequenceLink::new_step).
  bool new_step_pending = false;

  /// Wall time of the current case [s] (see WheelRailSolution).
  double geometry_seconds = 0.0, patch_solve_seconds = 0.0, patch_setup_seconds = 0.0;
};

}  // namespace rollcontact
