// Independent handles of the cntc_* library used from several threads at once (spec
// library-api.md §1.5): 4 threads × 100 calculations, each thread on its own result element,
// give exactly the results of the same calculations done one after another. Run under
// ThreadSanitizer in CI (preset tsan) as well as in the ordinary suite.

#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "rollcontact/contact_addon.h"

namespace {

constexpr int kThreads = 4;
constexpr int kCases = 100;

/// Sets up result element `ire` as a small steady-rolling Hertzian problem (module 3).
void set_up(int ire) {
  int icp = 1, imodul = 3, ifcver = 0, ierror = 0, len = 1;
  cntc_initialize(&ire, &imodul, &ifcver, &ierror, " ", &len);
  ASSERT_EQ(ierror, 0);
  int flags[] = {CNTC_ic_tang, CNTC_ic_norm, CNTC_ic_pvtime};
  int values[] = {3, 1, 0};
  int nflags = 3;
  cntc_setflags(&ire, &icp, &nflags, flags, values);
  int m = 0, nmat = 4;
  double material[] = {0.28, 0.28, 82000.0, 82000.0};
  cntc_setmaterialparameters(&ire, &icp, &m, &nmat, material);
  int law = 0, nfric = 2;
  double friction[] = {0.3, 0.3};
  cntc_setfrictionmethod(&ire, &icp, &law, &nfric, friction);
  int ipotcn = -3, nhertz = 5;
  double hertz[] = {16, 16, 3.0, 4.0, 1.1};  // 16 × 16 elements over semi-axes 3 and 4 mm
  cntc_sethertzcontact(&ire, &icp, &ipotcn, &nhertz, hertz);
  double fn = 20000.0;
  cntc_setnormalforce(&ire, &icp, &fn);
}

/// Case k of a sequence: creepages rising along a creep curve; returns FN, FX, FY, MZ.
std::array<double, 4> solve_case(int ire, int k) {
  int icp = 1, ierror = 0;
  double cksi = 1e-5 * k, ceta = -5e-6 * k, cphi = 1e-6 * (k % 7);
  cntc_setcreepages(&ire, &icp, &cksi, &ceta, &cphi);
  cntc_calculate(&ire, &icp, &ierror);
  std::array<double, 4> f{};
  if (ierror < 0) return {-1.0, 0.0, 0.0, 0.0};
  cntc_getcontactforces(&ire, &icp, &f[0], &f[1], &f[2], &f[3]);
  return f;
}

TEST(CntcThreads, SeparateHandlesGiveTheSingleThreadedResults) {
  // One after another, on result element 1 (each thread below repeats this sequence).
  set_up(1);
  std::vector<std::array<double, 4>> reference;
  for (int k = 0; k < kCases; ++k) reference.push_back(solve_case(1, k));
  ASSERT_GT(reference.back()[0], 19999.0);

  std::vector<std::vector<std::array<double, 4>>> results(kThreads);
  for (int t = 0; t < kThreads; ++t) set_up(10 + t);  // set-up is single-threaded (§1.5)
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t)
    threads.emplace_back([t, &results] {
      for (int k = 0; k < kCases; ++k) results[t].push_back(solve_case(10 + t, k));
    });
  for (auto& th : threads) th.join();

  for (int t = 0; t < kThreads; ++t) {
    ASSERT_EQ(results[t].size(), reference.size());
    for (int k = 0; k < kCases; ++k)
      for (int q = 0; q < 4; ++q) EXPECT_EQ(results[t][k][q], reference[k][q]) << t << " " << k;
  }
  for (int ire : {1, 10, 11, 12, 13}) cntc_finalize(&ire);
}

