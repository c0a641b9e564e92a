// The rigid slip per step (physics.md §9): w_x = ξ − φ·y, w_y = η + φ·x, and CONTACT's
// experimental E = 2, 3 that drop the spin term from w_y or from w_x.

#include <gtest/gtest.h>

#include "tangential/kinematics.hpp"

namespace rollcontact::tangential {
namespace {

model::PatchProblem steady(model::SpinInRigidSlip terms) {
  model::PatchProblem p;
  p.tangential.kind = model::TangentialKind::SteadyRolling;
  p.tangential.spin_terms = terms;
  p.rolling.spin_offset_factor = 0.0;  // spin evaluated at the element centres
  return p;
}

TEST(RigidSlip, SpinTermsDroppedOneComponentAtATime) {
  Grid g;
  g.mx = 5;
  g.my = 4;
  g.xl = -2.5;
  g.yl = -1.0;
  g.dx = 1.0;
  g.dy = 0.5;
  EffectiveKinematics kin;
  kin.dq = 0.2;
  const double ksi = 1e-3, eta = -2e-3, phi = 5e-4;
  const RigidShift both = rigid_shift(g, steady(model::SpinInRigidSlip::Both), kin, ksi, eta, phi);
  const RigidShift no_y =
      rigid_shift(g, steady(model::SpinInRigidSlip::LongitudinalOnly), kin, ksi, eta, phi);
  const RigidShift no_x =
      rigid_shift(g, steady(model::SpinInRigidSlip::LateralOnly), kin, ksi, eta, phi);
  for (int iy = 0; iy < g.my; ++iy)
    for (int ix = 0; ix < g.mx; ++ix) {
      const std::size_t i = g.index(ix, iy);
      const double x = g.x_centre(ix), y = g.y_centre(iy);
      EXPECT_DOUBLE_EQ(both.wx[i], kin.dq * (ksi - phi * y));
      EXPECT_DOUBLE_EQ(both.wy[i], kin.dq * (eta + phi * x));
      EXPECT_DOUBLE_EQ(no_y.wx[i], both.wx[i]);  // E = 2: w_y = η
      EXPECT_DOUBLE_EQ(no_y.wy[i], kin.dq * eta);
      EXPECT_DOUBLE_EQ(no_x.wx[i], kin.dq * ksi);  // E = 3: w_x = ξ
      EXPECT_DOUBLE_EQ(no_x.wy[i], both.wy[i]);
    }
}

}  // namespace
}  // namespace rollcontact::tangential
