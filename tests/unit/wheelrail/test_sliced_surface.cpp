// The wheel surface from slices (physics.md §13.9, spec-additions §A9): identical slices give the
// plain profile; a flat of known depth gives that depth at its angle (interpolating) or the
// B-spline average of its neighbours (approximating); θ is periodic and constant beyond the data.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "wheelrail/profile_curve.hpp"
#include "wheelrail/sliced_surface.hpp"
#include "wheelrail_problems.hpp"

namespace rollcontact::wheelrail {
namespace {

/// A tread with a rounded flange root: smooth, monotone in y (wheel order, descending y).
double tread_z(double y) {
  return -0.025 * y + (y < -20.0 ? 0.02 * (y + 20.0) * (y + 20.0) : 0.0);
}

Profile tread(double depth_mm) {
  Profile p = test_support::sampled_profile(tread_z, -40.0, 60.0, 0.5, true);
  for (double& z : p.z) z -= depth_mm;  // a smaller radius: z up
  return p;
}

model::ProfileSmoothing smoothing_with(double lambda) {
  model::ProfileSmoothing s;
  s.smooth = lambda;
  return s;
}

SlicedProfile slices_of(const std::vector<double>& theta,
                        const std::function<double(double)>& depth, int intpol) {
  SlicedProfile s;
  s.file = "slices (test)";
  s.u_intpol = intpol;
  s.u = theta;
  for (double th : theta) s.slices.push_back(tread(depth(th)));
  return s;
}

TEST(SlicedSurface, IdenticalSlicesAreThePlainProfile) {
  const model::ProfileSmoothing smoothing = smoothing_with(5.0);
  const ProfileCurve plain(model::WheelRailProfile{tread(0.0), smoothing, {}}, false);
  for (int intpol : {1, 2}) {
    const SlicedSurface surface(
        slices_of(
            {-3.0, -1.2, 0.0, 0.4, 1.1, 3.1}, [](double) { return 0.0; }, intpol),
        smoothing);
    for (double th : {-3.1, -2.0, 0.0, 0.2, 0.77, 3.0})
      for (double y : {-35.0, -20.3, -5.0, 0.0, 12.7, 55.0}) {
        const SurfacePoint p = surface.at(th, y);
        const CurvePoint c = plain.at_y(y);
        ASSERT_TRUE(p.found);
        EXPECT_NEAR(p.z, c.z, 1e-6) << "intpol " << intpol << " θ " << th << " y " << y;
        EXPECT_NEAR(p.dz_dy, c.dz_dy, 1e-5);
        EXPECT_NEAR(p.dz_du, 0.0, 1e-9);
      }
    EXPECT_FALSE(surface.at(0.0, 61.0).found);
    EXPECT_FALSE(surface.at(0.0, -41.0).found);
  }
}

TEST(SlicedSurface, AFlatHasItsDepthAtItsAngle) {
  // A flat of depth D at θ0 on a wheel of radius R: the radius drops by R − (R − D)/cos(θ − θ0)
  // within the half-angle acos(1 − D/R). Slices every 0.01 rad around the whole wheel.
  const double R = 490.0, D = 1.2, th0 = 0.65, half = std::acos(1.0 - D / R);
  const auto depth = [&](double th) {
    const double d = th - th0;
    return std::abs(d) < half ? R - (R - D) / std::cos(d) : 0.0;
  };
  std::vector<double> theta;
  for (int i = -314; i <= 314; ++i) theta.push_back(0.01 * i);
  const model::ProfileSmoothing smoothing = smoothing_with(0.0);
  const double z_round = SlicedSurface(slices_of(theta, depth, 1), smoothing).at(-2.0, 10.0).z;
  EXPECT_NEAR(z_round, tread_z(10.0), 1e-6);

  // Interpolating: through every slice, so the full depth at the flat's centre.
  const SlicedSurface interp(slices_of(theta, depth, 1), smoothing);
  EXPECT_NEAR(interp.at(th0, 10.0).z, z_round - D, 1e-6);
  EXPECT_NEAR(interp.at(th0 + 0.02, 10.0).z, z_round - depth(th0 + 0.02), 1e-6);
  // Slope in θ along the flat: ∂z/∂θ = −d'(θ) = (R − D) sin/cos² (the radius grows away).
  const double d = 0.015;
  EXPECT_NEAR(interp.at(th0 + d, 10.0).dz_du, (R - D) * std::sin(d) / (std::cos(d) * std::cos(d)),
              1e-2);  // 0.1 %: spline in θ

  // Approximating: the B-spline with the slices as control points averages neighbours
  // (1, 4, 1)/6 at a slice: the depth there is D − (R − D)·h²/6 for the flat's parabola.
  const SlicedSurface approx(slices_of(theta, depth, 2), smoothing);
  const double h = 0.01;
  const double expected = (depth(th0 - h) + 4.0 * depth(th0) + depth(th0 + h)) / 6.0;
  EXPECT_NEAR(approx.at(th0, 10.0).z, z_round - expected, 1e-6);
  EXPECT_NEAR(expected, D - (R - D) * h * h / 6.0, 1e-6);

  // Periodic in θ.
  EXPECT_NEAR(interp.at(th0 + 2.0 * std::numbers::pi, 10.0).z, interp.at(th0, 10.0).z, 1e-9);
}

TEST(SlicedSurface, ConstantBeyondTheSlicesCovered) {
  const model::ProfileSmoothing smoothing = smoothing_with(0.0);
  const auto depth = [](double th) { return 0.1 * th; };
  std::vector<double> theta;
  for (int i = -10; i <= 10; ++i) theta.push_back(0.1 * i);
  for (int intpol : {1, 2}) {
    const SlicedSurface s(slices_of(theta, depth, intpol), smoothing);
    EXPECT_NEAR(s.at(-2.5, 0.0).z, tread_z(0.0) + 0.1, 1e-6);
    EXPECT_NEAR(s.at(2.5, 0.0).z, tread_z(0.0) - 0.1, 1e-6);
    EXPECT_EQ(s.at(2.5, 0.0).dz_du, 0.0);
    EXPECT_NEAR(s.at(0.25, 0.0).z, tread_z(0.0) - 0.025, 1e-6);  // linear stays linear (interior)
  }
}

TEST(SlicedSurface, CrossSectionIsTheProfileAtThatAngle) {
  const model::ProfileSmoothing smoothing = smoothing_with(0.0);
  const auto depth = [](double th) { return 0.2 * std::sin(th); };
  std::vector<double> theta;
  for (int i = -32; i <= 32; ++i) theta.push_back(0.1 * i);
  const SlicedSurface s(slices_of(theta, depth, 1), smoothing);
  const Profile p = s.cross_section(0.3);
  ASSERT_GT(p.y.size(), 100u);
  EXPECT_GT(p.y.front(), p.y.back());  // wheel order
  for (std::size_t k = 0; k < p.y.size(); k += 37) EXPECT_NEAR(p.z[k], s.at(0.3, p.y[k]).z, 1e-9);
}

}  // namespace
}  // namespace rollcontact::wheelrail
