#pragma once
// A conformal patch (CONTACT's D=4; spec/wheelrail-advanced.md §1.4–1.8, spec-additions.md
// §A7): the grid uniform in (x, s̃) on the curved reference, one row per reference sample; the
// undeformed distance measured along each row's own normal; the rigid slip per element from the
// particle velocities of rail and wheel, split into least-squares "average creepages" and an
// element-wise remainder; and after the solve the forces both in the curvilinear frame (tilde)
// and turned into the reference's tangent plane (bar).

#include <string>
#include <vector>

#include "rollcontact/wheelrail.hpp"
#include "wheelrail/patch_setup.hpp"

namespace rollcontact::wheelrail {

/// Rigid slip of one element at its spin-arm position (x̃, ỹ) [mm] (grid coordinates plus the
/// rolling offset f_φ·δq, relative to the spin centre).
struct SlipSample {
  double x = 0.0, y = 0.0, wx = 0.0, wy = 0.0;
};

/// ξ, η, φ minimising Σ (w_x − ξ + φỹ)² + (w_y − η − φx̃)² (wheelrail-advanced.md §1.6 step 6);
/// all zero for no samples or a degenerate set (all at one point).
PatchKinematics fit_average_creepages(const std::vector<SlipSample>& samples);

/// Fills in the conformal patch of `region` in `s`: frame, curved reference, grid, gap,
/// approach, kinematics (average creepages) and the remainder of the rigid slip as the
/// problem's extra slip. `s.problem` must hold the case's patch settings already.
void setup_conformal_patch(const model::WheelRailProblem& problem, const PlacedProfiles& profiles,
                           const WheelsetPose& pose, const ContactRegion& region, PatchSetup& s,
                           std::vector<std::string>& warnings);

/// The tilde and bar forces and the planar moments of a solved conformal patch.
ConformalPatch conformal_forces(const PatchSetup& s, const Solution& solution);

}  // namespace rollcontact::wheelrail
