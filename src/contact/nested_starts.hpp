#pragma once
// Nested iteration for large grids: starts of the normal and the steady-rolling tangential
// problems from the same problem on grids with elements twice as large.

#include <vector>

#include "contact/patch_solver_impl.hpp"
#include "normal/normal_solver.hpp"
#include "tangential/tangential_system.hpp"

namespace rollcontact::contact {

using Field = std::vector<double>;

/// Nested iteration for large grids: the same normal problem on a grid with elements twice as
/// large (h averaged over the 2×2 fine elements), solved — itself started from a coarser grid —
/// and prolongated element-wise. Returns an empty field when the grid is too small to gain.
/// The fine solve then starts close to its solution, with few active-set changes.
Field coarse_grid_start(PatchSolver::Impl& st, int level, const Grid& grid, const Field& h,
                        normal::NormalLoad load, double value, const CombinedMaterial& material,
                        const normal::NormalSettings& settings, int& iterations);

/// Nested iteration for steady rolling on large grids, the tangential counterpart of
/// coarse_grid_start: the semismooth Newton iteration moves the adhesion front about one element
/// per step along the rows (docs/decisions.md), so a start whose division into adhesion and slip
/// is right to within an element or two saves most fine steps. The coarse problem has elements
/// twice as large: traction bound averaged over the 2×2 fine elements (force-conserving), slip
/// per step averaged over the fine contact elements and doubled with the rolling step, and the
/// operator (C − C′) with C′ one coarse step downstream. Its solution (itself started from a
/// coarser grid) is prolongated element-wise: slipping parents give slip at the fine bound in
/// the parent's direction, adhering parents their traction within the fine bound. Returns false
/// (start unchanged) when the grid is too small to gain or the coarse solve fails.
bool steady_coarse_start(PatchSolver::Impl& st, int level, const tangential::TangentialSystem& sys,
                         double shift_x, double shift_y, const CombinedMaterial& material,
                         const tangential::TangentialSettings& settings, Field& px, Field& py,
                         int& products);

}  // namespace rollcontact::contact
