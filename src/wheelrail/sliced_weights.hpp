#pragma once
// The weights of the reference point of a sliced wheel (an out-of-round wheel, a wheel flat:
// spec/physics.md §13.3 step 4 and §13.9). On a round wheel the gap along x at a lateral sample
// is the parabola c·x² − pen about the locus point, and its weight ∫ g² dx (GAPWGT = 0) or
// ∫ −g dx (GAPWGT = 1) over the interpenetration has a closed form. A sliced wheel's surface
// along x is not a parabola — near a flat it is flat-bottomed or has two edges — so the same
// integrals are taken over the wheel's actual height along the line x at that sample: the
// weight, its first moment in x (the sample's x in the weighted centre) and the interpenetrated
// x-range (the patch's length). docs/decisions.md, "Variable wheel profiles".

#include <vector>

#include "wheelrail/placed_profiles.hpp"
#include "wheelrail/wheelset_pose.hpp"

namespace rollcontact::wheelrail {

/// The wheel's lower surface along one line x at a lateral sample, at z_ws = 0: heights
/// z(x_k) [mm, down] at x_k = x0 + k·step (NaN where the line misses the wheel).
struct HeightsAlongX {
  double x0_mm = 0.0, step_mm = 0.0;
  std::vector<double> z;
  bool empty() const noexcept { return z.empty(); }
};

/// Half the widest window the heights are sampled over: 0.08·r0 (that of the sliced locus,
/// beyond a flat's half-length) [mm].
double full_window_mm(const PlacedProfiles& profiles);

/// Samples the wheel at track position y over x ∈ x_centre ± half_window_mm (at most
/// full_window_mm) every `step_mm`, starting each vertical line's search at `z_start` (the locus
/// height there).
HeightsAlongX wheel_heights_along_x(const PlacedProfiles& profiles,
                                    const WheelsetPose& pose_at_zero, double y_mm,
                                    double x_centre_mm, double z_start, double step_mm,
                                    double half_window_mm);

/// ∫ w(pen) dx and ∫ w(pen)·x dx with pen = z_wheel + z_ws − z_rail > 0 (w = pen², or pen for
/// linear weights), and the x-range where pen > 0 [mm]. weight = 0: no interpenetration.
struct SampleMoments {
  double weight = 0.0, weight_x = 0.0;
  double x_min = 0.0, x_max = 0.0;
};

SampleMoments gap_moments_along_x(const HeightsAlongX& wheel, double rail_z_mm, double z_ws_mm,
                                  bool linear_weights);

/// True when the interpenetration reaches the first or the last line: the window was too short.
bool reaches_window_end(const HeightsAlongX& wheel, const SampleMoments& moments);

}  // namespace rollcontact::wheelrail
