// The cntc_* conventions a client relies on (spec library-api.md §1–2): unit conventions with
// their scale factors and body sign, refused calls that change nothing, outputs left alone on
// a bad handle or before the first calculation, and CONTACT's side effects of the setters.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "rollcontact/contact_addon.h"

namespace {

struct Forces {
  double fn = 0.0, fx = 0.0, fy = 0.0, mz = 0.0;
};

/// A steady-rolling Hertzian case (a1 = 0.002, b1 = 0.004 1/mm, FN = 10 kN) on (ire, 1) in the
/// unit convention `units` (lengths in m when SI or SIMPACK).
Forces solve_in_units(int ire, int units) {
  const double len = units == CNTC_un_cntc ? 1.0 : 1e-3;  // external length per mm
  int icp = 1, imodul = 3, ifcver = 0, ierror = 0, one = 1;
  cntc_initialize(&ire, &imodul, &ifcver, &ierror, " ", &one);
  int flags[] = {CNTC_if_units, CNTC_ic_tang, CNTC_ic_norm};
  int values[] = {units, 3, 1};
  int nflags = 3;
  cntc_setflags(&ire, &icp, &nflags, flags, values);
  int m = 0, nmat = 4;
  const double pressure = len * len;  // external pressure per N/mm²: N/m² = 1e-6 N/mm²
  double material[] = {0.28, 0.28, 82000.0 / pressure, 82000.0 / pressure};
  cntc_setmaterialparameters(&ire, &icp, &m, &nmat, material);
  int law = 0, nfric = 2;
  double friction[] = {0.3, 0.3};
  cntc_setfrictionmethod(&ire, &icp, &law, &nfric, friction);
  int ipotcn = -1, nhertz = 5;
  double hertz[] = {20, 20, 0.002 / len, 0.004 / len, 1.1};
  cntc_sethertzcontact(&ire, &icp, &ipotcn, &nhertz, hertz);
  double veloc = 2000.0 * len, fn = 10000.0;
  cntc_setreferencevelocity(&ire, &icp, &veloc);
  cntc_setnormalforce(&ire, &icp, &fn);
  // The creepages as CONTACT takes them in every convention (the body sign is on outputs only).
  double cksi = 0.001, ceta = -0.0005, cphi = 0.0001 / len;
  cntc_setcreepages(&ire, &icp, &cksi, &ceta, &cphi);
  cntc_calculate(&ire, &icp, &ierror);
  EXPECT_GE(ierror, 0);
  Forces f;
  cntc_getcontactforces(&ire, &icp, &f.fn, &f.fx, &f.fy, &f.mz);
  // Read back with the body sign: SIMPACK's creepages are those of the wheel.
  const double body = units == CNTC_un_spck ? -1.0 : 1.0;
  double back[3] = {0.0, 0.0, 0.0};
  cntc_getcreepages(&ire, &icp, &back[0], &back[1], &back[2]);
  EXPECT_NEAR(back[0], body * cksi, 1e-15);
  EXPECT_NEAR(back[1], body * ceta, 1e-15);
  EXPECT_NEAR(back[2], body * cphi, 1e-12 * std::abs(cphi));
  cntc_finalize(&ire);
  return f;
}

TEST(CntcUnits, SiAndSimpackScaleLengthsAndSimpackFlipsTheBody) {
  const Forces c = solve_in_units(21, CNTC_un_cntc);
  const Forces si = solve_in_units(22, CNTC_un_si);
  const Forces sp = solve_in_units(23, CNTC_un_spck);
  ASSERT_NEAR(c.fn, 10000.0, 1e-6);
  EXPECT_GT(std::abs(c.fx), 100.0);  // a real creep force, not a default
  // The same problem: forces in N in every convention, MZ in N·mm or N·m.
  const double tol = 1e-9 * c.fn;
  EXPECT_NEAR(si.fn, c.fn, tol);
  EXPECT_NEAR(si.fx, c.fx, tol);
  EXPECT_NEAR(si.fy, c.fy, tol);
  EXPECT_NEAR(si.mz, c.mz * 1e-3, tol * 1e-3);
  // SIMPACK: forces on the wheel (body 2): the tangential ones change sign, FN does not.
  EXPECT_NEAR(sp.fn, c.fn, tol);
  EXPECT_NEAR(sp.fx, -c.fx, tol);
  EXPECT_NEAR(sp.fy, -c.fy, tol);
  EXPECT_NEAR(sp.mz, -c.mz * 1e-3, tol * 1e-3);
}

TEST(CntcErrors, BadHandlesAndEarlyGettersLeaveOutputsAlone) {
  int ire = 31, icp = 1, ierror = 0;
  double fn = -7.0, fx = -7.0, fy = -7.0, mz = -7.0;
  cntc_getcontactforces(&ire, &icp, &fn, &fx, &fy, &mz);  // nothing calculated yet
  EXPECT_EQ(fn, -7.0);
  EXPECT_EQ(mz, -7.0);
  int bad = 0;
  cntc_getcontactforces(&ire, &bad, &fn, &fx, &fy, &mz);
  EXPECT_EQ(fn, -7.0);
  cntc_calculate(&ire, &bad, &ierror);
  EXPECT_EQ(ierror, -104);
  int too_large = 1000;
  cntc_calculate(&too_large, &icp, &ierror);
  EXPECT_EQ(ierror, -101);
  cntc_calculate(nullptr, &icp, &ierror);  // null handle: an error code, no crash
  EXPECT_LT(ierror, 0);
  // A module-3 problem without a potential contact cannot be calculated.
  cntc_calculate(&ire, &icp, &ierror);
  EXPECT_EQ(ierror, CNTC_err_discr);
  // A module-1 element: calculate takes icp = -1 only, and first needs its profiles.
  int ire1 = 32, minus1 = -1, imodul = 1, ifcver = 0, one = 1;
  cntc_initialize(&ire1, &imodul, &ifcver, &ierror, " ", &one);
  cntc_calculate(&ire1, &one, &ierror);
  EXPECT_EQ(ierror, -106);
  cntc_calculate(&ire1, &minus1, &ierror);
  EXPECT_EQ(ierror, CNTC_err_profil);
  for (int e : {31, 32}) cntc_finalize(&e);
}

TEST(CntcErrors, RefusedSettersChangeNothing) {
  int ire = 33, icp = 1;
  int codes[] = {CNTC_ic_frclaw, CNTC_ic_mater, CNTC_ic_norm};
  int before[] = {-1, -1, -1}, after[] = {-1, -1, -1}, n = 3;
  cntc_getflags(&ire, &icp, &n, codes, before);
  int law = 7, nfric = 2;  // L = 7 does not exist
  double friction[] = {0.5, 0.5};
  cntc_setfrictionmethod(&ire, &icp, &law, &nfric, friction);
  int l2 = 2, wrong = 3;  // L = 2 needs 7 parameters
  cntc_setfrictionmethod(&ire, &icp, &l2, &wrong, friction);
  int m = 4, nmat = 4;  // M = 4 needs 8
  double material[] = {0.3, 0.3, 1.0, 1.0};
  cntc_setmaterialparameters(&ire, &icp, &m, &nmat, material);
  cntc_getflags(&ire, &icp, &n, codes, after);
  for (int k = 0; k < 3; ++k) EXPECT_EQ(after[k], before[k]) << codes[k];
  // Accepted ones have CONTACT's side effects: setnormalforce sets N = 1, setpenetration N = 0,
  // Polach (L = 5) is stored as L = 4.
  double value = 100.0;
  cntc_setnormalforce(&ire, &icp, &value);
  int code_n = CNTC_ic_norm, flag = -1, one = 1;
  cntc_getflags(&ire, &icp, &one, &code_n, &flag);
  EXPECT_EQ(flag, 1);
  cntc_setpenetration(&ire, &icp, &value);
  cntc_getflags(&ire, &icp, &one, &code_n, &flag);
  EXPECT_EQ(flag, 0);
  int polach = 5, npolach = 3;
  double params[] = {0.4, 0.4, 0.6};
  cntc_setfrictionmethod(&ire, &icp, &polach, &npolach, params);
  int code_l = CNTC_ic_frclaw;
  cntc_getflags(&ire, &icp, &one, &code_l, &flag);
  EXPECT_EQ(flag, 4);
  cntc_finalize(&ire);
}

TEST(CntcFields, ArraysHaveTheGridAndTheTotals) {
  int ire = 34, icp = 1, imodul = 3, ifcver = 0, ierror = 0, one = 1;
  cntc_initialize(&ire, &imodul, &ifcver, &ierror, " ", &one);
  int flags[] = {CNTC_ic_tang, CNTC_ic_norm};
  int values[] = {1, 1};  // a shift, FN given
  int nflags = 2;
  cntc_setflags(&ire, &icp, &nflags, flags, values);
  int ipotcn = -3, nhertz = 5;
  double hertz[] = {24, 20, 3.0, 2.5, 1.2};
  cntc_sethertzcontact(&ire, &icp, &ipotcn, &nhertz, hertz);
  double fn = 5000.0, sx = 1e-3, zero = 0.0;
  cntc_setnormalforce(&ire, &icp, &fn);
  cntc_setcreepages(&ire, &icp, &sx, &zero, &zero);
  cntc_calculate(&ire, &icp, &ierror);
  ASSERT_GE(ierror, 0);
  int mx = 0, my = 0;
  cntc_getnumelements(&ire, &icp, &mx, &my);
  ASSERT_EQ(mx, 24);
  ASSERT_EQ(my, 20);
  double dx = 0.0, dy = 0.0;
  cntc_getgriddiscretization(&ire, &icp, &dx, &dy);
  const int n = mx * my;
  std::vector<double> pn(n), px(n), py(n);
  cntc_gettractions(&ire, &icp, const_cast<int*>(&n), pn.data(), px.data(), py.data());
  double sum_n = 0.0, sum_x = 0.0;
  for (int i = 0; i < n; ++i) {
    sum_n += pn[i];
    sum_x += px[i];
  }
  double f[4];
  cntc_getcontactforces(&ire, &icp, &f[0], &f[1], &f[2], &f[3]);
  EXPECT_NEAR(sum_n * dx * dy, f[0], 1e-9 * f[0]);  // the pressures integrate to FN
  EXPECT_NEAR(sum_x * dx * dy, f[1], 1e-9 * f[0]);
  std::vector<int> eldiv(n, -1);
  cntc_getelementdivision(&ire, &icp, const_cast<int*>(&n), eldiv.data());
  int in_contact = 0;
  for (int i = 0; i < n; ++i) {
    EXPECT_TRUE(eldiv[i] >= 0 && eldiv[i] <= 2);
    in_contact += eldiv[i] != 0;
    EXPECT_EQ(eldiv[i] != 0, pn[i] > 0.0) << i;
  }
  double carea = 0.0, harea = 0.0, sarea = 0.0;
  cntc_getcontactpatchareas(&ire, &icp, &carea, &harea, &sarea);
  EXPECT_NEAR(carea, in_contact * dx * dy, 1e-12);
  EXPECT_NEAR(harea + sarea, carea, 1e-12);
  // A short array gets only its length: the rest stays as it was.
  std::vector<double> part(n, -3.0);
  int half = n / 2, code_pn = CNTC_fld_pn;
  cntc_getfielddata(&ire, &icp, &code_pn, &half, part.data());
  EXPECT_EQ(part[half], -3.0);
  EXPECT_EQ(part[half - 1], pn[half - 1]);
  cntc_finalize(&ire);
}

}  // namespace
