/* A client of CONTACT's library interface, written from the cntc_* specification only: the
 * steady-rolling Hertzian case of examples/steady_rolling.inp through cntc_* calls. Prints
 * FN FX FY MZ (CONTACT units) on one line.
 *
 *   cntc_hertz_rolling link [FN FX FY MZ]         the routines it was linked with
 *   cntc_hertz_rolling dlopen LIB [FN FX FY MZ]   the routines of the shared library LIB
 *                                                 (e.g. under CONTACT's contact_addon_linux64.so)
 *
 * With FN FX FY MZ given (e.g. from `rollcontact run` on the same case), exits 1 unless every
 * value agrees within 1e-12 of FN: the same problem solved by the same code.
 */
#include <dlfcn.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "rollcontact/contact_addon.h"

typedef struct {
  void (*initialize)(int*, int*, int*, int*, const char*, int*);
  void (*setflags)(int*, int*, int*, int*, int*);
  void (*setsolverflags)(int*, int*, int*, int*, int*, int*, double*);
  void (*setmaterialparameters)(int*, int*, int*, int*, double*);
  void (*setfrictionmethod)(int*, int*, int*, int*, double*);
  void (*sethertzcontact)(int*, int*, int*, int*, double*);
  void (*setreferencevelocity)(int*, int*, double*);
  void (*setrollingstepsize)(int*, int*, double*, double*);
  void (*setnormalforce)(int*, int*, double*);
  void (*setcreepages)(int*, int*, double*, double*, double*);
  void (*calculate)(int*, int*, int*);
  void (*getcontactforces)(int*, int*, double*, double*, double*, double*);
  void (*getnumelements)(int*, int*, int*, int*);
  void (*finalize)(int*);
  void (*finalizelast)(void);
} Api;

static int load(Api* api, const char* path) {
  void* lib = dlopen(path, RTLD_NOW | RTLD_LOCAL);
  if (lib == NULL) {
    fprintf(stderr, "cannot load %s: %s\n", path, dlerror());
    return 0;
  }
#define LOAD(field, name)                              \
  *(void**)(&api->field) = dlsym(lib, name);           \
  if (api->field == NULL) {                            \
    fprintf(stderr, "%s: no symbol %s\n", path, name); \
    return 0;                                          \
  }
  LOAD(initialize, "cntc_initialize")
  LOAD(setflags, "cntc_setflags")
  LOAD(setsolverflags, "cntc_setsolverflags")
  LOAD(setmaterialparameters, "cntc_setmaterialparameters")
  LOAD(setfrictionmethod, "cntc_setfrictionmethod")
  LOAD(sethertzcontact, "cntc_sethertzcontact")
  LOAD(setreferencevelocity, "cntc_setreferencevelocity")
  LOAD(setrollingstepsize, "cntc_setrollingstepsize")
  LOAD(setnormalforce, "cntc_setnormalforce")
  LOAD(setcreepages, "cntc_setcreepages")
  LOAD(calculate, "cntc_calculate")
  LOAD(getcontactforces, "cntc_getcontactforces")
  LOAD(getnumelements, "cntc_getnumelements")
  LOAD(finalize, "cntc_finalize")
  LOAD(finalizelast, "cntc_finalizelast")
#undef LOAD
  return 1;
}

static void linked(Api* api) {
  api->initialize = cntc_initialize;
  api->setflags = cntc_setflags;
  api->setsolverflags = cntc_setsolverflags;
  api->setmaterialparameters = cntc_setmaterialparameters;
  api->setfrictionmethod = cntc_setfrictionmethod;
  api->sethertzcontact = cntc_sethertzcontact;
  api->setreferencevelocity = cntc_setreferencevelocity;
  api->setrollingstepsize = cntc_setrollingstepsize;
  api->setnormalforce = cntc_setnormalforce;
  api->setcreepages = cntc_setcreepages;
  api->calculate = cntc_calculate;
  api->getcontactforces = cntc_getcontactforces;
  api->getnumelements = cntc_getnumelements;
  api->finalize = cntc_finalize;
  api->finalizelast = cntc_finalizelast;
}

