#pragma once
// Building creep-force lookup tables (include/rollcontact/creep_lookup.hpp): one steady-rolling
// Hertzian case per node, solved with the method of a TableSettings (exact theory by default),
// in parallel; and the table's interpolation error against the same method at points held back
// from the grid.

#include <cstddef>
#include <functional>

#include "batch/creep_table.hpp"
#include "batch/distribution.hpp"
#include "rollcontact/creep_lookup.hpp"

namespace rollcontact::batch {

/// The default grid: 17 semi-axis ratios 0.2 … 5, ξ̃ and η̃ in 25 values each over [−1, 1]
/// (denser near zero, where the creep curves bend; beyond, full sliding), φ̃ in 21 values over
/// [−3, 3]: 223,125 nodes (measured at 500 held-back points with the exact theory, mx 11:
/// interpolation error of the force 0.97 % of μFN rms, 4.5 % at most).
CreepLookupAxes default_lookup_axes();

/// A coarse grid for quick checks and tests: a/b 0.5, 1, 2; ξ̃, η̃ in 7 values over [−1, 1];
/// φ̃ −1, 0, 1 (441 nodes).
CreepLookupAxes coarse_lookup_axes();

/// The patch problem of one node: the TableSettings' method on a Hertzian contact with
/// c = √(ab) = 9 mm, FN 82 kN, G 82 GPa, ν 0.28, μ 0.3, creepages from the normalised ones.
model::PatchProblem lookup_problem(double a_over_b, double ksi_n, double eta_n, double phi_n,
                                   const TableSettings& s);

/// Solves one node; throws SolverError when the solution did not converge.
CreepLookupValue solve_lookup_node(double a_over_b, double ksi_n, double eta_n, double phi_n,
                                   const TableSettings& s, PatchSolver& solver);

/// The whole table on `threads` threads, or over the processes of `distribution` when it has
/// more than one (then the root returns the table and the others an empty one). `progress(done)`
/// as in run_table. Throws SolverError naming the first node that did not converge.
CreepLookupTable build_creep_lookup(const CreepLookupAxes& axes, const TableSettings& s,
                                    int threads, Distribution* distribution = nullptr,
                                    const std::function<void(std::size_t)>& progress = {});

/// Interpolation error of `table` against the method itself at `points` pseudo-random points
/// inside the grid (deterministic for a seed), normalised like the table.
struct LookupAccuracy {
  std::size_t points = 0;
  double max_force_error = 0.0;   ///< max |(Δfx, Δfy)| [of μFN]
  double rms_force_error = 0.0;   ///< rms |(Δfx, Δfy)| [of μFN]
  double max_moment_error = 0.0;  ///< max |Δmz| [of μFN·c]
};
LookupAccuracy held_back_accuracy(const CreepLookupTable& table, const TableSettings& s,
                                  std::size_t points, unsigned seed, int threads);

}  // namespace rollcontact::batch
