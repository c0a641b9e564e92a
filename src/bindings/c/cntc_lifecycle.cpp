// cntc_* life cycle (spec library-api.md §2.1) and global flags.

#include <thread>

#include "bindings/c/cntc_export.hpp"
#include "bindings/c/cntc_library.hpp"

using rollcontact::cntc::c_string;
using rollcontact::cntc::library;

CNTC_EXPORT void cntc_initializefirst(int* ifcver, int* ierror, int* ioutput, const char* c_wrkdir,
                                      const char* c_outdir, const char* c_expnam, int* len_wrkdir,
                                      int* len_outdir, int* len_expnam) {
  if (ifcver != nullptr) *ifcver = CNTC_IFCVER;
  const bool first =
      library().initialize_first(ioutput != nullptr ? *ioutput : 0, c_string(c_wrkdir, len_wrkdir),
                                 c_string(c_outdir, len_outdir), c_string(c_expnam, len_expnam));
  if (first && ierror != nullptr) *ierror = 0;  // a repeat call leaves it as passed (§2.1)
}

CNTC_EXPORT void cntc_initializefirst_new(int* ifcver, int* ierror, int* ioutput,
                                          const char* c_wrkdir, const char* c_outdir,
                                          const char* c_expnam, int* len_wrkdir, int* len_outdir,
                                          int* len_expnam) {
  cntc_initializefirst(ifcver, ierror, ioutput, c_wrkdir, c_outdir, c_expnam, len_wrkdir,
                       len_outdir, len_expnam);
}

CNTC_EXPORT void cntc_initialize(int* ire, int* imodul, int* ifcver, int* ierror,
                                 const char* c_outdir, int* len_outdir) {
  if (ifcver != nullptr) *ifcver = CNTC_IFCVER;
  library().initialize_first(0, "", c_string(c_outdir, len_outdir), "");
  const int code = ire != nullptr && imodul != nullptr ? library().create(*ire, *imodul) : -12;
  if (ierror != nullptr) *ierror = code;
}

CNTC_EXPORT void cntc_setfileunits(int* /*nunits*/, int* /*iunits*/) {
  // Fortran unit numbers: nothing to choose here (§2.1 allows ignoring the call).
}

CNTC_EXPORT void cntc_setglobalflags(int* lenflg, int* params, int* values) {
  if (lenflg == nullptr || params == nullptr || values == nullptr) return;
  for (int i = 0; i < *lenflg; ++i) {
    if (params[i] == CNTC_if_idebug) library().set_debug_level(values[i]);
    // CNTC_if_licdbg: no licence; CNTC_if_openmp: one thread per problem for now.
  }
}

CNTC_EXPORT void cntc_finalize(int* ire) {
  if (ire != nullptr) library().finalize(*ire);
}

CNTC_EXPORT void cntc_finalizelast(void) {
  library().finalize_last();
}

CNTC_EXPORT void cntc_getmaxnumthreads(int* mxthrd) {
  if (mxthrd == nullptr) return;
  const unsigned cores = std::thread::hardware_concurrency();
  *mxthrd = cores == 0 ? 1 : static_cast<int>(cores < 999 ? cores : 999);
}
