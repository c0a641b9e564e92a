// Creep-force lookup tables (include/rollcontact/creep_lookup.hpp): the interpolation is exact
// at the nodes and for functions multilinear in (ln a/b, ξ̃, η̃, φ̃), keeps the creepage direction
// outside the table, scales to physical units by the stated normalisation, rejects malformed
// grids, and survives an HDF5 round trip bit for bit; files that are not tables are refused
// with their name.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <vector>

#include "rollcontact/creep_lookup.hpp"
#include "rollcontact/errors.hpp"
#include "support/files.hpp"

namespace rollcontact {
namespace {

/// A table whose values are a function multilinear in (ln a/b, ξ̃, η̃, φ̃).
CreepLookupValue multilinear(double ab, double x, double y, double z) {
  const double l = std::log(ab);
  return {0.1 + 0.3 * x - 0.2 * y + 0.05 * x * y * z + 0.07 * l * x,
          -0.4 * y + 0.1 * z + 0.02 * l * y * z, 0.3 * z - 0.01 * x * y + 0.05 * l};
}

CreepLookupTable test_table() {
  CreepLookupAxes ax;
  ax.a_over_b = {0.25, 0.5, 1.0, 4.0};
  ax.ksi = {-1.0, -0.3, 0.0, 0.2, 1.0};
  ax.eta = {-1.0, 0.0, 0.5, 1.0};
  ax.phi = {-2.0, 0.0, 3.0};
  std::vector<CreepLookupValue> v;
  for (double ab : ax.a_over_b)
    for (double x : ax.ksi)
      for (double y : ax.eta)
        for (double z : ax.phi) v.push_back(multilinear(ab, x, y, z));
  return CreepLookupTable(ax, v, {"exact", 11, 0.28, "test"});
}

TEST(CreepLookup, ExactAtNodesAndForMultilinearFunctions) {
  const CreepLookupTable t = test_table();
  const CreepLookupAxes& ax = t.axes();
  for (std::size_t a = 0; a < ax.a_over_b.size(); ++a)
    for (std::size_t i = 0; i < ax.ksi.size(); ++i) {
      const CreepLookupValue v = t.evaluate(ax.a_over_b[a], ax.ksi[i], ax.eta[1], ax.phi[2]);
      const CreepLookupValue e = t.values()[t.node_index(a, i, 1, 2)];
      EXPECT_EQ(v.fx, e.fx);
      EXPECT_EQ(v.fy, e.fy);
      EXPECT_EQ(v.mz, e.mz);
    }
  for (const double ab : {0.3, 0.7, 2.2})
    for (const double x : {-0.9, -0.1, 0.15, 0.6})
      for (const double y : {-0.4, 0.3, 0.77})
        for (const double z : {-1.5, 0.5, 2.9}) {
          const CreepLookupValue v = t.evaluate(ab, x, y, z), e = multilinear(ab, x, y, z);
          EXPECT_NEAR(v.fx, e.fx, 1e-14);
          EXPECT_NEAR(v.fy, e.fy, 1e-14);
          EXPECT_NEAR(v.mz, e.mz, 1e-14);
        }
}

TEST(CreepLookup, OutsideTheBoxTheCreepageDirectionIsKept) {
  const CreepLookupTable t = test_table();
  // (4, 2) lies beyond ξ̃ = 1: it is evaluated at (1, 0.5), on the border, same direction.
  const CreepLookupValue far = t.evaluate(1.0, 4.0, 2.0, 0.0);
  const CreepLookupValue border = t.evaluate(1.0, 1.0, 0.5, 0.0);
  EXPECT_DOUBLE_EQ(far.fx, border.fx);
  EXPECT_DOUBLE_EQ(far.fy, border.fy);
  // a/b and φ̃ are clamped.
  EXPECT_DOUBLE_EQ(t.evaluate(100.0, 0.1, 0.1, 9.0).mz, t.evaluate(4.0, 0.1, 0.1, 3.0).mz);
}

TEST(CreepLookup, ForcesFollowTheNormalisation) {
  const CreepLookupTable t = test_table();
  const double a = 6.0, b = 4.0, fn = 50000.0, g = 80000.0, mu = 0.35;
  const double c = std::sqrt(a * b), ksi = 2e-4, eta = -1e-4, phi = 3e-5;
  const double s = g * c * c / (mu * fn);
  const CreepLookupValue v = t.evaluate(a / b, s * ksi, s * eta, s * c * phi);
  const CreepLookupForces f = t.forces(a, b, fn, g, mu, ksi, eta, phi);
  EXPECT_DOUBLE_EQ(f.fx_N, v.fx * mu * fn);
  EXPECT_DOUBLE_EQ(f.fy_N, v.fy * mu * fn);
  EXPECT_DOUBLE_EQ(f.mz_Nmm, v.mz * mu * fn * c);
  EXPECT_EQ(t.forces(a, b, 0.0, g, mu, ksi, eta, phi).fx_N, 0.0);  // no load, no force
}

TEST(CreepLookup, MalformedGridsAreRejected) {
  CreepLookupAxes ax{{1.0, 2.0}, {0.0, 1.0}, {0.0, 1.0}, {0.0, 1.0}};
  std::vector<CreepLookupValue> v(16);
  EXPECT_NO_THROW(CreepLookupTable(ax, v, {}));
  EXPECT_THROW(CreepLookupTable(ax, std::vector<CreepLookupValue>(15), {}), InvalidValueError);
  CreepLookupAxes bad = ax;
  bad.ksi = {1.0, 1.0};
  EXPECT_THROW(CreepLookupTable(bad, v, {}), InvalidValueError);
  bad = ax;
  bad.a_over_b = {0.0, 1.0};
  EXPECT_THROW(CreepLookupTable(bad, v, {}), InvalidValueError);
  v[3].fy = std::nan("");
  EXPECT_THROW(CreepLookupTable(ax, v, {}), InvalidValueError);
}

TEST(CreepLookup, Hdf5RoundTripIsBitExact) {
  namespace fs = std::filesystem;
  const test_support::ScratchDir scratch("rollcontact_lookup_test");
  const fs::path& dir = scratch.path();
  const CreepLookupTable t = test_table();
  save_creep_lookup(t, dir / "t.h5");
  EXPECT_FALSE(fs::exists(dir / "t.h5.part"));
  const CreepLookupTable back = load_creep_lookup(dir / "t.h5");
  EXPECT_EQ(back.axes().ksi, t.axes().ksi);
  EXPECT_EQ(back.axes().a_over_b, t.axes().a_over_b);
  EXPECT_EQ(back.info().method, "exact");
  EXPECT_EQ(back.info().mx, 11);
  EXPECT_EQ(back.info().software, "test");
  ASSERT_EQ(back.values().size(), t.values().size());
  for (std::size_t i = 0; i < t.values().size(); ++i) {
    EXPECT_EQ(back.values()[i].fx, t.values()[i].fx);
    EXPECT_EQ(back.values()[i].fy, t.values()[i].fy);
    EXPECT_EQ(back.values()[i].mz, t.values()[i].mz);
  }
  // Not a table: named in the message.
  std::ofstream(dir / "text.h5") << "hello";
  try {
    (void)load_creep_lookup(dir / "text.h5");
    FAIL() << "accepted a text file";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("text.h5"), std::string::npos);
  }
  EXPECT_THROW((void)load_creep_lookup(dir / "missing.h5"), InputError);
}

}  // namespace
}  // namespace rollcontact
