// Contact search D=5 (spec-additions §A2): the vertical gap between rail and wheel minimised
// along x at every lateral sample. Checked against a dense scan along x, against the contact
// locus (D=2), which cannot find a deeper gap, and through the solver, where both searches give
// the same patch on a smooth geometry.

#include <gtest/gtest.h>

#include <cmath>

#include "rollcontact/wheelrail.hpp"
#include "wheelrail/contact_search.hpp"
#include "wheelrail/placed_profiles.hpp"
#include "wheelrail/wheelset_pose.hpp"
#include "wheelrail_problems.hpp"

namespace rollcontact::wheelrail {
namespace {

/// A cone on the crown, yawed by 20 mrad: its lowest points lie off the view direction.
model::WheelRailProblem yawed_cone() {
  model::WheelRailProblem p = test_support::crowned_rail_problem(300.0, 0.05);
  p.motion.y_mm = 1.0;
  p.motion.yaw_rad = 0.02;
  p.motion.roll_rad = 0.003;
  return p;
}

TEST(GapGrid, MicrometreElementsKeepTheSearchBounded) {
  // DS = 1e-5 mm asked for 0.3·DS samples: 20 million over the 60 mm crown and gigabytes with
  // the wheel's (std::bad_alloc, exit 3). The search is capped at 250,000 samples (at 0.2 mm it
  // takes its 0.06 mm spacing, 1,001 samples); the patch grid itself is coarsened by NPOT_MAX.
  model::WheelRailProblem p = test_support::crowned_rail_problem(300.0);
  const PlacedProfiles prof(p);
  EXPECT_EQ(sample_rail(p, prof).base.gap.size(), 1001U);
  p.search.dx_mm = p.search.ds_mm = 1e-5;
  const GapSamples tiny = sample_rail(p, prof);
  EXPECT_LE(tiny.base.gap.size(), 250001U);
  EXPECT_GE(tiny.base.gap.size(), 249999U);
}

TEST(GapGrid, EachSampleIsTheMinimumAlongX) {
  model::WheelRailProblem p = yawed_cone();
  p.search.method = model::ContactSearch::GapGrid;
  const PlacedProfiles prof(p);
  const WheelsetPose pose = pose_of(p, prof, 0.0);
  GapSamples grid = sample_rail(p, prof);
  sample_wheel(p, prof, pose, grid);
  const SearchResult s = search_contact(p, prof, grid, 0.0);
  model::WheelRailProblem q = yawed_cone();
  GapSamples locus = sample_rail(q, prof);
  sample_wheel(q, prof, pose, locus);
  const SearchResult l = search_contact(q, prof, locus, 0.0);
  int checked = 0;
  for (std::size_t j = 0; j < s.gap.gap.size(); j += 37) {
    if (!(s.gap.gap[j] < 1.0)) continue;  // within a millimetre of contact
    const double y = s.gap.y(j);
    // Dense scan: 0.002 mm steps over ±6 mm around the found x.
    double best = 1e30;
    for (int i = -3000; i <= 3000; ++i) {
      const double x = s.gap.x_locus[j] + 0.002 * i;
      double t = 0.0;
      if (!wheel_surface_along(prof, pose, Vec3{x, y, 0.0}, Vec3{0.0, 0.0, 1.0}, grid.locus_z[j],
                               t))
        continue;
      best = std::min(best, prof.rail_at_track_y(y).z - t);
    }
    EXPECT_NEAR(s.gap.gap[j], best, 1e-8) << "sample " << j;
    EXPECT_LE(s.gap.gap[j], l.gap.gap[j] + 1e-9) << "sample " << j;
    ++checked;
  }
  EXPECT_GT(checked, 10);
}

TEST(GapGrid, SameContactAsTheLocusOnASmoothGeometry) {
  model::WheelRailProblem p = yawed_cone();
  p.patch.tangential.kind = model::TangentialKind::SteadyRolling;
  p.vertical = model::VerticalLoading::Force;
  p.motion.fz_N = 10000.0;
  const WheelRailSolution a = WheelsetSolver().solve(p);
  p.search.method = model::ContactSearch::GapGrid;
  const WheelRailSolution b = WheelsetSolver().solve(p);
  ASSERT_TRUE(a.converged && b.converged);
  ASSERT_EQ(a.patches.size(), 1u);
  ASSERT_EQ(b.patches.size(), 1u);
  // The locus interpolates between wheel-profile circles 0.03 mm apart: a few µm of position.
  EXPECT_NEAR(b.patches[0].reference_tr.x, a.patches[0].reference_tr.x, 5e-3);
  EXPECT_NEAR(b.patches[0].reference_tr.y, a.patches[0].reference_tr.y, 5e-3);
  EXPECT_NEAR(b.z_ws_mm, a.z_ws_mm, 1e-4);
  EXPECT_NEAR(b.force_tr.y, a.force_tr.y, 5e-3 * std::abs(a.force_tr.y) + 2.0);
}

}  // namespace
}  // namespace rollcontact::wheelrail
