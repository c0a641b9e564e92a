// The C interface of creep-force lookup tables (include/rollcontact/creep_lookup.h) from
// librollcontact_cntc.so: the values of the C++ table, physical units, and errors that name
// the file instead of crashing.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "rollcontact/creep_lookup.h"
#include "rollcontact/creep_lookup.hpp"
#include "support/files.hpp"

namespace {

using namespace rollcontact;

CreepLookupTable make_table() {
  CreepLookupAxes ax{{0.5, 1.0, 2.0}, {-1.0, 0.0, 0.4, 1.0}, {-1.0, 0.0, 1.0}, {-1.0, 0.0, 1.0}};
  std::vector<CreepLookupValue> v;
  for (double ab : ax.a_over_b)
    for (double x : ax.ksi)
      for (double y : ax.eta)
        for (double z : ax.phi)
          v.push_back({-std::tanh(2 * x) / ab, -std::tanh(y + 0.3 * z), 0.1 * z});
  return CreepLookupTable(ax, v, {"exact", 9, 0.28, "test"});
}

TEST(CreepLookupC, EvaluatesAsTheCppTable) {
  const test_support::ScratchDir scratch("rc_lookup_c");
  const std::filesystem::path path = scratch / "rc_lookup_c.h5";
  const CreepLookupTable t = make_table();
  save_creep_lookup(t, path);
  char error[256] = "x";
  rc_creep_lookup* c = rc_creep_lookup_open(path.c_str(), error, sizeof error);
  ASSERT_NE(c, nullptr) << error;
  EXPECT_STREQ(error, "");
  for (const double ab : {0.6, 1.0, 1.7})
    for (const double x : {-0.7, 0.1, 0.5, 3.0}) {
      double out[3];
      rc_creep_lookup_eval(c, ab, x, 0.2, -0.4, out);
      const CreepLookupValue v = t.evaluate(ab, x, 0.2, -0.4);
      EXPECT_EQ(out[0], v.fx);
      EXPECT_EQ(out[1], v.fy);
      EXPECT_EQ(out[2], v.mz);
    }
  double f[3];
  rc_creep_lookup_forces(c, 6.0, 4.0, 5e4, 8e4, 0.3, 1e-4, 0.0, 0.0, f);
  const CreepLookupForces e = t.forces(6.0, 4.0, 5e4, 8e4, 0.3, 1e-4, 0.0, 0.0);
  EXPECT_EQ(f[0], e.fx_N);
  EXPECT_EQ(f[2], e.mz_Nmm);
  rc_creep_lookup_close(c);
}

TEST(CreepLookupC, ErrorsNameTheFile) {
  char error[256];
  EXPECT_EQ(rc_creep_lookup_open("/nonexistent/table.h5", error, sizeof error), nullptr);
  EXPECT_NE(std::string(error).find("/nonexistent/table.h5"), std::string::npos) << error;
  EXPECT_EQ(rc_creep_lookup_open(nullptr, nullptr, 0), nullptr);
  double out[3] = {1, 1, 1};
  rc_creep_lookup_eval(nullptr, 1, 0, 0, 0, out);  // no table: zeros, no crash
  EXPECT_EQ(out[0], 0.0);
  rc_creep_lookup_close(nullptr);
}

}  // namespace
