// Building creep-force lookup tables (batch/creep_lookup_build.hpp): the table's values at its
// own nodes are the method's solutions, the linear regime follows Kalker's coefficients, the
// forces are odd in the creepages, and the distributed build equals the threaded one.

#include <gtest/gtest.h>

#include <cmath>

#include "batch/creep_lookup_build.hpp"
#include "simplified/kalker_coefficients.hpp"

namespace rollcontact::batch {
namespace {

CreepLookupAxes small_axes() {
  return {{0.5, 1.0, 2.0}, {-0.3, -0.01, 0.0, 0.01, 0.3}, {-0.2, 0.0, 0.2}, {0.0, 0.5}};
}

TableSettings exact11() {
  TableSettings s;
  s.mx = 11;
  return s;
}

TEST(CreepLookupBuild, NodesAreTheExactSolutions) {
  const CreepLookupAxes ax = small_axes();
  const CreepLookupTable t = build_creep_lookup(ax, exact11(), 2);
  ASSERT_EQ(t.values().size(), 3u * 5u * 3u * 2u);
  EXPECT_EQ(t.info().method, "exact");
  EXPECT_EQ(t.info().mx, 11);
  for (std::size_t a = 0; a < 3; ++a)
    for (std::size_t i = 0; i < 5; ++i)
      for (std::size_t j = 0; j < 3; ++j)
        for (std::size_t k = 0; k < 2; ++k) {
          PatchSolver fresh;
          const CreepLookupValue e =
              solve_lookup_node(ax.a_over_b[a], ax.ksi[i], ax.eta[j], ax.phi[k], exact11(), fresh);
          const CreepLookupValue v = t.evaluate(ax.a_over_b[a], ax.ksi[i], ax.eta[j], ax.phi[k]);
          // The same solution up to the solver tolerance (warm operator caches differ in
          // rounding only): 1e-6 of μFN.
          EXPECT_NEAR(v.fx, e.fx, 1e-6);
          EXPECT_NEAR(v.fy, e.fy, 1e-6);
          EXPECT_NEAR(v.mz, e.mz, 1e-6);
        }
}

TEST(CreepLookupBuild, LinearRegimeFollowsKalkerAndForcesAreOdd) {
  const CreepLookupTable t = build_creep_lookup(small_axes(), exact11(), 2);
  for (const double ab : {0.5, 1.0, 2.0}) {
    // F_x = −G c² C11 ξ, i.e. fx = −C11·ξ̃, for small creepage (11×11 elements: within 6 %).
    const double c11 = simplified::kalker_coefficients(ab, 0.28).c11;
    const CreepLookupValue v = t.evaluate(ab, 0.01, 0.0, 0.0);
    EXPECT_NEAR(v.fx / (-c11 * 0.01), 1.0, 0.06) << ab;
    EXPECT_NEAR(v.fy, 0.0, 1e-6);  // zero up to the solver tolerance
    const CreepLookupValue plus = t.evaluate(ab, 0.3, 0.2, 0.0);
    const CreepLookupValue minus = t.evaluate(ab, -0.3, -0.2, 0.0);
    EXPECT_NEAR(plus.fx, -minus.fx, 1e-6);
    EXPECT_NEAR(plus.fy, -minus.fy, 1e-6);
    EXPECT_LE(std::hypot(plus.fx, plus.fy), 1.0 + 1e-6);  // never beyond μFN
  }
}

TEST(CreepLookupBuild, OneProcessDistributionEqualsThreads) {
  SerialDistribution one;
  const CreepLookupTable a = build_creep_lookup(small_axes(), exact11(), 2);
  const CreepLookupTable b = build_creep_lookup(small_axes(), exact11(), 1, &one);
  ASSERT_EQ(a.values().size(), b.values().size());
  for (std::size_t i = 0; i < a.values().size(); ++i) {
    EXPECT_NEAR(a.values()[i].fx, b.values()[i].fx, 1e-6);
    EXPECT_NEAR(a.values()[i].fy, b.values()[i].fy, 1e-6);
  }
  const LookupAccuracy acc = held_back_accuracy(a, exact11(), 10, 3u, 2);
  EXPECT_EQ(acc.points, 10u);
  EXPECT_GE(acc.max_force_error, acc.rms_force_error);
  EXPECT_LT(acc.max_force_error, 0.5);  // a coarse 3×5×3×2 grid still interpolates sensibly
}

}  // namespace
}  // namespace rollcontact::batch
