// cntc_* routines of module 1 (wheel/rail, spec library-api.md §2.4, §2.5, §2.8): track,
// wheelset, vertical force and profiles go into the element's WheelRailRecord in internal units
// (mm, N, s, rad) — the record a module-1 .inp case gives —; the totals and contact locations
// come from the last WheelRailSolution.

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>

#include "bindings/c/cntc_export.hpp"
#include "bindings/c/cntc_library.hpp"
#include "format/profiles/profile_points.hpp"
#include "format/profiles/profile_reader.hpp"
#include "rollcontact/errors.hpp"

namespace rollcontact::cntc {
namespace {

Module1Problem* wheel_rail(const int* ire, const char* routine, Access access = Access::Module1,
                           int icp = -1) {
  if (ire == nullptr) {
    library().log(fmt::format("{}: null handle argument (refused)", routine));
    return nullptr;
  }
  return library().open(*ire, icp, access, routine).m1;
}

void reject(const char* routine, const std::string& why) {
  library().log(fmt::format("{}: {} (refused, nothing changed)", routine, why));
}

/// The profile options of setprofileinputfname/values: iparam = [itype, –, mirrory, mirrorz,
/// errhndl, ismooth], rparam = [sclfac, smooth, maxomit, zigthrs, kinkhigh, kinklow, kinkwid];
/// positions not given keep their defaults. Returns itype (−1: from the file extension).
int apply_profile_options(format::ProfileSpec& spec, const Units& units, int nints,
                          const int* iparam, int nreals, const double* rparam) {
  auto ip = [&](int k, int fallback) { return k < nints && iparam ? iparam[k] : fallback; };
  auto rp = [&](int k, double fallback) { return k < nreals && rparam ? rparam[k] : fallback; };
  spec.mirror_y = ip(2, 0) == 1 ? 1 : 0;
  spec.mirror_z = std::clamp(ip(3, 0), -1, 1);
  spec.errhnd = std::clamp(ip(4, 0), -2, 1);
  spec.ismooth = std::clamp(ip(5, 0), 0, 2);
  const double sclfac = rp(0, -1.0);
  spec.scale_yz = sclfac > 0.0 ? sclfac : units.length;  // ≤ 0: the active unit convention
  spec.smooth = std::max(0.0, rp(1, 0.0));
  spec.maxomit = std::clamp(rp(2, 0.5), 0.0, 1.0);
  spec.zigthrs = rp(3, 5.0 * std::acos(-1.0) / 6.0);
  spec.kinkhigh = rp(4, std::acos(-1.0) / 6.0);
  spec.kinklow = rp(5, spec.kinkhigh / 5.0);
  spec.kinkwid = 6 < nreals && rparam ? rparam[6] * units.length : 2.0;  // [L]; default 2 mm
  return ip(0, -1);
}

/// Reads the profile into the rail or wheel of `p`; the error, if any, is kept for calculate.
void store_profile(
    Module1Problem& p, bool is_wheel, format::ProfileSpec spec,
    const std::function<Profile(const format::ProfileOptions&, std::vector<std::string>&)>& read) {
  std::string& error = is_wheel ? p.wheel_error : p.rail_error;
  error.clear();
  std::vector<std::string> warnings;
  try {
    const format::ProfileOptions options{is_wheel, spec.mirror_y, spec.mirror_z, spec.scale_yz};
    spec.profile = read(options, warnings);
    const double length = format::profile_chord_length(spec.profile);
    if (length < format::kMinProfileLength_mm || length > format::kMaxProfileLength_mm)
      throw GeometryError(fmt::format(
          "{} profile has a length of {:.6g} mm, outside 5..500 mm: the scale factor or the "
          "file's units are probably wrong",
          is_wheel ? "wheel" : "rail", length));
  } catch (const Error& e) {
    error = e.what();
    library().log(std::string(is_wheel ? "wheel" : "rail") + " profile: " + error);
  }
  for (const std::string& w : warnings) library().log(w);
  (is_wheel ? p.record.wheel : p.record.rail) = std::move(spec);
}

}  // namespace
}  // namespace rollcontact::cntc

using namespace rollcontact;
using namespace rollcontact::cntc;

CNTC_EXPORT void cntc_setverticalforce(int* ire, double* fz) {
  Module1Problem* p = wheel_rail(ire, "cntc_setverticalforce");
  if (p == nullptr || fz == nullptr) return;
  p->record.digits.n = 1;
  p->record.motion.fz = *fz;
}

