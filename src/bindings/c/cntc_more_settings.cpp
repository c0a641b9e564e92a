// The remaining settings of spec library-api.md §2.2–2.3: metadata, temperature, extra rigid
// slip, reading a module-1 input file, and the names older clients still bind
// (setmaterialproperties, settrackdimensions_new/_old, setinterfaciallayer). Each either stores
// what CONTACT stores or refuses with a log line, never silently.

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <variant>

#include "bindings/c/cntc_export.hpp"
#include "bindings/c/cntc_library.hpp"
#include "format/inp/inp_reader.hpp"
#include "rollcontact/errors.hpp"

namespace rollcontact::cntc {
namespace {}  // namespace
}  // namespace rollcontact::cntc

using namespace rollcontact;
using namespace rollcontact::cntc;

CNTC_EXPORT void cntc_setmetadata(int* ire, int* icp, int* lenmta, int* params, double* values) {
  const Target t = open_target(ire, icp, Access::Settings, "cntc_setmetadata");
  if (!t || lenmta == nullptr || (*lenmta > 0 && (params == nullptr || values == nullptr))) return;
  auto& meta = t.m3 != nullptr ? t.m3->metadata : t.m1->metadata;
  // 2011 time, 2012-2016 positions, 2021-2023 run, axle, side: recorded for the output files.
  static constexpr int codes[9] = {2011, 2012, 2013, 2014, 2015, 2016, 2021, 2022, 2023};
  for (int i = 0; i < *lenmta; ++i) {
    const int* c = std::find(std::begin(codes), std::end(codes), params[i]);
    if (c == std::end(codes)) {
      library().log(fmt::format("cntc_setmetadata: unknown code {} ignored", params[i]));
      continue;
    }
    const std::size_t k = static_cast<std::size_t>(c - std::begin(codes));
    meta[k] = k >= 6 ? std::round(values[i]) : values[i];
  }
}

CNTC_EXPORT void cntc_settemperaturedata(int* ire, int* icp, int* imeth, int* nparam,
                                         double* rparam) {
  constexpr const char* name = "cntc_settemperaturedata";
  const Target t = open_target(ire, icp, Access::Either, name);
  if (!t) return;
  if (imeth == nullptr || nparam == nullptr) return reject(name, "null argument");
  const int h = *imeth;
  if (h != 0 && h != 1 && h != 3) return reject(name, fmt::format("H = {} not 0, 1 or 3", h));
  if (h <= 1 && *nparam > 1) return reject(name, fmt::format("H = {} takes 0 or 1 values", h));
  if (h == 3 && *nparam != 9) return reject(name, "H = 3 needs 9 values (release 25.1: betapl)");
  if (h == 3 && rparam == nullptr) return reject(name, "null array");
  format::ControlDigits& d = t.m3 != nullptr ? t.m3->record.digits : t.m1->record.digits;
  format::HeatParameters& heat = t.m3 != nullptr ? t.m3->record.heat : t.m1->record.heat;
  d.h = h;
  if (h != 3) return;
  const double len = t.units().length;
  // λ per length and ρ per volume: divided by the length factor and its cube (§2.2).
  heat = {rparam[0], rparam[1], rparam[2] / len, rparam[3] / (len * len * len),
          rparam[4], rparam[5], rparam[6] / len, rparam[7] / (len * len * len),
          rparam[8]};
}

CNTC_EXPORT void cntc_setextrarigidslip(int* ire, int* icp, int* lenarr, double* wx, double* wy) {
  constexpr const char* name = "cntc_setextrarigidslip";
  Module3Problem* p = open_target(ire, icp, Access::Module3, name).m3;
  if (p == nullptr) return;
  if (lenarr == nullptr || (*lenarr > 0 && (wx == nullptr || wy == nullptr)))
    return reject(name, "null argument");
  const auto& pc = p->record.potential;
  if (!p->grid_given) return reject(name, "set the potential contact first");
  const std::size_t npot = static_cast<std::size_t>(pc.mx) * static_cast<std::size_t>(pc.my);
  auto& k = p->record.kinematics;
  k.extra_slip.assign(2 * npot, 0.0);
  const std::size_t n = std::min(npot, static_cast<std::size_t>(std::max(0, *lenarr)));
  for (std::size_t i = 0; i < n; ++i) {
    k.extra_slip[2 * i] = wx[i];
    k.extra_slip[2 * i + 1] = wy[i];
  }
  // CONTACT stores E = 1; in the case record the per-element values are E = 9 (getflags
  // reports 1).
  k.extra_slip_mode = 9;
  p->record.digits.e = 9;
}

CNTC_EXPORT void cntc_setmaterialproperties(int* ire, int* icp, double* g1, double* nu1, double* g2,
                                            double* nu2) {
  // The pre-release-21 form of setmaterialparameters with M = 0.
  if (g1 == nullptr || nu1 == nullptr || g2 == nullptr || nu2 == nullptr) return;
  int m = 0, n = 4;
  double values[4] = {*nu1, *nu2, *g1, *g2};
  cntc_setmaterialparameters(ire, icp, &m, &n, values);
}

CNTC_EXPORT void cntc_setinterfaciallayer(int* ire, int* icp, int* /*imeth*/, int* /*nparam*/,
                                          double* /*params*/) {
  const Target t = open_target(ire, icp, Access::Settings, "cntc_setinterfaciallayer");
  if (t) reject("cntc_setinterfaciallayer", "obsolete: use cntc_setmaterialparameters M = 4");
}

CNTC_EXPORT void cntc_settrackdimensions_new(int* ire, int* ztrack, int* nparam, double* rparam) {
  cntc_settrackdimensions(ire, ztrack, nparam, rparam);
}

CNTC_EXPORT void cntc_settrackdimensions_old(int* ire, int* /*ztrack*/, int* /*nparam*/,
                                             double* /*rparam*/) {
  const int whole = -1;
  if (open_target(ire, &whole, Access::Module1, "cntc_settrackdimensions_old"))
    reject("cntc_settrackdimensions_old", "the pre-release-21 layout; use cntc_settrackdimensions");
}

CNTC_EXPORT void cntc_readinpfile(int* ire, int* inp_type, const char* c_fname, int* len_fname,
                                  int* ierror) {
  constexpr const char* name = "cntc_readinpfile";
  int code = 0;
  const int whole = -1;
  Module1Problem* p = open_target(ire, &whole, Access::Module1, name, &code).m1;
  auto fail = [&](int c) {
    if (ierror != nullptr) *ierror = c;
  };
  if (p == nullptr) return fail(code);
  if (inp_type == nullptr || *inp_type != 1988) {
    library().log(fmt::format("{}: input type {} not supported (1988: CONTACT module-1 .inp)", name,
                              inp_type != nullptr ? *inp_type : 0));
    return fail(CNTC_err_input);
  }
  std::filesystem::path path = c_string(c_fname, len_fname);
  if (path.is_relative()) path = library().working_folder() / path;
  try {
    const auto cases = format::read_input_cases(path);
    for (const auto& c : cases)
      if (const auto* w = std::get_if<format::WheelRailRecord>(&c)) {
        // The first module-1 case becomes the element's configuration (units: CONTACT's).
        p->record = *w;
        p->rail_error.clear();
        p->wheel_error.clear();
        p->friction_given = true;
        p->units = Units{};
        return fail(0);
      }
    library().log(fmt::format("{}: {} has no module-1 case", name, path.string()));
    return fail(CNTC_err_input);
  } catch (const Error& e) {
    library().log(std::string(name) + ": " + e.what());
    return fail(CNTC_err_input);
  }
}
