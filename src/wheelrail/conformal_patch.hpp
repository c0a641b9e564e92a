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

/// What the grid must cover, relative to the reference point [mm]: x along the track and the
/// rail arc length (the region's, on a super grid widened to a continued patch's previous
/// contact).
struct PatchExtent {
  double x_lo_mm = 0.0, x_hi_mm = 0.0, s_lo_mm = 0.0, s_hi_mm = 0.0;
};

/// Fills in the conformal patch of `region` in `s`: curved reference, grid, gap, approach,
/// kinematics (average creepages) and the remainder of the rigid slip as the problem's extra
/// slip. `s` holds the frame, the super grid's origin and continuation (setup_patch) and
/// `s.problem` the case's patch settings already.
void setup_conformal_patch(const model::WheelRailProblem& problem, const PlacedProfiles& profiles,
                           const WheelsetPose& pose, const ContactRegion& region,
                           const PatchExtent& extent, PatchSetup& s,
                           std::vector<std::string>& warnings);

/// The tilde and bar forces and the planar moments of a solved conformal patch.
ConformalPatch conformal_forces(const PatchSetup& s, const Solution& solution);

}  // namespace rollcontact::wheelrail
