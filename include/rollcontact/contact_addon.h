/* rollcontact's CONTACT-compatible C library interface (the cntc_* routines).
 *
 * A program written for CONTACT's library (contact_addon.h, release 25.1) links or loads
 * librollcontact_cntc.so — or the same library under CONTACT's file name
 * contact_addon_linux64.so — without source changes. Conventions (spec library-api.md §1):
 * every routine returns void and takes every argument by pointer; strings come with their
 * length; arrays are caller-allocated, element numbering x fastest (j = ix + mx*(iy-1)).
 * Result elements ire = 1..999 (module 1 wheel/rail or module 3 basic contact), contact
 * problems icp = 1..9 in module 3, icp = -1 for a whole wheel/rail problem in module 1.
 * Errors never abort: a bad handle or argument is logged and the outputs are left untouched;
 * routines with an ierror argument return CONTACT's codes (CNTC_err_*).
 *
 * This release implements the life cycle, the settings and per-patch results of modules 1
 * and 3, and module 1's track, wheelset, profile and total-force routines; see
 * docs/c-library.md for what is not served yet.
 */
#ifndef ROLLCONTACT_CONTACT_ADDON_H
#define ROLLCONTACT_CONTACT_ADDON_H

#ifdef __cplusplus
extern "C" {
#endif

/* Interface version: 100*major + 10*minor + update of the CONTACT interface served. */
#define CNTC_IFCVER 2520

/* Unit conventions (flag CNTC_if_units). */
#define CNTC_un_cntc 1934  /* mm, N, mm/s, rad; forces on body 1 (default) */
#define CNTC_un_spck 1935  /* m, N, m/s, rad; forces on body 2 */
#define CNTC_un_si 1936    /* m, N, m/s, rad; forces on body 1 */
#define CNTC_un_imper 1937 /* not implemented: CONTACT units */

/* Flag codes (cntc_setflags, cntc_getflags, cntc_setglobalflags). */
#define CNTC_if_units 1933
#define CNTC_ic_config 1967
#define CNTC_ic_pvtime 1970
#define CNTC_ic_bound 1971
#define CNTC_ic_tang 1972
#define CNTC_ic_norm 1973
#define CNTC_ic_force 1974
#define CNTC_ic_frclaw 1976
#define CNTC_ic_discns 1977
#define CNTC_ic_inflcf 1978
#define CNTC_ic_mater 1979
#define CNTC_ic_exrhs 1980
#define CNTC_ic_xflow 1981
#define CNTC_ic_heat 1982
#define CNTC_ic_iestim 1983
#define CNTC_ic_output 1984
#define CNTC_ic_flow 1985
#define CNTC_ic_return 1986
#define CNTC_ic_matfil 1987
#define CNTC_ic_sens 1988
#define CNTC_ic_ifmeth 1989
#define CNTC_ic_ifvari 1990
#define CNTC_ic_sbsout 1991
#define CNTC_ic_sbsfil 1992
#define CNTC_ic_npomax 1993
#define CNTC_if_idebug 2000
#define CNTC_if_licdbg 2001
#define CNTC_if_wrtinp 2002
#define CNTC_if_openmp 2003
#define CNTC_if_timers 2004
#define CNTC_if_ncase 2005
#define CNTC_FLAGS_DIM 25 /* the most flags intended per call (not enforced) */

/* Metadata codes (cntc_setmetadata). */
#define CNTC_mt_tim 2011
#define CNTC_mt_xr 2012
#define CNTC_mt_yr 2013
#define CNTC_mt_xw 2014
#define CNTC_mt_yw 2015
#define CNTC_mt_sw 2016
#define CNTC_mt_run 2021
#define CNTC_mt_axle 2022
#define CNTC_mt_side 2023

/* Input-file types (cntc_readinpfile): only 1988 is read; the others return CNTC_err_input. */
#define CNTC_inp_vamp 1984
#define CNTC_inp_modul1 1988
#define CNTC_inp_spck 1990
#define CNTC_inp_gensys 1992

/* Field codes (cntc_getfielddata). */
#define CNTC_fld_h 1
#define CNTC_fld_mu 2
#define CNTC_fld_px 3
#define CNTC_fld_py 4
#define CNTC_fld_pn 5
#define CNTC_fld_ux 7
#define CNTC_fld_uy 8
#define CNTC_fld_un 9
#define CNTC_fld_sx 15
#define CNTC_fld_sy 16
#define CNTC_fld_temp1 20
#define CNTC_fld_temp2 21
#define CNTC_fld_taucrt 11
#define CNTC_fld_uplsx 12
#define CNTC_fld_uplsy 13
#define CNTC_fld_wx 22
#define CNTC_fld_wy 23

/* Error codes. */
#define CNTC_err_allow -12
#define CNTC_err_search -25
#define CNTC_err_ftot -26
#define CNTC_err_broydn -26 /* the same code under the name CONTACT's Python wrapper uses */
#define CNTC_err_norm -27
#define CNTC_err_tang -28
#define CNTC_err_tol -29
#define CNTC_err_icp -31
#define CNTC_err_profil -32
#define CNTC_err_frclaw -33
#define CNTC_err_discr -34
#define CNTC_err_input -39
#define CNTC_err_other -99

/* 2.1 Life cycle */
void cntc_initializefirst(int* ifcver, int* ierror, int* ioutput, const char* c_wrkdir,
                          const char* c_outdir, const char* c_expnam, int* len_wrkdir,
                          int* len_outdir, int* len_expnam);
void cntc_initializefirst_new(int* ifcver, int* ierror, int* ioutput, const char* c_wrkdir,
                              const char* c_outdir, const char* c_expnam, int* len_wrkdir,
                              int* len_outdir, int* len_expnam);
void cntc_initialize(int* ire, int* imodul, int* ifcver, int* ierror, const char* c_outdir,
                     int* len_outdir);
void cntc_setfileunits(int* nunits, int* iunits);
void cntc_setglobalflags(int* lenflg, int* params, int* values);
void cntc_finalize(int* ire);
void cntc_finalizelast(void);
void cntc_getmaxnumthreads(int* mxthrd);

/* 2.2 Configuration common to modules 1 and 3 */
void cntc_setflags(int* ire, int* icp, int* lenflg, int* params, int* values);
void cntc_getflags(int* ire, int* icp, int* nparam, int* iparam, int* values);
void cntc_setsolverflags(int* ire, int* icp, int* gdigit, int* nints, int* iparam, int* nreals,
                         double* rparam);
void cntc_setmaterialparameters(int* ire, int* icp, int* mdigit, int* nparam, double* rparam);
void cntc_settimestep(int* ire, int* icp, double* dt);
void cntc_setrollingstepsize(int* ire, int* icp, double* chi, double* dq);
void cntc_setfrictionmethod(int* ire, int* icp, int* imeth, int* nparam, double* params);
void cntc_setpotcontact(int* ire, int* icp, int* ipotcn, int* nparam, double* rparam);
void cntc_settangentialforces(int* ire, int* icp, double* fx, double* fy);
void cntc_setmetadata(int* ire, int* icp, int* lenmta, int* params, double* values);
void cntc_settemperaturedata(int* ire, int* icp, int* imeth, int* nparam, double* rparam);
void cntc_readinpfile(int* ire, int* inp_type, const char* c_fname, int* len_fname, int* ierror);
/* Older names some clients still bind: setmaterialproperties is setmaterialparameters with M = 0
 * (g1, nu1, g2, nu2); settrackdimensions_new is settrackdimensions; settrackdimensions_old and
 * setinterfaciallayer are refused with a log line. */
void cntc_setmaterialproperties(int* ire, int* icp, double* g1, double* nu1, double* g2,
                                double* nu2);
void cntc_setinterfaciallayer(int* ire, int* icp, int* imeth, int* nparam, double* params);
void cntc_settrackdimensions_new(int* ire, int* ztrack, int* nparam, double* rparam);
void cntc_settrackdimensions_old(int* ire, int* ztrack, int* nparam, double* rparam);

/* 2.3 Module 3 only */
void cntc_setreferencevelocity(int* ire, int* icp, double* veloc);
void cntc_sethertzcontact(int* ire, int* icp, int* ipotcn, int* nparam, double* rparam);
void cntc_setpenetration(int* ire, int* icp, double* pen);
void cntc_setnormalforce(int* ire, int* icp, double* fn);
void cntc_setundeformeddistc(int* ire, int* icp, int* ibase, int* nparam, double* prmudf);
void cntc_setcreepages(int* ire, int* icp, double* vx, double* vy, double* phi);
void cntc_setextrarigidslip(int* ire, int* icp, int* lenarr, double* wx, double* wy);
void cntc_gethertzcontact(int* ire, int* icp, int* lenarr, double* values);

/* 2.4 Module 1 only: track, wheelset, vertical force */
void cntc_setverticalforce(int* ire, double* fz);
void cntc_settrackdimensions(int* ire, int* ztrack, int* nparam, double* rparam);
void cntc_setwheelsetdimensions(int* ire, int* ewheel, int* nparam, double* rparam);
void cntc_setwheelsetposition(int* ire, int* ewheel, int* nparam, double* rparam);
void cntc_setwheelsetvelocity(int* ire, int* ewheel, int* nparam, double* rparam);
void cntc_setwheelsetflexibility(int* ire, int* ewheel, int* nparam, double* rparam);
void cntc_getwheelsetposition(int* ire, int* lenarr, double* values);
void cntc_getwheelsetvelocity(int* ire, int* lenarr, double* values);

/* 2.5 Module 1 only: profiles */
void cntc_setprofileinputfname(int* ire, const char* c_fname, int* len_fname, int* nints,
                               int* iparam, int* nreals, double* rparam);
void cntc_setprofileinputvalues(int* ire, int* npoint, double* values, int* nints, int* iparam,
                                int* nreals, double* rparam);
void cntc_getprofilevalues(int* ire, int* itask, int* nints, int* iparam, int* nreals,
                           double* rparam, int* lenarr, double* values);
void cntc_getprofilevalues_new(int* ire, int* itask, int* nints, int* iparam, int* nreals,
                               double* rparam, int* lenarr, double* values);

/* 2.6 Subsurface stresses */
void subs_addblock(int* ire, int* icp, int* iblk, int* isubs, int* nx, int* ny, int* nz,
                   double* xparam, double* yparam, double* zparam);
void subs_calculate(int* ire, int* icp, int* ierror);
void subs_getblocksize(int* ire, int* icp, int* iblk, int* nx, int* ny, int* nz);
void subs_getresults(int* ire, int* icp, int* iblk, int* lenarr, int* ncol, int* icol,
                     double* values);

/* 2.7 Solving */
void cntc_calculate(int* ire, int* icp, int* ierror);
void cntc_calculate1(int* ire, int* ierror);
void cntc_calculate3(int* ire, int* icp, int* ierror);

/* 2.8 Results (module 1 totals) */
void cntc_getnumcontactpatches(int* ire, int* npatch);
void cntc_getglobalforces(int* ire, int* icp, int* lenarr, double* values);
void cntc_getcontactlocation(int* ire, int* icp, int* lenarr, double* values);

/* 2.9 Results per patch */
void cntc_getreferencevelocity(int* ire, int* icp, double* veloc);
void cntc_getnumelements(int* ire, int* icp, int* mx, int* my);
void cntc_getgriddiscretization(int* ire, int* icp, double* dx, double* dy);
void cntc_getpotcontact(int* ire, int* icp, int* lenarr, double* values);
void cntc_getpenetration(int* ire, int* icp, double* pen);
void cntc_getcreepages(int* ire, int* icp, double* vx, double* vy, double* phi);
void cntc_getcontactforces(int* ire, int* icp, double* fn, double* tx, double* ty, double* mz);
void cntc_getcontactpatchareas(int* ire, int* icp, double* carea, double* harea, double* sarea);
void cntc_getelementdivision(int* ire, int* icp, int* lenarr, int* eldiv);
void cntc_getmaximumpressure(int* ire, int* icp, double* pnmax);
void cntc_getmaximumtraction(int* ire, int* icp, double* ptmax);
void cntc_getmaximumtemperature(int* ire, int* icp, double* t1max, double* t2max);
void cntc_getfielddata(int* ire, int* icp, int* ifld, int* lenarr, double* fld);
void cntc_gettractions(int* ire, int* icp, int* lenarr, double* pn, double* px, double* py);
void cntc_getmicroslip(int* ire, int* icp, int* lenarr, double* sx, double* sy);
void cntc_getdisplacements(int* ire, int* icp, int* lenarr, double* un, double* ux, double* uy);
void cntc_getsensitivities(int* ire, int* icp, int* lenout, int* lenin, double* sens);
void cntc_getparameters(int* ire, int* icp, int* itask, int* lenarr, double* values);
void cntc_getcalculationtime(int* ire, int* icp, double* tcpu, double* twall);
void cntc_resetcalculationtime(int* ire, int* icp);

#ifdef __cplusplus
}
#endif

#endif /* ROLLCONTACT_CONTACT_ADDON_H */
