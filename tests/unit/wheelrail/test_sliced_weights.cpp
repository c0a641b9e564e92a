// The weight integrals of a sliced wheel's lateral sample (sliced_weights.hpp) on heights given
// by hand: a parabola gives the closed form of physics.md §13.3 step 4 and its vertex as the
// centre; a flat-bottomed profile is weighted by its actual shape.

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "wheelrail/contact_search.hpp"
#include "wheelrail/sliced_weights.hpp"

namespace rollcontact::wheelrail {
namespace {

/// Heights z(x) = z_of(x) [mm, down] every `step` mm on x ∈ [−40, 40].
HeightsAlongX heights(const std::function<double(double)>& z_of, double step) {
  HeightsAlongX h;
  h.step_mm = step;
  h.x0_mm = -40.0;
  for (double x = -40.0; x <= 40.0 + 1e-9; x += step) h.z.push_back(z_of(x));
  return h;
}

TEST(SlicedWeights, ParabolaGivesTheClosedFormAndItsVertex) {
  // A wheel whose lowest point is at x = 1.5: z = −c (x − 1.5)², rail at z = 0, lowered by pen.
  const double c = 1.0 / (2.0 * 460.0), pen = 0.1, shift = 1.5;
  const HeightsAlongX h = heights([&](double x) { return -c * (x - shift) * (x - shift); }, 0.01);
  for (const bool linear : {false, true}) {
    const SampleMoments m = gap_moments_along_x(h, 0.0, pen, linear);
    // The rectangle rule on a smooth integrand vanishing at the ends: O(step²) relative.
    EXPECT_NEAR(m.weight, gap_sample_weight(pen, c, linear),
                1e-4 * gap_sample_weight(pen, c, linear));
    EXPECT_NEAR(m.weight_x / m.weight, shift, 1e-6);
    const double t0 = std::sqrt(pen / c);
    EXPECT_NEAR(m.x_min, shift - t0, 0.01);
    EXPECT_NEAR(m.x_max, shift + t0, 0.01);
  }
}

TEST(SlicedWeights, FlatBottomWeighsItsWholeLength) {
  // Interpenetration 0.1 mm on x ∈ [0, 10] and nowhere else (a step profile): weight
  // 0.1²·10 = 0.1 mm³, centre 5 mm, linear weight 1 mm².
  const HeightsAlongX h = heights([](double x) { return x >= 0.0 && x <= 10.0 ? 0.1 : -1.0; }, 0.5);
  const SampleMoments m = gap_moments_along_x(h, 0.0, 0.0, false);
  EXPECT_NEAR(m.weight, 0.01 * 10.5, 1e-12);  // 21 samples of 0.5 mm
  EXPECT_NEAR(m.weight_x / m.weight, 5.0, 1e-12);
  EXPECT_DOUBLE_EQ(m.x_min, 0.0);
  EXPECT_DOUBLE_EQ(m.x_max, 10.0);
  EXPECT_NEAR(gap_moments_along_x(h, 0.0, 0.0, true).weight, 0.1 * 10.5, 1e-12);
}

TEST(SlicedWeights, NoInterpenetrationAndMissedLinesWeighNothing) {
  HeightsAlongX h = heights([](double) { return -0.5; }, 1.0);
  h.z[40] = std::nan("");
  const SampleMoments m = gap_moments_along_x(h, 0.0, 0.2, false);
  EXPECT_EQ(m.weight, 0.0);
  EXPECT_EQ(m.x_min, 0.0);
  EXPECT_EQ(m.x_max, 0.0);
}

TEST(SlicedWeights, AnInterpenetrationAtTheWindowsEndAsksForAWiderOne) {
  // The parabola of ParabolaGivesTheClosedFormAndItsVertex interpenetrates over ±10.2 mm: a
  // window of ±40 mm holds it, one of ±8 mm is cut at both ends.
  const double c = 1.0 / (2.0 * 460.0), pen = 0.1;
  const auto z = [&](double x) { return -c * x * x; };
  const HeightsAlongX wide = heights(z, 0.5);
  EXPECT_FALSE(reaches_window_end(wide, gap_moments_along_x(wide, 0.0, pen, false)));
  HeightsAlongX narrow;
  narrow.step_mm = 0.5;
  narrow.x0_mm = -8.0;
  for (double x = -8.0; x <= 8.0 + 1e-9; x += 0.5) narrow.z.push_back(z(x));
  EXPECT_TRUE(reaches_window_end(narrow, gap_moments_along_x(narrow, 0.0, pen, false)));
  EXPECT_FALSE(reaches_window_end(narrow, gap_moments_along_x(narrow, 0.0, 0.01, false)));
}

}  // namespace
}  // namespace rollcontact::wheelrail
