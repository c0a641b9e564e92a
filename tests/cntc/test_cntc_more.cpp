// The remaining cntc_* routines against physics and against the routes they must agree with:
// subsurface stresses under a Hertzian pressure (Johnson's closed form on the axis), profile
// values of a circular profile given as points, readinpfile = the same case set by calls,
// extra rigid slip, material parameters read back.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include "rollcontact/contact_addon.h"
#include "support/files.hpp"

namespace {

/// A frictionless Hertzian contact on (ire, 1): circle of radius a = 2 mm, FN = 1000 N.
void hertz_normal(int ire, int mx) {
  int icp = 1, imodul = 3, ifcver = 0, ierror = 0, one = 1;
  cntc_initialize(&ire, &imodul, &ifcver, &ierror, " ", &one);
  int flags[] = {CNTC_ic_tang, CNTC_ic_norm};
  int values[] = {0, 1};
  int nflags = 2;
  cntc_setflags(&ire, &icp, &nflags, flags, values);
  int ipotcn = -3, nhertz = 5;
  double hertz[] = {double(mx), double(mx), 2.0, 2.0, 1.05};
  cntc_sethertzcontact(&ire, &icp, &ipotcn, &nhertz, hertz);
  double fn = 1000.0;
  cntc_setnormalforce(&ire, &icp, &fn);
}

TEST(CntcSubsurface, StressOnTheAxisFollowsHertz) {
  const int ire = 41;
  int icp = 1, ierror = 0;
  hertz_normal(ire, 61);
  int r = ire;
  cntc_calculate(&r, &icp, &ierror);
  ASSERT_GE(ierror, 0);
  double pmax = 0.0;
  cntc_getmaximumpressure(&r, &icp, &pmax);
  // Points on the axis at z = 0.5a and a (isubs 9: x, y, z lists).
  int iblk = 1, isubs = 9, nx = 1, ny = 1, nz = 2;
  double x[] = {0.0}, y[] = {0.0}, z[] = {1.0, 2.0};
  subs_addblock(&r, &icp, &iblk, &isubs, &nx, &ny, &nz, x, y, z);
  subs_calculate(&r, &icp, &ierror);
  ASSERT_EQ(ierror, 0);
  int bx = 0, by = 0, bz = 0;
  subs_getblocksize(&r, &icp, &iblk, &bx, &by, &bz);
  ASSERT_EQ(bx * by * bz, 2);
  int lenarr = 2, ncol = 2, icol[] = {3, 21};  // z, σzz
  double out[4] = {};
  subs_getresults(&r, &icp, &iblk, &lenarr, &ncol, icol, out);
  const double p0 = 3.0 * 1000.0 / (2.0 * std::numbers::pi * 4.0);  // Hertz peak pressure
  EXPECT_NEAR(pmax, p0, 0.02 * p0);
  for (int k = 0; k < 2; ++k) {
    const double zk = out[k], a = 2.0;
    EXPECT_DOUBLE_EQ(zk, z[k]);
    // Johnson (3.45): σzz = −p0 / (1 + z²/a²) on the axis; 2 % for the 58-element diameter.
    const double expected = -p0 / (1.0 + zk * zk / (a * a));
    EXPECT_NEAR(out[2 + k], expected, 0.02 * p0) << "z = " << zk;
  }
  int bad = 7, ncol1 = 1, invalid = 99;
  double untouched = -5.0;
  subs_getresults(&r, &icp, &bad, &lenarr, &ncol1, &invalid, &untouched);
  EXPECT_EQ(untouched, -5.0);  // a block that does not exist leaves the array alone
  cntc_finalize(&r);
}

TEST(CntcTemperature, WithoutTangentialProblemTheBulkTemperaturesAreReturned) {
  // H = 3 with T = 0 (v25.1): the bulk temperatures are the result, as maxima and as fields.
  const int ire = 45;
  int r = ire, icp = 1, ierror = 0;
  hertz_normal(ire, 21);
  int h = 3, nparam = 9;
  double heat[] = {20.0, 450.0, 50e-3, 7.85e-6, 150.0, 450.0, 50e-3, 7.85e-6, 0.0};
  cntc_settemperaturedata(&r, &icp, &h, &nparam, heat);
  cntc_calculate(&r, &icp, &ierror);
  ASSERT_GE(ierror, 0);
  double t1 = 0.0, t2 = 0.0;
  cntc_getmaximumtemperature(&r, &icp, &t1, &t2);
  EXPECT_DOUBLE_EQ(t1, 20.0);
  EXPECT_DOUBLE_EQ(t2, 150.0);
  int ifld = CNTC_fld_temp2, lenarr = 4;
  std::array<double, 4> field{};
  cntc_getfielddata(&r, &icp, &ifld, &lenarr, field.data());
  EXPECT_TRUE(std::all_of(field.begin(), field.end(), [](double v) { return v == 150.0; }));
  cntc_finalize(&r);
}

TEST(CntcParameters, MaterialAndFrictionReadBack) {
  const int ire = 42;
  int r = ire, icp = 1, ierror = 0;
  hertz_normal(ire, 21);
  int m = 0, nmat = 4;
  double material[] = {0.25, 0.3, 80000.0, 70000.0};
  cntc_setmaterialparameters(&r, &icp, &m, &nmat, material);
  int law = 0, nfric = 2;
  double friction[] = {0.35, 0.3};  // the smaller one for both (§2.2)
  cntc_setfrictionmethod(&r, &icp, &law, &nfric, friction);
  cntc_calculate(&r, &icp, &ierror);
  ASSERT_GE(ierror, 0);
  int itask = 2, lenarr = 22;
  std::vector<double> v(22, -1.0);
  cntc_getparameters(&r, &icp, &itask, &lenarr, v.data());
  EXPECT_EQ(v[0], 80000.0);
  EXPECT_EQ(v[1], 70000.0);
  const double g = 2.0 / (1.0 / 80000.0 + 1.0 / 70000.0);
  EXPECT_NEAR(v[2], g, 1e-9 * g);  // combined modulus (physics.md §3.1)
  EXPECT_EQ(v[3], 0.25);
  itask = 3;
  cntc_getparameters(&r, &icp, &itask, &lenarr, v.data());
  EXPECT_EQ(v[0], 0.0);  // L
  EXPECT_EQ(v[1], 1.0);  // one set
  EXPECT_EQ(v[5], 0.3);  // fstat = fkin = min
  EXPECT_EQ(v[6], 0.3);
  cntc_finalize(&r);
}

TEST(CntcExtraRigidSlip, ActsLikeAShiftOfTheSameSize) {
  // A shift problem: an extra rigid slip wx everywhere adds to the shift (same unit, mm).
  auto solve = [](int ire, double shift, double extra) {
    int r = ire, icp = 1, ierror = 0;
    hertz_normal(ire, 21);
    int flags[] = {CNTC_ic_tang};
    int values[] = {1};
    int nflags = 1;
    cntc_setflags(&r, &icp, &nflags, flags, values);
    double zero = 0.0;
    cntc_setcreepages(&r, &icp, &shift, &zero, &zero);
    if (extra != 0.0) {
      int n = 21 * 21;
      std::vector<double> wx(n, extra), wy(n, 0.0);
      cntc_setextrarigidslip(&r, &icp, &n, wx.data(), wy.data());
    }
    cntc_calculate(&r, &icp, &ierror);
    double f[4] = {};
    cntc_getcontactforces(&r, &icp, &f[0], &f[1], &f[2], &f[3]);
    cntc_finalize(&r);
    return f[1];
  };
  const double plain = solve(43, 2e-3, 0.0), split = solve(44, 1e-3, 1e-3);
  EXPECT_GT(std::abs(plain), 1.0);
  EXPECT_NEAR(split, plain, 1e-6 * std::abs(plain));
}

TEST(CntcProfiles, CircleGivenAsPointsSamplesBack) {
  // A rail head of radius 300 mm over ±30 mm, as points; its samples lie on the circle, the arc
  // length ends at the arc's length and the surface angle is the circle's slope angle.
  int ire = 45, imodul = 1, ifcver = 0, ierror = 0, one = 1;
  cntc_initialize(&ire, &imodul, &ifcver, &ierror, " ", &one);
  const double radius = 300.0;
  std::vector<double> yz;
  for (int k = 0; k <= 60; ++k) {
    const double y = -30.0 + k;
    yz.push_back(y);
    yz.push_back(radius - std::sqrt(radius * radius - y * y));  // z downwards
  }
  int npoint = 61, nints = 1, iparam[] = {0}, nreals = 0;
  cntc_setprofileinputvalues(&ire, &npoint, yz.data(), &nints, iparam, &nreals, nullptr);
  int task = -1, lenarr = 400, getints = 2, getparam[] = {0, 1}, getreals = 1;
  double ds[] = {0.5};
  std::vector<double> v(400, 0.0);
  cntc_getprofilevalues(&ire, &task, &getints, getparam, &getreals, ds, &lenarr, v.data());
  EXPECT_EQ(v[0], 0.0);  // loaded without error
  task = 0;
  cntc_getprofilevalues(&ire, &task, &getints, getparam, &getreals, ds, &lenarr, v.data());
  const int n = static_cast<int>(v[0]);
  const double arc = 2.0 * radius * std::asin(30.0 / radius);
  EXPECT_EQ(n, static_cast<int>(std::floor(arc / 0.5 + 1e-9)) + 1);
  ASSERT_LE(2 * n, lenarr);
  task = 1;
  cntc_getprofilevalues(&ire, &task, &getints, getparam, &getreals, ds, &lenarr, v.data());
  for (int k = 0; k < n; ++k) {
    const double y = v[k], z = v[n + k];
    EXPECT_NEAR(std::hypot(y, z - radius), radius, 1e-3) << k;  // on the circle (spline)
  }
  task = 4;
  std::vector<double> s(400, 0.0), angle(400, 0.0);
  cntc_getprofilevalues(&ire, &task, &getints, getparam, &getreals, ds, &lenarr, s.data());
  EXPECT_NEAR(s[n - 1], 0.5 * (n - 1), 1e-9);
  task = 5;
  cntc_getprofilevalues(&ire, &task, &getints, getparam, &getreals, ds, &lenarr, angle.data());
  task = 1;
  cntc_getprofilevalues(&ire, &task, &getints, getparam, &getreals, ds, &lenarr, v.data());
  for (int k = 0; k < n; k += 10) {
    const double y = v[k];
    if (std::abs(y) > 27.0) continue;  // the natural spline's end conditions bend the ends
    const double slope = y / std::sqrt(radius * radius - y * y);  // dz/dy of the circle
    EXPECT_NEAR(angle[k], std::atan(slope), 1e-4) << "y = " << y;
  }
  cntc_finalize(&ire);
}

TEST(CntcReadInpFile, GivesTheCaseOfTheFile) {
  // readinpfile (module-1 .inp) then calculate = the same case built by the set-up calls of
  // cntc_mbench_wheelrail.c; the reference is rollcontact run's result (tests of that client).
  const std::filesystem::path examples{ROLLCONTACT_EXAMPLES_DIR};
  if (!std::filesystem::exists(examples / "mbench_a22_right.inp")) GTEST_SKIP();
  int ire = 46, inp = 1988, ierror = -1;
  const std::string file = (examples / "mbench_a22_right.inp").string();
  int len = static_cast<int>(file.size());
  cntc_readinpfile(&ire, &inp, file.c_str(), &len, &ierror);
  ASSERT_EQ(ierror, 0);
  int icp = -1;
  cntc_calculate(&ire, &icp, &ierror);
  ASSERT_EQ(ierror, 0);
  double g[24] = {};
  int lenarr = 24;
  cntc_getglobalforces(&ire, &icp, &lenarr, g);
  // Case 1 of the benchmark (y = 0), CONTACT's reference output: FX(TR) 0.2783 N, FY(TR)
  // 36.24 N, FZ(TR) 10000 N; the small forces are at the solver's noise level EPS·μ·FZ =
  // 0.03 N, so they are compared within 0.1 N (1e-5 of FZ).
  EXPECT_NEAR(g[0], 0.2783, 0.1);
  EXPECT_NEAR(g[1], 36.24, 0.1);
  EXPECT_NEAR(g[2], 10000.0, 1.0);
  int other = 1983;
  cntc_readinpfile(&ire, &other, file.c_str(), &len, &ierror);
  EXPECT_EQ(ierror, CNTC_err_input);
  cntc_finalize(&ire);
}

/// The Manchester benchmark wheel (0 left, 1 right) at y_ws = 0 read from its .inp with C1
/// replaced; returns the element number.
int centred_wheel(int ire, int side, const std::filesystem::path& dir) {
  std::ifstream in(dir / "mbench_a22_right.inp");
  std::string text, line;
  for (int n = 1; std::getline(in, line) && n <= 26; ++n) {
    if (n == 13) line[1] = static_cast<char>('0' + side);  // the C digit of C-P-B-T-N-F-S
    text += line + "\n";
  }
  const rollcontact::test_support::ScratchDir scratch("cntc_side" + std::to_string(side));
  const std::filesystem::path& file = scratch.path();
  for (const char* name : {"MBench_UIC60_v3.prr", "MBench_S1002_v3.prw"})
    std::filesystem::copy_file(dir / name, file / name,
                               std::filesystem::copy_options::overwrite_existing);
  std::ofstream(file / "case.inp") << text << " 0 MODULE\n";
  const std::string path = (file / "case.inp").string();
  int inp = 1988, len = static_cast<int>(path.size()), ierror = -1, icp = -1;
  cntc_readinpfile(&ire, &inp, path.c_str(), &len, &ierror);
  EXPECT_EQ(ierror, 0);
  cntc_calculate(&ire, &icp, &ierror);
  EXPECT_EQ(ierror, 0);
  return ire;
}

TEST(CntcWheelRail, MomentsAndMarkersFollowTheForcesAndMirrorBetweenWheels) {
  const std::filesystem::path dir{ROLLCONTACT_EXAMPLES_DIR};
  if (!std::filesystem::exists(dir / "mbench_a22_right.inp")) GTEST_SKIP();
  std::array<std::array<double, 24>, 2> g{};
  std::array<std::array<double, 38>, 2> loc{};
  for (int side = 0; side < 2; ++side) {
    int ire = centred_wheel(47 + side, side, dir), icp = -1, patch = 1, n24 = 24, n38 = 38;
    cntc_getglobalforces(&ire, &icp, &n24, g[side].data());
    cntc_getcontactlocation(&ire, &patch, &n38, loc[side].data());
    int npatch = 0;
    cntc_getnumcontactpatches(&ire, &npatch);
    ASSERT_EQ(npatch, 1);
    double fn = 0, fx = 0, fs = 0, mn = 0;
    cntc_getcontactforces(&ire, &patch, &fn, &fx, &fs, &mn);
    // physics.md §13.6: M = (r_ref − r_marker) × F + MN·n, n = (0, −sin δ, cos δ), about the
    // rail marker (0, y_r, z_r) in track coordinates.
    const double d = loc[side][3];
    const double rx = loc[side][0], ry = loc[side][1] - loc[side][25],
                 rz = loc[side][2] - loc[side][26];
    const double fxt = g[side][0], fyt = g[side][1], fzt = g[side][2];
    const double tol = 1e-9 * fzt * 1000.0;
    EXPECT_NEAR(g[side][3], ry * fzt - rz * fyt, tol);
    EXPECT_NEAR(g[side][4], rz * fxt - rx * fzt - mn * std::sin(d), tol);
    EXPECT_NEAR(g[side][5], rx * fyt - ry * fxt + mn * std::cos(d), tol);
    cntc_finalize(&ire);
  }
  // A centred wheelset is symmetric: the left wheel is the mirror image of the right one in
  // track coordinates (CONTACT's reference: FY(TR) -36.24 and +36.24 N).
  const double tol = 1e-6 * g[1][2];
  EXPECT_NEAR(g[0][1], -g[1][1], tol);           // FY
  EXPECT_NEAR(g[0][2], g[1][2], tol);            // FZ
  EXPECT_NEAR(g[0][3], -g[1][3], tol * 1000.0);  // MX
  EXPECT_NEAR(g[0][4], g[1][4], tol * 1000.0);   // MY
  EXPECT_NEAR(g[0][5], -g[1][5], tol * 1000.0);  // MZ
  EXPECT_NEAR(loc[0][1], -loc[1][1], 1e-9);      // reference y
  EXPECT_NEAR(loc[0][25], -loc[1][25], 1e-9);    // rail marker y
  EXPECT_NEAR(loc[0][21], -loc[1][21], 1e-9);    // wheel marker y
  EXPECT_NEAR(g[1][1], 36.24, 0.1);

  // getprofilevalues task 2: the placed rail surface passes through the contact point.
  int ire = centred_wheel(49, 1, dir), task = 2, nints = 2, iparam[] = {0, 1}, nreals = 1;
  double ds[] = {0.2};
  int lenarr = 4000;
  std::vector<double> v(4000, 0.0);
  int task0 = 0;
  cntc_getprofilevalues(&ire, &task0, &nints, iparam, &nreals, ds, &lenarr, v.data());
  const int n = static_cast<int>(v[0]);
  ASSERT_GT(n, 100);
  ASSERT_LE(2 * n, lenarr);
  cntc_getprofilevalues(&ire, &task, &nints, iparam, &nreals, ds, &lenarr, v.data());
  double best = 1e30;
  for (int k = 0; k < n; ++k)
    best = std::min(best, std::hypot(v[k] - loc[1][1], v[n + k] - loc[1][2]));
  EXPECT_LT(best, 0.15);  // within the 0.2 mm sampling and the approach of the bodies
  // Task 3: the gauge point lies at half the gauge (1435/2 mm), GAUGHT = 14 mm below the top,
  // on the placed rail.
  std::vector<double> placed(v.begin(), v.begin() + 2 * n);
  int task3 = 3;
  std::vector<double> gauge(6, 0.0);
  int six = 6;
  cntc_getprofilevalues(&ire, &task3, &nints, iparam, &nreals, ds, &six, gauge.data());
  EXPECT_DOUBLE_EQ(gauge[4], 717.5);
  EXPECT_DOUBLE_EQ(gauge[5], 14.0);
  double nearest = 1e30;
  for (int k = 0; k < n; ++k)
    nearest = std::min(nearest, std::hypot(placed[k] - gauge[4], placed[n + k] - gauge[5]));
  EXPECT_LT(nearest, 0.15);
  EXPECT_NEAR(gauge[0] + gauge[2], gauge[4], 1e-9);  // rail not rolled: offsets add up

  // Subsurface stresses of a wheel/rail patch: common blocks (icp = -1) or the patch's own.
  int minus1 = -1, one = 1, iblk = 1, isubs = 9, nx = 1, ny = 1, nz = 8, ierror = -1;
  double x0[] = {0.0}, y0[] = {0.0}, zs[] = {0.5, 1.0, 1.5, 2.0, 3.0, 4.0, 6.0, 9.0};
  subs_addblock(&ire, &minus1, &iblk, &isubs, &nx, &ny, &nz, x0, y0, zs);
  subs_calculate(&ire, &minus1, &ierror);
  ASSERT_EQ(ierror, 0);
  int bx = 0, by = 0, bz = 0;
  subs_getblocksize(&ire, &one, &iblk, &bx, &by, &bz);
  EXPECT_EQ(bx * by * bz, 8);
  int rows = 8, ncol = 1, vm = 8;
  double sigvm[8] = {};
  subs_getresults(&ire, &one, &iblk, &rows, &ncol, &vm, sigvm);
  double pmax = 0.0;
  cntc_getmaximumpressure(&ire, &one, &pmax);
  // Below the centre of a near-Hertzian patch the von Mises stress rises from the surface to
  // an interior maximum of about 0.55-0.62 p0 (Johnson, ch. 3.4) and decays below it.
  const double peak = *std::max_element(std::begin(sigvm), std::end(sigvm));
  EXPECT_GT(peak, 0.50 * pmax);
  EXPECT_LT(peak, 0.65 * pmax);
  EXPECT_LT(sigvm[0], peak);
  EXPECT_LT(sigvm[7], peak);
  int two = 2;
  subs_addblock(&ire, &one, &iblk, &isubs, &nx, &ny, &two, x0, y0, zs);  // patch 1's own
  subs_calculate(&ire, &minus1, &ierror);
  subs_getblocksize(&ire, &one, &iblk, &bx, &by, &bz);
  EXPECT_EQ(bz, 2);
  cntc_finalize(&ire);
}

TEST(CntcWheelRail, MasslessRailDeflectionsAreLocationOutputs18And19) {
  // examples/massless_rail.inp case 1 (F=3): KYRAIL 5e4, KZRAIL 1e5 N/mm, FZ 10 kN (N=1).
  const std::string path =
      (std::filesystem::path(ROLLCONTACT_REPO_EXAMPLES_DIR) / "massless_rail.inp").string();
  int ire = 71, inp = 1988, len = static_cast<int>(path.size()), ierror = -1, icp = -1;
  int patch = 1, n24 = 24, n38 = 38;
  cntc_readinpfile(&ire, &inp, path.c_str(), &len, &ierror);
  ASSERT_EQ(ierror, 0);
  cntc_calculate(&ire, &icp, &ierror);
  ASSERT_EQ(ierror, 0);
  std::array<double, 24> g{};
  std::array<double, 38> loc{};
  cntc_getglobalforces(&ire, &icp, &n24, g.data());
  cntc_getcontactlocation(&ire, &patch, &n38, loc.data());
  EXPECT_DOUBLE_EQ(loc[18], 0.1);  // δz = (FZ + FZRAIL)/KZRAIL
  const double eps = 1e-5;         // EPS of the file: KY·δy = FY(TR) within about KY·EPS
  EXPECT_NEAR(loc[17], g[1] / 5e4, 2.0 * eps);
  EXPECT_GT(loc[17], 0.1);
  // A softer rail through cntc_settrackdimensions Z = 32: [ky, fy, kz, fz, dystep0].
  int z = 32, n = 5;
  double rail[5] = {2e4, 0.0, 2e5, 1000.0, 1.0};
  cntc_settrackdimensions(&ire, &z, &n, rail);
  cntc_calculate(&ire, &icp, &ierror);
  ASSERT_EQ(ierror, 0);
  cntc_getglobalforces(&ire, &icp, &n24, g.data());
  cntc_getcontactlocation(&ire, &patch, &n38, loc.data());
  EXPECT_DOUBLE_EQ(loc[18], 11000.0 / 2e5);
  EXPECT_NEAR(loc[17], g[1] / 2e4, 2.0 * eps);
}

TEST(CntcWheelRail, RollerRigThroughTheLibrary) {
  // examples/roller_rig.inp case 1 (C1 = 5, NOMRADR 685 mm) read through the library; then the
  // roller becomes a ring of 1500 mm (cntc_settrackdimensions Z = 1: GAUGHT, GAUGSQ, GAUGWD,
  // CANT, NOMRADR) turning at the same surface speed (cntc_setwheelsetvelocity: RPITCH first):
  // the wheel conforms to it and the pressure falls, FZ stays at 10 kN.
  const std::string path =
      (std::filesystem::path(ROLLCONTACT_REPO_EXAMPLES_DIR) / "roller_rig.inp").string();
  int ire = 72, inp = 1988, len = static_cast<int>(path.size()), ierror = -1, icp = -1;
  int patch = 1, n24 = 24;
  cntc_readinpfile(&ire, &inp, path.c_str(), &len, &ierror);
  ASSERT_EQ(ierror, 0);
  cntc_calculate(&ire, &icp, &ierror);
  ASSERT_EQ(ierror, 0);
  std::array<double, 24> g{};
  cntc_getglobalforces(&ire, &icp, &n24, g.data());
  EXPECT_NEAR(g[2], 1e4, 1e4 * 1e-5 * 1.01);
  double pmax_roller = 0.0, pmax_ring = 0.0;
  cntc_getmaximumpressure(&ire, &patch, &pmax_roller);
  int z = 1, n5 = 5, e = 2, n6 = 6;
  double track[5] = {14.0, 0.0, 1435.0, 0.0, -1500.0};
  cntc_settrackdimensions(&ire, &z, &n5, track);
  double velocity[6] = {-2000.0 / 1500.0, 0.0, 0.0, 0.0, 0.0, -4.34811810};
  cntc_setwheelsetvelocity(&ire, &e, &n6, velocity);
  cntc_calculate(&ire, &icp, &ierror);
  ASSERT_EQ(ierror, 0);
  cntc_getglobalforces(&ire, &icp, &n24, g.data());
  EXPECT_NEAR(g[2], 1e4, 1e4 * 1e-5 * 1.01);
  cntc_getmaximumpressure(&ire, &patch, &pmax_ring);
  EXPECT_LT(pmax_ring, 0.8 * pmax_roller);
  cntc_finalize(&ire);
}

TEST(CntcWheelRail, ConformalContactAndInclinationCorrectionByTheirFlags) {
  // examples/conformal_flange_root.inp case 1 (planar, D=2) read through the library; with
  // CNTC_ic_discns = 4 the same wheel is solved conformally, as the file's case 2 (rollcontact
  // run: F(TR) = (−850.02, 572.84, 10000) planar, (−851.84, 561.20, 9999.9) N conformal).
  const std::string path =
      (std::filesystem::path(ROLLCONTACT_REPO_EXAMPLES_DIR) / "conformal_flange_root.inp").string();
  int ire = 73, inp = 1988, len = static_cast<int>(path.size()), ierror = -1, icp = -1;
  int n24 = 24;
  cntc_readinpfile(&ire, &inp, path.c_str(), &len, &ierror);
  ASSERT_EQ(ierror, 0);
  cntc_calculate(&ire, &icp, &ierror);
  ASSERT_EQ(ierror, 0);
  std::array<double, 24> planar{}, conformal{};
  cntc_getglobalforces(&ire, &icp, &n24, planar.data());
  int nflags = 1, flags[1] = {CNTC_ic_discns}, values[1] = {4};
  cntc_setflags(&ire, &icp, &nflags, flags, values);
  cntc_calculate(&ire, &icp, &ierror);
  ASSERT_EQ(ierror, 0);
  cntc_getglobalforces(&ire, &icp, &n24, conformal.data());
  EXPECT_NEAR(planar[1], 572.84, 0.01);
  EXPECT_NEAR(conformal[1], 561.20, 0.01);
  EXPECT_NEAR(conformal[0], -851.84, 0.01);
  EXPECT_NEAR(conformal[2], 1e4, 2.0);

  // Blanco's inclination correction on the same conformal patch: C3 = 4, IF_METH 0, variant 4,
  // with MAXOUT 5 for the coupling it brings (rollcontact run on the file with a third case
  // 0144002 / 0000331 / MAXOUT 5 / "0 4": F(TR) = (−852.93, 565.99, 10000) N; the correction
  // moves FY by 4.8 N, 500 times the tolerance here).
  int gdigit = 0, nints = 4, iparam[4] = {999, 100, 30, 5}, nreals = 1;
  double rparam[1] = {1e-5};
  cntc_setsolverflags(&ire, &icp, &gdigit, &nints, iparam, &nreals, rparam);
  int ncorr = 3, corr_flags[3] = {CNTC_ic_inflcf, CNTC_ic_ifmeth, CNTC_ic_ifvari},
      corr_values[3] = {4, 0, 4};
  cntc_setflags(&ire, &icp, &ncorr, corr_flags, corr_values);
  cntc_calculate(&ire, &icp, &ierror);
  ASSERT_EQ(ierror, 0);
  std::array<double, 24> corrected{};
  cntc_getglobalforces(&ire, &icp, &n24, corrected.data());
  EXPECT_NEAR(corrected[0], -852.93, 0.01);
  EXPECT_NEAR(corrected[1], 565.99, 0.01);
  EXPECT_NEAR(corrected[2], 1e4, 2.0);
  cntc_finalize(&ire);
}

}  // namespace
