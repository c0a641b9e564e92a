#pragma once
// From patch solutions to the wheel/rail outputs and back (src/wheelrail, private): see
// wheelset_results.cpp.

#include <utility>

#include "rollcontact/model/wheelrail.hpp"
#include "rollcontact/wheelrail.hpp"
#include "wheelrail/patch_setup.hpp"
#include "wheelrail/placed_profiles.hpp"
#include "wheelrail/wheelset_pose.hpp"

namespace rollcontact::wheelrail {

/// A geometry vector as the public API's.
inline Vector3 to_public(Vec3 v) {
  return {v.x, v.y, v.z};
}

/// Combined contact modulus E* = G/(1 − ν) of the two bodies (physics.md §3.1).
double contact_modulus(const model::Bodies& b);

/// The outputs of one solved patch: its reference point in track, rail-profile, wheelset and
/// wheel-profile coordinates, creepages, forces in track and wheelset coordinates, moments about
/// the rail and wheel markers (physics.md §13.6), and the solution itself.
WheelRailPatch describe_patch(const model::WheelRailProblem& p, const PlacedProfiles& prof,
                              const WheelsetPose& pose, const PatchSetup& s, Solution sol);

/// A patch's normal and lateral force in its planar frame (the one turned by the contact angle)
/// [N]: a conformal patch's BAR forces, a planar patch's FN, FS.
struct PlanarForces {
  double fn = 0.0, fs = 0.0;
};
inline PlanarForces planar_forces(const WheelRailPatch& w) {
  if (w.conformal.active) return {w.conformal.bar_fn, w.conformal.bar_fs};
  return {w.solution.totals.fn, w.solution.totals.fy};
}

/// A conformal patch's BAR forces of its pressure alone (Σ p_n turned by each row's α − δ),
/// without the tangential tractions' share [N]; planar_forces() for a planar patch's FN, 0.
PlanarForces pressure_part(const WheelRailPatch& w);

/// The rail and wheel markers of the placement (physics.md §13.2).
void describe_markers(const model::WheelRailProblem& p, const PlacedProfiles& prof,
                      const WheelsetPose& pose, WheelRailSolution& out);

/// A left wheel is computed as a right one; its lateral components change sign.
void mirror_to_left(WheelRailSolution& s);

/// The contact area of a patch's solution on the super grid (its elements with pressure).
SuperGridBox contact_box(const Solution& s, const PatchSetup& setup);

/// The pitch moment on the rail about the wheelset's axle, in wheelset coordinates [N·mm]: the
/// moment about the wheel marker m plus m × F (F=2's MY_WS). The marker lies about the wheel's
/// radius below the axle, so M_y ≈ r·F_x(ws).
double axle_pitch_moment(const WheelRailSolution& s);

/// Linear theory's d(F_x/F_z)/dVPITCH [s/rad] (spec-additions §A6): Σ G·a·b·C11·r/|V| over the
/// patches (a, b the equivalent ellipse of each patch's contact, G and ν its combined constants),
/// r the distance of the contact point below the axle, over F_z.
double linear_pitch_slope(const WheelRailSolution& s, double v);

/// A left wheel's inputs are given in its mirrored frame (y towards its field side); the
/// geometry is computed for a right wheel, so the lateral inputs change sign here and the
/// lateral outputs in mirror_to_left().
model::WheelRailProblem as_right_side(model::WheelRailProblem p);

}  // namespace rollcontact::wheelrail