CNTC_EXPORT void cntc_settrackdimensions(int* ire, int* ztrack, int* nparam, double* rparam) {
  constexpr const char* name = "cntc_settrackdimensions";
  Module1Problem* p = wheel_rail(ire, name);
  if (p == nullptr) return;
  if (ztrack == nullptr || nparam == nullptr) return reject(name, "null argument");
  const int z = *ztrack, n = *nparam;
  const bool ok = (z == 0 && n == 0) || (z == 1 && n >= 5 && n <= 6) || (z == 2 && n == 6) ||
                  (z == 3 && n >= 11 && n <= 12) || ((z == 32 || z == 33) && n >= 4 && n <= 5);
  if (!ok) return reject(name, fmt::format("Z = {} with nparam = {}", z, n));
  if (n > 0 && rparam == nullptr) return reject(name, "null array");
  const double len = p->units.length, vel = p->units.velocity;
  format::WheelRailRecord& r = p->record;
  if (z == 32 || z == 33) {  // massless rail: [kyrail, fyrail, kzrail, fzrail, {dystep0}]
    r.has_massless_rail = true;
    r.massless_rail = {rparam[0] / len, rparam[1], rparam[2] / len, rparam[3],
                       n >= 5 ? rparam[4] * len : 1.0};
    return;
  }
  int k = 0;
  if (z == 1 || z == 3) {
    format::TrackDimensions& t = r.track;
    const int nz1 = z == 1 ? n : n - 6;
    t.gaught = rparam[0] * len;
    if (t.gaught > 0.0) {
      t.gaugsq = rparam[1];
      t.gaugwd = rparam[2] * len;
    } else {
      t.raily0 = rparam[1] * len;
      t.railz0 = rparam[2] * len;
    }
    t.cant = rparam[3];
    t.nomradr = rparam[4] * len;
    t.curv = nz1 >= 6 ? rparam[5] / len : 0.0;
    k = nz1;
  }
  if (z == 2 || z == 3) {
    const double* d = rparam + k;
    r.rail_deviations = {d[0] * len, d[1] * len, d[2], d[3] * vel, d[4] * vel, d[5]};
  }
  r.digits.z = z <= 0 ? 0 : 3;
}

CNTC_EXPORT void cntc_setwheelsetdimensions(int* ire, int* ewheel, int* nparam, double* rparam) {
  constexpr const char* name = "cntc_setwheelsetdimensions";
  Module1Problem* p = wheel_rail(ire, name);
  if (p == nullptr) return;
  if (ewheel == nullptr || nparam == nullptr) return reject(name, "null argument");
  const int e = *ewheel, n = *nparam;
  if (e < 0 || e > 5) return reject(name, fmt::format("E = {} outside 0..5", e));
  const bool dims = e == 3 || e == 5;
  if ((dims && (n < 3 || n > 4)) || (!dims && n != 0))
    return reject(name, fmt::format("E = {} with nparam = {}", e, n));
  if (dims) {
    if (rparam == nullptr) return reject(name, "null array");
    const double len = p->units.length;
    format::WheelsetDimensions& w = p->record.wheelset;
    w.fbdist = rparam[0] * len;
    w.fbpos = rparam[1] * len;
    w.nomradw = std::clamp(rparam[2] * len, 1e-3, 1e20);
    w.ytape = n >= 4 ? rparam[3] * len : 1000.0;
  }
  int& stored = p->record.digits.e;
  stored = stored <= 3 ? e : (stored == 4 ? 5 : stored);
}

CNTC_EXPORT void cntc_setwheelsetposition(int* ire, int* ewheel, int* nparam, double* rparam) {
  constexpr const char* name = "cntc_setwheelsetposition";
  Module1Problem* p = wheel_rail(ire, name);
  if (p == nullptr) return;
  if (ewheel == nullptr || nparam == nullptr || rparam == nullptr)
    return reject(name, "null argument");
  if (*ewheel < 1 || *ewheel > 5 || *nparam != 6)
    return reject(name,
                  fmt::format("E = {} with nparam = {} (E 1..5 with 6 values)", *ewheel, *nparam));
  const double len = p->units.length;
  format::WheelsetMotion& m = p->record.motion;
  m.s = rparam[0] * len;
  m.y = rparam[1] * len;
  m.z = rparam[2] * len;  // not used when the vertical force is given (N = 1)
  m.roll = rparam[3];
  m.yaw = rparam[4];
  m.pitch = rparam[5];
  if (p->record.digits.e <= 0) p->record.digits.e = 1;
}

