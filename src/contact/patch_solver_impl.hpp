#pragma once
// What a PatchSolver holds between cases: its options, the operator cache and the previous
// solution (sequences, warm starts).

#include <optional>

#include "contact/operator_cache.hpp"
#include "rollcontact/solve.hpp"

namespace rollcontact {

struct PatchSolver::Impl {
  explicit Impl(const SolveOptions& o) : options(o), operators({o.fft, o.fft_planning}) {}

  SolveOptions options;
  OperatorCache operators;
  std::optional<Solution> previous;  ///< last solved case (P=0 continuation, warm starts)
  /// Where the previous solution's grid origin lies in the sequence's frame (SequenceLink).
  double previous_origin_x = 0.0, previous_origin_y = 0.0;
  /// The last solution of the step before the previous one (SequenceLink::new_step), and its
  /// grid origin.
  std::optional<Solution> earlier;
  double earlier_origin_x = 0.0, earlier_origin_y = 0.0;
  /// The pressure of the last solve, whether or not it became the previous one (the start of
  /// the next normal iteration, SequenceLink::normal_from_previous), on its grid and origin.
  std::vector<double> latest_pn;
  Grid latest_grid;
  double latest_origin_x = 0.0, latest_origin_y = 0.0;
  /// The last normal problem NormCG solved to convergence: its gap h* and load, and its answer.
  /// A full solve at the height of the vertical-force iteration's last normal estimate poses
  /// the same problem again, bit for bit (SequenceLink::normal_from_previous).
  struct NormalAnswer {
    Grid grid;
    std::vector<double> h, pn, un;  ///< un = A·pn
    bool force_given = false;
    double load = 0.0;
    CombinedMaterial material;  ///< it was solved with (viscoelastic bodies and tables: never kept)
    double pen = 0.0;
    double eps = 0.0;  ///< the tolerance it was solved to
    /// Solved with the normal operator of this grid size and element and this material (so its
    /// un is A·pn there; a patch's turned coefficients, C=4, change with its rows): what of the
    /// material the normal operator depends on.
    bool same_operator(const Grid& other, const CombinedMaterial& m) const {
      return grid.mx == other.mx && grid.my == other.my && grid.dx == other.dx &&
             grid.dy == other.dy && material.g == m.g && material.nu == m.nu && material.k == m.k &&
             material.normal_layer_compliance == m.normal_layer_compliance &&
             material.elements == m.elements &&
             material.inclination_variant == m.inclination_variant &&
             material.inclination_curvature_per_mm == m.inclination_curvature_per_mm;
    }
  };
  std::optional<NormalAnswer> last_normal;
};

}  // namespace rollcontact