int main(int argc, char** argv) {
  Api api;
  int first_expected = 0;
  if (argc >= 2 && strcmp(argv[1], "link") == 0) {
    linked(&api);
    first_expected = 2;
  } else if (argc >= 3 && strcmp(argv[1], "dlopen") == 0) {
    if (!load(&api, argv[2])) return 2;
    first_expected = 3;
  } else {
    fprintf(stderr, "usage: %s link | dlopen LIBRARY\n", argv[0]);
    return 2;
  }
  int ire = 1, icp = 1, imodul = 3, ifcver = 0, ierror = 0, len = 1;
  api.initialize(&ire, &imodul, &ifcver, &ierror, " ", &len);
  if (ierror != 0 || ifcver < 2510) {
    fprintf(stderr, "cntc_initialize: ierror %d, ifcver %d\n", ierror, ifcver);
    return 1;
  }
  /* Steady rolling (T = 3), normal force given (N = 1), creepages given (F = 0), CONTACT units. */
  int flags[] = {CNTC_if_units, CNTC_ic_tang, CNTC_ic_norm, CNTC_ic_force, CNTC_ic_pvtime};
  int values[] = {CNTC_un_cntc, 3, 1, 0, 2};
  int nflags = 5;
  api.setflags(&ire, &icp, &nflags, flags, values);

  int g = 0, nints = 4, nreals = 1, iparam[] = {999, 100, 30, 1};
  double eps = 1e-5;
  api.setsolverflags(&ire, &icp, &g, &nints, iparam, &nreals, &eps);

  int m = 0, nmat = 4;
  double material[] = {0.28, 0.28, 82000.0, 82000.0}; /* nu1, nu2, G1, G2 [N/mm2] */
  api.setmaterialparameters(&ire, &icp, &m, &nmat, material);

  int law = 0, nfric = 2;
  double friction[] = {0.3, 0.3};
  api.setfrictionmethod(&ire, &icp, &law, &nfric, friction);

  int ipotcn = -1, nhertz = 5;
  double hertz[] = {30, 30, 0.002, 0.004, 1.1}; /* mx, my, A1, B1 [1/mm], scale */
  api.sethertzcontact(&ire, &icp, &ipotcn, &nhertz, hertz);

  double veloc = 2000.0, chi = 0.0, dq = 0.1, fn = 10000.0;
  api.setreferencevelocity(&ire, &icp, &veloc);
  api.setrollingstepsize(&ire, &icp, &chi, &dq);
  api.setnormalforce(&ire, &icp, &fn);
  double cksi = 0.001, ceta = -0.0005, cphi = 0.0001;
  api.setcreepages(&ire, &icp, &cksi, &ceta, &cphi);

  api.calculate(&ire, &icp, &ierror);
  if (ierror < 0) {
    fprintf(stderr, "cntc_calculate: ierror %d\n", ierror);
    return 1;
  }
  int mx = 0, my = 0;
  api.getnumelements(&ire, &icp, &mx, &my);
  if (mx != 30 || my != 30) {
    fprintf(stderr, "grid %d x %d, expected 30 x 30\n", mx, my);
    return 1;
  }
  double f[4] = {0.0, 0.0, 0.0, 0.0};
  api.getcontactforces(&ire, &icp, &f[0], &f[1], &f[2], &f[3]);
  printf("%.17g %.17g %.17g %.17g\n", f[0], f[1], f[2], f[3]);
  if (argc >= first_expected + 4) {
    static const char* names[] = {"FN", "FX", "FY", "MZ"};
    for (int k = 0; k < 4; ++k) {
      const double expected = strtod(argv[first_expected + k], NULL);
      if (fabs(f[k] - expected) > 1e-12 * fabs(f[0])) {
        fprintf(stderr, "%s = %.17g, expected %.17g\n", names[k], f[k], expected);
        return 1;
      }
    }
  }

  /* Bad handles are refused with CONTACT's access codes, never a crash. */
  int bad_icp = 0, bad_ire = 1000, code = 0;
  api.calculate(&ire, &bad_icp, &code);
  if (code != -104) {
    fprintf(stderr, "calculate with icp = 0 gave %d, expected -104\n", code);
    return 1;
  }
  api.calculate(&bad_ire, &icp, &code);
  if (code != -101) {
    fprintf(stderr, "calculate with ire = 1000 gave %d, expected -101\n", code);
    return 1;
  }
  api.getcontactforces(&ire, &icp, NULL, NULL, NULL, NULL);
  api.finalize(&ire);
  api.finalizelast();
  return 0;
}