CNTC_EXPORT void cntc_setwheelsetvelocity(int* ire, int* ewheel, int* nparam, double* rparam) {
  constexpr const char* name = "cntc_setwheelsetvelocity";
  Module1Problem* p = wheel_rail(ire, name);
  if (p == nullptr) return;
  if (ewheel == nullptr || nparam == nullptr || rparam == nullptr)
    return reject(name, "null argument");
  int e = *ewheel;
  if (e == 1 && *nparam == 6) e = 2;  // backward compatibility (§2.4)
  if (e < 2 || e > 5 || *nparam != 6)
    return reject(name,
                  fmt::format("E = {} with nparam = {} (E 2..5 with 6 values)", *ewheel, *nparam));
  const double vel = p->units.velocity;
  format::WheelsetMotion& m = p->record.motion;
  if (p->record.is_roller()) {
    m.rpitch = rparam[0];
    m.vs = 0.0;
  } else {
    m.vs = rparam[0] * vel;
  }
  m.vy = rparam[1] * vel;
  m.vz = rparam[2] * vel;
  m.vroll = rparam[3];
  m.vyaw = rparam[4];
  m.vpitch = rparam[5];
  if (p->record.digits.e <= 1) p->record.digits.e = e;
}

CNTC_EXPORT void cntc_setwheelsetflexibility(int* ire, int* ewheel, int* nparam, double* rparam) {
  constexpr const char* name = "cntc_setwheelsetflexibility";
  Module1Problem* p = wheel_rail(ire, name);
  if (p == nullptr) return;
  if (ewheel == nullptr || nparam == nullptr) return reject(name, "null argument");
  const int e = *ewheel, n = *nparam;
  if (e < 1 || e > 5) return reject(name, fmt::format("E = {} outside 1..5", e));
  const bool flexible = e >= 4;
  // CONTACT refuses E = 1..3 with more than one value (python_mbench.py sends 12): quietly.
  if ((flexible && n != 12) || (!flexible && n > 1))
    return reject(name, fmt::format("E = {} with nparam = {}", e, n));
  format::WheelDeviations& d = p->record.wheel_deviations;
  int& stored = p->record.digits.e;
  if (!flexible) {
    d = {};
    if (stored >= 4) stored -= 2;
    return;
  }
  if (rparam == nullptr) return reject(name, "null array");
  const double len = p->units.length, vel = p->units.velocity;
  d = {rparam[0] * len, rparam[1] * len, rparam[2] * len, rparam[3], rparam[4],  rparam[5],
       rparam[6] * vel, rparam[7] * vel, rparam[8] * vel, rparam[9], rparam[10], rparam[11]};
  stored = e == 5 ? 5 : (stored == 3 || stored == 5 ? 5 : 4);
}

CNTC_EXPORT void cntc_setprofileinputfname(int* ire, const char* c_fname, int* len_fname,
                                           int* nints, int* iparam, int* nreals, double* rparam) {
  constexpr const char* name = "cntc_setprofileinputfname";
  Module1Problem* p = wheel_rail(ire, name);
  if (p == nullptr) return;
  if (nints == nullptr || nreals == nullptr) return reject(name, "null argument");
  const std::string file = c_string(c_fname, len_fname);
  if (file.empty()) return reject(name, "no file name");
  format::ProfileSpec spec;
  int itype = apply_profile_options(spec, p->units, *nints, iparam, *nreals, rparam);
  std::filesystem::path path = file;
  if (path.is_relative()) path = library().working_folder() / path;
  spec.file = file;
  spec.path = path.string();
  if (itype != 0 && itype != 1) {  // from the extension: .prw, .whl, .slcw are wheels
    const std::string ext = path.extension().string();
    itype =
        ext == ".prw" || ext == ".whl" || ext == ".slcw" || ext == ".PRW" || ext == ".WHL" ? 1 : 0;
  }
  const bool is_wheel = itype == 1;
  store_profile(*p, is_wheel, std::move(spec),
                [&](const format::ProfileOptions& o, std::vector<std::string>& w) {
                  return format::read_profile_file(path, o, w);
                });
}

CNTC_EXPORT void cntc_setprofileinputvalues(int* ire, int* npoint, double* values, int* nints,
                                            int* iparam, int* nreals, double* rparam) {
  constexpr const char* name = "cntc_setprofileinputvalues";
  Module1Problem* p = wheel_rail(ire, name);
  if (p == nullptr) return;
  if (npoint == nullptr || nints == nullptr || nreals == nullptr || values == nullptr)
    return reject(name, "null argument");
  if (*npoint < 2)
    return reject(name, fmt::format("npoint = {}: a profile needs 2 points", *npoint));
  format::ProfileSpec spec;
  const int itype = apply_profile_options(spec, p->units, *nints, iparam, *nreals, rparam);
  const bool is_wheel = *nints == 0 ? true : std::clamp(itype, 0, 1) == 1;
  spec.file = "(values)";
  format::RawProfile raw;
  raw.file = spec.file;
  for (int i = 0; i < *npoint; ++i) {
    raw.y.push_back(values[2 * i]);
    raw.z.push_back(values[2 * i + 1]);
  }
  store_profile(*p, is_wheel, std::move(spec),
                [&](const format::ProfileOptions& o, std::vector<std::string>& w) {
                  return format::finish_profile(raw, o, w);
                });
}

