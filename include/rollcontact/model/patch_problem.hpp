#pragma once
// PatchProblem: everything that defines one contact patch for the solvers — physics only.
// Front ends (.inp, TOML, the C++ API, later the wheel/rail contact search) build it; the
// PatchSolver solves it. Units: mm, N, N/mm², s, rad. No file names, no input-format codes of
// the control words; see docs/architecture.md.

#include <vector>

#include "rollcontact/model/bodies.hpp"
#include "rollcontact/model/friction.hpp"
#include "rollcontact/model/geometry.hpp"
#include "rollcontact/model/heat.hpp"
#include "rollcontact/model/loading.hpp"
#include "rollcontact/model/solver_options.hpp"

namespace rollcontact::model {

/// How a problem relates to the previous one solved by the same PatchSolver (a sequence).
struct SequenceLink {
  /// Start from the previous solution: its tractions are the previous time of transient rolling
  /// and the warm start of the iterations. false: a new sequence (no memory).
  bool continue_previous = false;
  /// This problem's solution replaces the remembered previous one (false: it is solved but the
  /// sequence keeps the older state).
  bool becomes_previous = true;
  /// With prescribed forces: start the creepage iteration from the previous case's creepages
  /// (true) or afresh (false).
  bool force_iteration_from_previous = false;
  /// With continue_previous: start the normal iteration from the last solve's pressure (mapped
  /// onto this grid; also of a solve that did not become the previous one, such as the normal
  /// estimates of the vertical-force iteration, which lie closest to the next height) instead
  /// of the coarse-grid estimate — the start, not the answer. The wheel/rail solver sets it for
  /// the iterates and cases of one patch position.
  bool normal_from_previous = false;
  /// Where this problem's grid coordinates (0, 0) lie in a frame the grids of the sequence share
  /// [mm] (module 1's super grid: x along the track, y the rail arc length). The previous
  /// solution's fields are mapped onto this grid by the difference of the two origins (with the
  /// element offsets as before); 0, 0 for grids that share their coordinates (module 3).
  double origin_x_mm = 0.0, origin_y_mm = 0.0;
  /// The first solve of a new step of an evenly stepped sequence (a sweep, the time steps of a
  /// vehicle simulation): the remembered previous solution is the last of the step before, and
  /// with steady rolling the iterations start from it and the step's before that extrapolated
  /// linearly (2·last − before: exact where the tractions grow linearly from step to step, as
  /// in adhesion when the creepages do). Only a start: the solution does not depend on it
  /// beyond the tolerance.
  bool new_step = false;
};

struct PatchProblem {
  PotentialContact potential;  ///< the grid, or a Hertzian area
  UndeformedDistance gap;      ///< h(x, y) on a rectangular potential contact
  Bodies bodies;
  Friction friction;
  NormalLoading normal;
  TangentialLoading tangential;
  Rolling rolling;
  SolverOptions solver;
  SequenceLink sequence;
  SurfaceHeat heat{};                       ///< surface temperature wanted (steady rolling)
  std::vector<SubsurfaceBlock> subsurface;  ///< stresses wanted at these points (empty: none)
};

}  // namespace rollcontact::model
