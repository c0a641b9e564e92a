#pragma once
// Contact search D=2 (spec/physics.md §13.3): the contact locus of the wheel (for every lateral
// position the wheel point whose surface normal is perpendicular to the track), the gap between
// rail and locus on a uniform lateral grid (spacing 0.3·DS), the interpenetration regions with
// their weighted reference points and contact angles, and their combination into patches.

#include <vector>

#include "rollcontact/model/wheelrail.hpp"
#include "wheelrail/placed_profiles.hpp"
#include "wheelrail/sliced_weights.hpp"
#include "wheelrail/wheelset_pose.hpp"

namespace rollcontact::wheelrail {

/// The gap function on the lateral grid (track coordinates).
struct GapFunction {
  double y0_mm = 0.0, dy_mm = 0.0;  ///< y_j = y0 + j·dy
  std::vector<double> gap;          ///< rail z − locus z [mm]; +huge where there is no wheel
  std::vector<double> x_locus;      ///< x of the locus point [mm]
  std::vector<double> wheel_y;      ///< wheel-profile y of the locus point [mm]
  std::vector<double> rail_angle;   ///< rail surface inclination atan(dz/dy) [rad]
  double y(std::size_t j) const { return y0_mm + dy_mm * static_cast<double>(j); }
};

/// Lateral and vertical extent of one of the regions a patch was combined from [mm].
struct RegionExtent {
  double y_min = 0.0, y_max = 0.0, z_min = 0.0, z_max = 0.0;
};

/// One contact region: where the wheel and the rail interpenetrate, or a combination of them.
struct ContactRegion {
  std::size_t first = 0, last = 0;  ///< gap samples, one guard sample each side included
  Vec3 reference;                   ///< weighted reference point on the rail [mm]
  double delta_rad = 0.0;           ///< contact angle: weighted rail inclination
  double x_min = 0.0, x_max = 0.0;  ///< longitudinal extent of the interpenetration [mm]
  double y_min = 0.0, y_max = 0.0;  ///< lateral extent (samples first..last) [mm]
  double z_min = 0.0, z_max = 0.0;  ///< vertical extent of the rail surface there [mm]
  double min_gap = 0.0;             ///< deepest interpenetration (negative) [mm]
  int regions = 1;                  ///< interpenetration regions combined into this one
  /// Its reference angle was turned towards a neighbour between D_SEP and D_TURN.
  bool angle_turned = false;
  /// The region's own angle, before any turning (= delta_rad when not turned).
  double delta_own_rad = 0.0;
  double weight = 0.0;                  ///< Σ w of the samples
  double wx = 0.0, wy = 0.0, wd = 0.0;  ///< Σ w·x_lc, Σ w·y, Σ w·α (for combination)
  /// Regions combined at a distance D_COMB < d ≤ D_SEP, by lateral position: their influence on
  /// each other is attenuated (factors, row-major parts × parts; physics.md §13.3 step 5).
  /// Empty when the patch is one region or fully combined ones.
  std::vector<RegionExtent> parts;
  std::vector<double> part_factors;
};

struct SearchResult {
  GapFunction gap;
  std::vector<ContactRegion> patches;  ///< by decreasing lateral position, at most 10
  double min_gap_mm = 0.0;             ///< smallest gap anywhere (the start of contact)
  /// The smallest gap between the samples: the vertex of the parabola through the smallest
  /// sample and its neighbours (min_gap_mm where that is not a minimum) [mm]. The smallest
  /// sample overestimates it by up to the gap's curvature times (dy/2)², depending on where the
  /// samples fall; the vertex does not.
  double min_gap_between_samples_mm = 0.0;
  double delta_at_min_rad = 0.0;        ///< rail inclination where the gap is smallest
  double curvature_at_min = 0.0;        ///< d²g/dy² / 2 there [1/mm] (lateral Hertz curvature)
  bool minimum_at_profile_end = false;  ///< the deepest local minimum is at a rail profile end
};

/// What the gap function needs that does not change with the wheelset height z_ws: the rail
/// surface at every lateral sample and the wheel's contact locus at z_ws = 0 (the height moves
/// the wheel vertically only, so the locus at z_ws is this one shifted by z_ws). Made once per
/// case, used by every iterate of the vertical-force iteration.
struct GapSamples {
  GapFunction base;             ///< grid, x of the locus and rail inclination (gap unset)
  std::vector<double> rail_z;   ///< rail height per sample [mm] (NaN: outside the rail)
  std::vector<double> locus_z;  ///< locus height at z_ws = 0 [mm] (−huge: no wheel)
  /// A roller or sliced rail: how much lower the rail's surface lies under the locus than its
  /// section at x = 0 [mm]; empty for a prismatic rail.
  std::vector<double> rail_drop;
  /// The wheel profile sampled for the locus (every wheel_step_mm in y): it does not depend on
  /// the wheelset's pose, so cases with the same profiles and DS reuse it (plain wheels only;
  /// a sliced wheel's cross-section changes with its rotation).
  std::vector<CurvePoint> wheel_points;
  double wheel_step_mm = 0.0;
  double wheel_radius_max_mm = 0.0;  ///< max |r0 + z| over wheel_points [mm]
  /// A sliced wheel: its pose at z_ws = 0 and, per lateral sample, its height along x there
  /// (the reference point's weights, sliced_weights.hpp). Filled by search_contact for the
  /// samples that interpenetrate, when first needed; empty for a plain wheel.
  WheelsetPose pose_at_zero;
  std::vector<HeightsAlongX> heights_along_x;
};

/// Weight of one interpenetrating gap sample of depth pen [mm] with the rolling curvature c
/// [1/mm] (the gap along x is c·x² − pen): ∫ g² dx (GAPWGT = 0) or ∫ −g dx (GAPWGT = 1) over
/// the interpenetrated length (spec/physics.md §13.3 step 4).
double gap_sample_weight(double pen_mm, double c_per_mm, bool linear);

/// The combined curvature of the two surfaces along the rolling direction, 1/(2·NOMRADW) (+
/// 1/(2·NOMRADR) on a roller rig; an internal roller's negative radius lowers it) [1/mm]: the
/// weights of the reference point and the patch's length.
double rolling_curvature_per_mm(const model::WheelRailProblem& problem);
/// The rail part (grid, heights, inclinations): the same for every case with the same rail
/// placement and DS.
GapSamples sample_rail(const model::WheelRailProblem& problem, const PlacedProfiles& profiles);
/// Fills in the wheel's locus of a case (its pose at z_ws = 0).
void sample_wheel(const model::WheelRailProblem& problem, const PlacedProfiles& profiles,
                  const WheelsetPose& pose_at_zero, GapSamples& samples);

/// Runs the search at wheelset height z_ws [mm]. No exception for a miss: no patches. A sliced
/// wheel's heights along x are added to `samples` where they are first needed.
SearchResult search_contact(const model::WheelRailProblem& problem, const PlacedProfiles& profiles,
                            GapSamples& samples, double z_ws_mm);

}  // namespace rollcontact::wheelrail
