// Where contact starts (iterate 0 of the vertical-force iteration, and the origin of the
// approach from which a sweep's next case starts): the gap is sampled every 0.3·DS, and its
// smallest sample lies above the true minimum by up to half the gap's second derivative times
// (dy/2)², depending on where the samples fall. The vertex of the parabola through the smallest
// sample and its neighbours does not depend on that. A cone on a 300 mm crown: changing the
// conicity moves the contact along the crown (by r·Δc) across one sample spacing.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "wheelrail/contact_search.hpp"
#include "wheelrail/placed_profiles.hpp"
#include "wheelrail/wheelset_pose.hpp"
#include "wheelrail_problems.hpp"

namespace rollcontact::wheelrail {
namespace {

SearchResult search_at_zero(const model::WheelRailProblem& p) {
  const PlacedProfiles prof(p);
  GapSamples samples = sample_rail(p, prof);
  sample_wheel(p, prof, pose_of(p, prof, 0.0), samples);
  return search_contact(p, prof, samples, 0.0);
}

TEST(ContactStart, TheParabolaThroughTheSmallestSamplesFindsTheMinimum) {
  double worst_sample = 0.0, worst_vertex = 0.0;
  for (int k = 0; k < 8; ++k) {
    // The contact lies where the crown's slope is the cone's: 0.0375 mm further per step, eight
    // steps across the coarse search's sample spacing of 0.3 mm.
    model::WheelRailProblem p = test_support::crowned_rail_problem(300.0, 0.05 + 1.25e-4 * k);
    p.search.ds_mm = 1.0;
    const SearchResult coarse = search_at_zero(p);
    // Reference: samples 3 µm apart, whose smallest lies within 1e-8 mm of the minimum.
    p.search.ds_mm = 0.01;
    const SearchResult fine = search_at_zero(p);
    ASSERT_LT(fine.min_gap_mm, 1e20);
    EXPECT_GE(coarse.min_gap_mm, fine.min_gap_mm - 1e-8) << "step " << k;
    worst_sample = std::max(worst_sample, std::abs(coarse.min_gap_mm - fine.min_gap_mm));
    worst_vertex =
        std::max(worst_vertex, std::abs(coarse.min_gap_between_samples_mm - fine.min_gap_mm));
  }
  // (1/300)/2 · (0.15 mm)² = 3.8e-5 mm at most for the smallest sample; its error shows.
  EXPECT_GT(worst_sample, 1e-5);
  EXPECT_LT(worst_sample, 4e-5);
  // The vertex is exact for a parabola: what remains (5.6e-9 mm) is the reference's own
  // sampling error (up to 4e-9 mm) and the crown's quartic term.
  EXPECT_LT(worst_vertex, 2e-8);
}

}  // namespace
}  // namespace rollcontact::wheelrail
