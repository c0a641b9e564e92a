// What an MBS code pays per call of CONTACT's library interface: cntc_calculate on the
// Manchester benchmark wheel (S1002 on UIC60, 10 kN, steady rolling) with the wheelset moving
// along the sweep (lateral shift 0-10 mm, yaw up to 24 mrad), as a vehicle simulation
// calls it time step after time step; DX = DS = 0.5 and 0.2 mm. Needs CONTACT's examples
// (../shared/reference/contact-examples) for the profiles.

#include <benchmark/benchmark.h>

#include <filesystem>
#include <string>

#include "rollcontact/contact_addon.h"

namespace {

const std::string kExamples = "../shared/reference/contact-examples";

bool set_up(int ire, double dx, int iestim) {
  int icp = -1, imodul = 1, ifcver = 0, ierror = 0, one = 1;
  cntc_initialize(&ire, &imodul, &ifcver, &ierror, " ", &one);
  int flags[] = {CNTC_ic_config, CNTC_ic_tang, CNTC_ic_norm, CNTC_ic_iestim};
  int values[] = {1, 3, 1, iestim};
  int nflags = 4;
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
  double discr[] = {dx, dx, 1.5707963267948966, 8.0, 4.0};
  cntc_setpotcontact(&ire, &icp, &ipotcn, &npot, discr);
  int ztrack = 3, ntrack = 11;
  double track[] = {14.0, 0.0, 1435.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  cntc_settrackdimensions(&ire, &ztrack, &ntrack, track);
  int ewheel = 3, nwheel = 3;
  double wheelset[] = {1360.0, -70.0, 460.0};
  cntc_setwheelsetdimensions(&ire, &ewheel, &nwheel, wheelset);
  for (const char* name : {"MBench_UIC60_v3.prr", "MBench_S1002_v3.prw"}) {
    const std::string path = kExamples + "/" + name;
    if (!std::filesystem::exists(path)) return false;
    int len = static_cast<int>(path.size()), nints = 1, nreals = 0;
    int itype = path.back() == 'w' ? 1 : 0;
    cntc_setprofileinputfname(&ire, path.c_str(), &len, &nints, &itype, &nreals, nullptr);
  }
  return true;
}

/// Arguments: 10·DX [mm]; IESTIM (1: each call starts from the previous one's solution).
void BM_CntcWheelRailStep(benchmark::State& state) {
  const double dx = static_cast<double>(state.range(0)) / 10.0;
  int ire = 1 + static_cast<int>(state.range(0)) + 10 * static_cast<int>(state.range(1)), icp = -1;
  if (!set_up(ire, dx, static_cast<int>(state.range(1)))) {
    state.SkipWithError("CONTACT examples not found (run from the repository folder)");
    return;
  }
  int k = 0, failures = 0;
  for (auto _ : state) {
    const double y = 0.1 * (k % 101);  // 0 .. 10 mm, then again
    double position[] = {0.0, y, 0.0, 0.0, 0.0024 * y, 0.0};
    double velocity[] = {2000.0, 0.0, 0.0, 0.0, 0.0, -2000.0 / 460.0};
    int e = 2, n = 6, ierror = 0;
    cntc_setwheelsetposition(&ire, &e, &n, position);
    cntc_setwheelsetvelocity(&ire, &e, &n, velocity);
    cntc_calculate(&ire, &icp, &ierror);
    failures += ierror != 0;
    ++k;
  }
  state.counters["failures"] = failures;
  cntc_finalize(&ire);
}
BENCHMARK(BM_CntcWheelRailStep)
    ->Args({5, 0})
    ->Args({5, 1})
    ->Args({2, 0})
    ->Args({2, 1})
    ->Unit(benchmark::kMillisecond)
    ->MinTime(2.0);

}  // namespace

BENCHMARK_MAIN();
