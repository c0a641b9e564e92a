// The behaviours of spec library-api.md §5's checklist that a client notices only when it goes
// wrong: the access categories of §1.3 for every kind of routine (refused calls return their code
// and leave outputs alone, never crash), the flags getflags returns, the defaults of a fresh
// problem, the damping and layer parameters in the problem's units, the repeat
// initialisation, and the grid of a transient wheel/rail sequence.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "rollcontact/contact_addon.h"

namespace {

/// A frictionless Hertzian contact on (ire, 1) in CONTACT units, calculated: circle of radius
/// 2 mm, FN = 1000 N, 15 × 15 elements.
void hertz_calculated(int ire) {
  int icp = 1, imodul = 3, ifcver = 0, ierror = 0, one = 1;
  cntc_initialize(&ire, &imodul, &ifcver, &ierror, " ", &one);
  int flags[] = {CNTC_ic_tang, CNTC_ic_norm};
  int values[] = {0, 1};
  int nflags = 2;
  cntc_setflags(&ire, &icp, &nflags, flags, values);
  int ipotcn = -3, nhertz = 5;
  double hertz[] = {15.0, 15.0, 2.0, 2.0, 1.05};
  cntc_sethertzcontact(&ire, &icp, &ipotcn, &nhertz, hertz);
  double fn = 1000.0;
  cntc_setnormalforce(&ire, &icp, &fn);
  cntc_calculate(&ire, &icp, &ierror);
  ASSERT_GE(ierror, 0);
}

/// The Manchester benchmark's first case (right wheel, DX = DS = 0.2 mm) read into module-1
/// element `ire`; false when the shared examples are absent.
bool benchmark_wheel(int ire) {
  const std::filesystem::path file =
      std::filesystem::path(ROLLCONTACT_EXAMPLES_DIR) / "mbench_a22_right.inp";
  if (!std::filesystem::exists(file)) return false;
  const std::string path = file.string();
  int inp = 1988, len = static_cast<int>(path.size()), ierror = -1;
  cntc_readinpfile(&ire, &inp, path.c_str(), &len, &ierror);
  EXPECT_EQ(ierror, 0);
  return ierror == 0;
}

TEST(CntcAccess, WholeOrPatchRoutinesTakeOnlyProblemNumbersInModule3) {
  // Category 7 accepts −1 for a wheel/rail problem only: in module 3 it is a bad icp (−104),
  // not problem "−1" (which read outside the problem table).
  const int element = 71;
  hertz_calculated(element);
  int ire = element, minus1 = -1, zero = 0, ierror = 0;
  int code = CNTC_ic_norm, n = 1, value = -9;
  cntc_getflags(&ire, &minus1, &n, &code, &value);
  EXPECT_EQ(value, -9);
  subs_calculate(&ire, &minus1, &ierror);
  EXPECT_EQ(ierror, -104);
  subs_calculate(&ire, &zero, &ierror);
  EXPECT_EQ(ierror, -104);
  int too_large = 1000, one = 1;
  subs_calculate(&too_large, &one, &ierror);
  EXPECT_EQ(ierror, -101);
  int imeth = 0, nparam = 0;
  cntc_settemperaturedata(&ire, &minus1, &imeth, &nparam, nullptr);
  int iblk = 1, isubs = 5, nx = 1, ny = 1, nz = 1;  // every element, at z = 1 mm
  double x = 0.0, y = 0.0, z = 1.0;
  subs_addblock(&ire, &minus1, &iblk, &isubs, &nx, &ny, &nz, &x, &y, &z);
  subs_addblock(&ire, &one, &iblk, &isubs, &nx, &ny, &nz, &x, &y, &z);
  subs_calculate(&ire, &one, &ierror);  // the problem itself is unharmed
  EXPECT_EQ(ierror, 0);
  int bx = -9, by = -9, bz = -9;  // a refused call leaves its outputs alone
  subs_getblocksize(&too_large, &one, &iblk, &bx, &by, &bz);
  EXPECT_EQ(bx, -9);
  subs_getblocksize(&ire, &one, &iblk, &bx, &by, &bz);  // block 1: the 15 x 15 grid, 1 depth
  EXPECT_EQ(bx, 15);
  EXPECT_EQ(bz, 1);
  cntc_finalize(&ire);
}

TEST(CntcAccess, CalculateOneAndThreeCheckTheirModule) {
  const int element = 72;
  hertz_calculated(element);
  int ire = element, icp = 1, ierror = 0;
  cntc_calculate1(&ire, &ierror);
  EXPECT_EQ(ierror, -103);  // not available in module 3
  int ire1 = 73, imodul = 1, ifcver = 0, one = 1, minus1 = -1;
  cntc_initialize(&ire1, &imodul, &ifcver, &ierror, " ", &one);
  cntc_calculate3(&ire1, &icp, &ierror);
  EXPECT_EQ(ierror, -102);  // not available in module 1
  cntc_calculate3(&ire1, &minus1, &ierror);
  EXPECT_EQ(ierror, -102);
  for (int e : {ire, ire1}) cntc_finalize(&e);
}

TEST(CntcAccess, WheelRailPatchesAreThoseOfTheLastCalculate) {
  int ire = 74, minus1 = -1, ierror = 0;
  if (!benchmark_wheel(ire)) GTEST_SKIP();
  int one = 1, n = 1, code = CNTC_ic_norm, value = -9;
  cntc_getflags(&ire, &one, &n, &code, &value);  // no patch before the first calculate (−31)
  EXPECT_EQ(value, -9);
  cntc_calculate(&ire, &minus1, &ierror);
  ASSERT_EQ(ierror, 0);
  int npatch = 0;
  cntc_getnumcontactpatches(&ire, &npatch);
  ASSERT_EQ(npatch, 1);
  cntc_getflags(&ire, &one, &n, &code, &value);
  EXPECT_EQ(value, 1);  // N = 1: the benchmark prescribes the vertical force
  int two = 2;
  value = -9;
  cntc_getflags(&ire, &two, &n, &code, &value);
  EXPECT_EQ(value, -9);
  double tcpu = -9.0, twall = -9.0;
  cntc_getcalculationtime(&ire, &two, &tcpu, &twall);
  EXPECT_EQ(tcpu, -9.0);
  cntc_getcalculationtime(&ire, &one, &tcpu, &twall);
  EXPECT_GE(tcpu, 0.0);
  // getcontactlocation wants a patch; gethertzcontact is a module-3 routine.
  std::vector<double> location(30, -9.0);
  int lenarr = 30;
  cntc_getcontactlocation(&ire, &minus1, &lenarr, location.data());
  EXPECT_EQ(location[0], -9.0);
  std::vector<double> hertz(10, -9.0);
  int lenhz = 10;
  cntc_gethertzcontact(&ire, &one, &lenhz, hertz.data());
  EXPECT_EQ(hertz[0], -9.0);
  // getgriddiscretization: −1 is the wheel/rail problem's DX, DS; a patch its grid.
  double dx = -9.0, ds = -9.0;
  cntc_getgriddiscretization(&ire, &minus1, &dx, &ds);
  EXPECT_DOUBLE_EQ(dx, 0.2);
  EXPECT_DOUBLE_EQ(ds, 0.2);
  dx = ds = -9.0;
  cntc_getgriddiscretization(&ire, &one, &dx, &ds);
  EXPECT_DOUBLE_EQ(dx, 0.2);
  cntc_finalize(&ire);
}

TEST(CntcFlags, StoredFlagsAreReadBackClamped) {
  const int element = 75;
  hertz_calculated(element);
  int ire = element, icp = 1;
  int codes[] = {CNTC_ic_sens,   CNTC_ic_sbsout, CNTC_ic_sbsfil, CNTC_ic_xflow,
                 CNTC_if_wrtinp, CNTC_ic_ifmeth, CNTC_ic_ifvari, CNTC_ic_npomax};
  int set[] = {7, 3, 5, 1234567, 1, 4, 9, 50};
  int n = 8;
  cntc_setflags(&ire, &icp, &n, codes, set);
  int got[8] = {-9, -9, -9, -9, -9, -9, -9, -9};
  cntc_getflags(&ire, &icp, &n, codes, got);
  // S2 [0,3]; O_s [0,4] with 3 → 2; A_s 0..2 else 0; X on; wrtinp as given; IF_METH [0,1];
  // VARIANT [1,4]; NPOT_MAX [100, 1e6].
  const int expected[] = {3, 2, 0, 1, 1, 1, 4, 100};
  for (int k = 0; k < n; ++k) EXPECT_EQ(got[k], expected[k]) << "code " << codes[k];
  cntc_finalize(&ire);
}

TEST(CntcDefaults, FreshWheelRailProblemHasThePositionPrescribed) {
  int ire = 76, imodul = 1, ifcver = 0, ierror = 0, one = 1, minus1 = -1;
  cntc_initialize(&ire, &imodul, &ifcver, &ierror, " ", &one);
  int code = CNTC_ic_norm, n = 1, value = -9;
  cntc_getflags(&ire, &minus1, &n, &code, &value);
  EXPECT_EQ(value, 0);
  double fz = 10000.0;
  cntc_setverticalforce(&ire, &fz);
  cntc_getflags(&ire, &minus1, &n, &code, &value);
  EXPECT_EQ(value, 1);
  cntc_finalize(&ire);
}

TEST(CntcMaterial, LayerAndDampingParametersReadBackInTheProblemsUnits) {
  // SI units: the layer's modulus in Pa, thickness in m, k_tau in N/m³; damping in s and N/s.
  int ire = 77, icp = 1, imodul = 3, ifcver = 0, ierror = 0, one = 1;
  cntc_initialize(&ire, &imodul, &ifcver, &ierror, " ", &one);
  int flags[] = {CNTC_if_units, CNTC_ic_tang, CNTC_ic_norm};
  int values[] = {CNTC_un_si, 0, 1};
  int nflags = 3;
  cntc_setflags(&ire, &icp, &nflags, flags, values);
  int m4 = 4, n8 = 8;
  double layer[] = {0.28, 0.28, 82e9, 82e9, 2e8, 50e-6, 3e20, 4e12};
  cntc_setmaterialparameters(&ire, &icp, &m4, &n8, layer);
  int m12 = 12, n4 = 4, n3 = 3;
  double damping[] = {1e-4, 2e-4, 5e5, 6e5};
  cntc_setmaterialparameters(&ire, &icp, &m12, &n3, damping);  // wrong count: refused
  cntc_setmaterialparameters(&ire, &icp, &m12, &n4, damping);
  int law = 0, nfric = 2;
  double friction[] = {0.3, 0.3};
  cntc_setfrictionmethod(&ire, &icp, &law, &nfric, friction);
  int ipotcn = -3, nhertz = 5;
  double hertz[] = {15.0, 15.0, 2e-3, 2e-3, 1.05};
  cntc_sethertzcontact(&ire, &icp, &ipotcn, &nhertz, hertz);
  double fn = 1000.0;
  cntc_setnormalforce(&ire, &icp, &fn);
  cntc_calculate(&ire, &icp, &ierror);
  ASSERT_GE(ierror, 0);
  int itask = 2, lenarr = 22, code = CNTC_ic_mater, n = 1, mdigit = -1;
  std::vector<double> v(22, -9.0);
  cntc_getparameters(&ire, &icp, &itask, &lenarr, v.data());
  EXPECT_NEAR(v[14], 2e8, 1e-6 * 2e8);      // g3 [Pa]
  EXPECT_NEAR(v[15], 50e-6, 1e-6 * 50e-6);  // laythk [m]
  EXPECT_EQ(v[16], 0.0);                    // tau_c0 ≥ 1e10: no plasticity
  EXPECT_NEAR(v[17], 4e12, 1e-6 * 4e12);    // k_tau [N/m³]
  EXPECT_EQ(v[18], 1e-4);
  EXPECT_EQ(v[19], 2e-4);
  EXPECT_EQ(v[20], 5e5);
  EXPECT_EQ(v[21], 6e5);
  cntc_getflags(&ire, &icp, &n, &code, &mdigit);
  EXPECT_EQ(mdigit, 4);  // the damping digit leaves M
  cntc_finalize(&ire);
}

TEST(CntcFields, FrictionAndRigidSlipFieldsAndUncomputedOnesUntouched) {
  // Steady rolling with ξ = 1e-3, η = −5e-4, no spin, μ = 0.25 (Coulomb): the local friction
  // coefficient is μ in every element, the rigid slip W/δq is (ξ, η); the layer's fields of an
  // elastic problem were not computed and leave the array as it was.
  int ire = 79, icp = 1, imodul = 3, ifcver = 0, ierror = 0, one = 1;
  cntc_initialize(&ire, &imodul, &ifcver, &ierror, " ", &one);
  int flags[] = {CNTC_ic_tang, CNTC_ic_norm};
  int values[] = {3, 1};
  int nflags = 2;
  cntc_setflags(&ire, &icp, &nflags, flags, values);
  int law = 0, nfric = 2;
  double friction[] = {0.25, 0.25};
  cntc_setfrictionmethod(&ire, &icp, &law, &nfric, friction);
  int ipotcn = -1, nhertz = 5;
  double hertz[] = {12, 12, 0.002, 0.004, 1.1};
  cntc_sethertzcontact(&ire, &icp, &ipotcn, &nhertz, hertz);
  double veloc = 2000.0, fn = 10000.0, cksi = 1e-3, ceta = -5e-4, cphi = 0.0;
  cntc_setreferencevelocity(&ire, &icp, &veloc);
  cntc_setnormalforce(&ire, &icp, &fn);
  cntc_setcreepages(&ire, &icp, &cksi, &ceta, &cphi);
  cntc_calculate(&ire, &icp, &ierror);
  ASSERT_GE(ierror, 0);
  int lenarr = 144;
  std::vector<double> field(144, -9.0);
  int code = CNTC_fld_mu;
  cntc_getfielddata(&ire, &icp, &code, &lenarr, field.data());
  for (double v : field) ASSERT_EQ(v, 0.25);
  code = CNTC_fld_wx;
  cntc_getfielddata(&ire, &icp, &code, &lenarr, field.data());
  for (double v : field) ASSERT_NEAR(v, cksi, 1e-15);
  code = CNTC_fld_wy;
  cntc_getfielddata(&ire, &icp, &code, &lenarr, field.data());
  for (double v : field) ASSERT_NEAR(v, ceta, 1e-15);
  std::fill(field.begin(), field.end(), -9.0);
  for (int uncomputed : {CNTC_fld_taucrt, CNTC_fld_uplsx, CNTC_fld_uplsy}) {
    cntc_getfielddata(&ire, &icp, &uncomputed, &lenarr, field.data());
    EXPECT_EQ(field[0], -9.0) << uncomputed;
  }
  cntc_finalize(&ire);
}

TEST(CntcLifecycle, RepeatedInitializeFirstLeavesIerrorAsPassed) {
  int ifcver = 0, ierror = -1, ioutput = 0, blank = 1;
  cntc_initializefirst(&ifcver, &ierror, &ioutput, " ", " ", " ", &blank, &blank, &blank);
  ierror = 42;
  ifcver = 0;
  cntc_initializefirst(&ifcver, &ierror, &ioutput, " ", " ", " ", &blank, &blank, &blank);
  EXPECT_EQ(ierror, 42);
  EXPECT_GE(ifcver, 2510);  // always set
}

TEST(CntcWheelRail, GridChangeWithinATransientSequenceIsRefused) {
  int ire = 78, minus1 = -1, ierror = 0;
  if (!benchmark_wheel(ire)) GTEST_SKIP();
  int codes[] = {CNTC_ic_tang, CNTC_ic_pvtime};
  int first[] = {2, 2}, n = 2;
  cntc_setflags(&ire, &minus1, &n, codes, first);
  cntc_calculate(&ire, &minus1, &ierror);
  ASSERT_EQ(ierror, 0);
  int next[] = {2, 0};
  cntc_setflags(&ire, &minus1, &n, codes, next);
  int ipotcn = 0, nparam = 3;
  double grid[] = {0.25, 0.25, 0.0};
  cntc_setpotcontact(&ire, &minus1, &ipotcn, &nparam, grid);
  cntc_calculate(&ire, &minus1, &ierror);
  EXPECT_EQ(ierror, CNTC_err_discr);
  // A new sequence (P = 2) may take the new grid.
  cntc_setflags(&ire, &minus1, &n, codes, first);
  cntc_calculate(&ire, &minus1, &ierror);
  EXPECT_EQ(ierror, 0);
  cntc_finalize(&ire);
}

}  // namespace