CNTC_EXPORT void cntc_getwheelsetposition(int* ire, int* lenarr, double* values) {
  Module1Problem* p = wheel_rail(ire, "cntc_getwheelsetposition");
  if (p == nullptr || lenarr == nullptr || values == nullptr) return;
  const double len = p->units.length;
  const format::WheelsetMotion& m = p->record.motion;
  const double z = p->result ? p->result->z_ws_mm : m.z;
  const double all[6] = {m.s / len, m.y / len, z / len, m.roll, m.yaw, m.pitch};
  for (int k = 0; k < std::min(*lenarr, 6); ++k) values[k] = all[k];
}

CNTC_EXPORT void cntc_getwheelsetvelocity(int* ire, int* lenarr, double* values) {
  Module1Problem* p = wheel_rail(ire, "cntc_getwheelsetvelocity");
  if (p == nullptr || lenarr == nullptr || values == nullptr) return;
  const double vel = p->units.velocity;
  const format::WheelsetMotion& m = p->record.motion;
  const double all[6] = {m.vs / vel, m.vy / vel, m.vz / vel, m.vroll, m.vyaw, m.vpitch};
  for (int k = 0; k < std::min(*lenarr, 6); ++k) values[k] = all[k];
}

CNTC_EXPORT void cntc_getnumcontactpatches(int* ire, int* npatch) {
  Module1Problem* p = wheel_rail(ire, "cntc_getnumcontactpatches");
  if (p == nullptr || npatch == nullptr) return;
  *npatch = p->result ? static_cast<int>(p->result->patches.size()) : 0;
}

CNTC_EXPORT void cntc_getglobalforces(int* ire, int* icp, int* lenarr, double* values) {
  if (icp == nullptr || lenarr == nullptr || values == nullptr) return;
  Module1Problem* p = wheel_rail(ire, "cntc_getglobalforces", Access::Module1Forces, *icp);
  if (p == nullptr) return;
  for (int k = 0; k < *lenarr; ++k) values[k] = 0.0;  // invalid patch or no result: zeros
  if (!p->result) return;
  const WheelRailSolution& s = *p->result;
  Vector3 tr, ws;
  if (*icp == -1) {
    tr = s.force_tr;
    ws = s.force_ws;
  } else if (*icp >= 1 && *icp <= static_cast<int>(s.patches.size())) {
    tr = s.patches[static_cast<std::size_t>(*icp - 1)].force_tr;
    ws = s.patches[static_cast<std::size_t>(*icp - 1)].force_ws;
  } else {
    return;
  }
  // Forces on the output body; the solution's lateral components are in the left wheel's
  // mirrored frame, the library's in the track's (§1.4).
  const double body = p->units.body, left = p->record.is_left() ? -1.0 : 1.0;
  const double forces[2][3] = {{tr.x, left * tr.y, tr.z}, {ws.x, left * ws.y, ws.z}};
  for (int frame = 0; frame < 2; ++frame)
    for (int c = 0; c < 3; ++c) {
      const int k = 6 * frame + c;  // positions 1-3 (track), 7-9 (wheelset)
      if (k < *lenarr) values[k] = body * forces[frame][c];
    }
  // Positions 4-6, 10-12 (moments about the markers) and 13-24 (profile frames): not yet, 0.
}

CNTC_EXPORT void cntc_getcontactlocation(int* ire, int* icp, int* lenarr, double* values) {
  if (icp == nullptr || lenarr == nullptr || values == nullptr) return;
  Module1Problem* p = wheel_rail(ire, "cntc_getcontactlocation", Access::Module1Patch, *icp);
  if (p == nullptr || !p->result) return;
  const auto& patches = p->result->patches;
  std::vector<double> all(38, 0.0);
  if (*icp >= 1 && *icp <= static_cast<int>(patches.size())) {
    const WheelRailPatch& w = patches[static_cast<std::size_t>(*icp - 1)];
    const double len = p->units.length, left = p->record.is_left() ? -1.0 : 1.0;
    all[0] = w.reference_tr.x / len;  // 1-4: reference point in track coordinates
    all[1] = left * w.reference_tr.y / len;
    all[2] = w.reference_tr.z / len;
    all[3] = left * w.contact_angle_rad;
    all[4] = w.reference_tr.x / len;  // 5-7: in rail-profile coordinates (s, δ: not yet)
    all[5] = left * w.y_rail_mm / len;
    all[6] = w.z_rail_mm / len;
    all[9] = w.reference_wheel.x / len;  // 10-12: relative to the wheel-profile origin
    all[10] = left * w.reference_wheel.y / len;
    all[11] = w.reference_wheel.z / len;
  }
  for (int k = 0; k < std::min(*lenarr, 38); ++k)
    if (k != 28) values[k] = all[static_cast<std::size_t>(k)];  // position 29 is never written
}