/// Sets up result element `ire` as the Manchester benchmark wheel (side 0 left, 1 right).
void set_up_wheel(int ire, int side, const std::string& dir) {
  int icp = -1, imodul = 1, ifcver = 0, ierror = 0, one = 1;
  cntc_initialize(&ire, &imodul, &ifcver, &ierror, " ", &one);
  int flags[] = {CNTC_ic_config, CNTC_ic_tang, CNTC_ic_norm};
  int values[] = {side, 3, 1};
  int nflags = 3;
  cntc_setflags(&ire, &icp, &nflags, flags, values);
  int m = 0, nmat = 4;
  double material[] = {0.28, 0.28, 82000.0, 82000.0};
  cntc_setmaterialparameters(&ire, &icp, &m, &nmat, material);
  int law = 0, nfric = 2;
  double friction[] = {0.3, 0.3};
  cntc_setfrictionmethod(&ire, &icp, &law, &nfric, friction);
  double fz = 10000.0;
  cntc_setverticalforce(&ire, &fz);
  int ipotcn = -1, npot = 5;
  double discr[] = {0.5, 0.5, 1.5707963267948966, 8.0, 4.0};
  cntc_setpotcontact(&ire, &icp, &ipotcn, &npot, discr);
  int ztrack = 3, ntrack = 11;
  double track[] = {14.0, 0.0, 1435.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  cntc_settrackdimensions(&ire, &ztrack, &ntrack, track);
  int ewheel = 3, nwheel = 3;
  double wheelset[] = {1360.0, -70.0, 460.0};
  cntc_setwheelsetdimensions(&ire, &ewheel, &nwheel, wheelset);
  for (const char* name : {"MBench_UIC60_v3.prr", "MBench_S1002_v3.prw"}) {
    const std::string path = dir + "/" + name;
    int len = static_cast<int>(path.size()), nints = 1, nreals = 0;
    int itype = path.back() == 'w' ? 1 : 0;
    cntc_setprofileinputfname(&ire, path.c_str(), &len, &nints, &itype, &nreals, nullptr);
  }
}

/// Wheel/rail case k: the lateral shift and yaw of the benchmark sweep; FX, FY, FZ on the rail.
std::array<double, 4> solve_wheel_case(int ire, int k) {
  int icp = -1, ierror = 0, e = 2, n = 6;
  double position[] = {0.0, 0.5 * k, 0.0, 0.0, 0.0012 * k, 0.0};
  double velocity[] = {2000.0, 0.0, 0.0, 0.0, 0.0, -2000.0 / 460.0};
  cntc_setwheelsetposition(&ire, &e, &n, position);
  cntc_setwheelsetvelocity(&ire, &e, &n, velocity);
  cntc_calculate(&ire, &icp, &ierror);
  double g[24] = {};
  int lenarr = 24;
  cntc_getglobalforces(&ire, &icp, &lenarr, g);
  return {double(ierror), g[0], g[1], g[2]};
}

TEST(CntcThreads, WheelRailElementsInParallelGiveTheSerialResults) {
  const std::string dir = ROLLCONTACT_EXAMPLES_DIR;
  if (!std::filesystem::exists(dir + "/MBench_UIC60_v3.prr")) GTEST_SKIP();
  constexpr int kWheelCases = 8;
  std::vector<std::vector<std::array<double, 4>>> reference(2);
  for (int side = 0; side < 2; ++side) {
    set_up_wheel(100 + side, side, dir);
    for (int k = 0; k < kWheelCases; ++k)
      reference[side].push_back(solve_wheel_case(100 + side, k));
    ASSERT_EQ(reference[side][0][0], 0.0);
    ASSERT_NEAR(reference[side][0][3], 10000.0, 1.0);
  }
  std::vector<std::vector<std::array<double, 4>>> results(kThreads);
  for (int t = 0; t < kThreads; ++t) set_up_wheel(110 + t, t % 2, dir);
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t)
    threads.emplace_back([t, &results] {
      for (int k = 0; k < kWheelCases; ++k) results[t].push_back(solve_wheel_case(110 + t, k));
    });
  for (auto& th : threads) th.join();
  for (int t = 0; t < kThreads; ++t)
    for (int k = 0; k < kWheelCases; ++k)
      for (int q = 0; q < 4; ++q)
        EXPECT_EQ(results[t][k][q], reference[t % 2][k][q]) << t << " " << k;
  for (int ire : {100, 101, 110, 111, 112, 113}) cntc_finalize(&ire);
}

}  // namespace
