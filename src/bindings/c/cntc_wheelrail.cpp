// cntc_* routines of module 1 (wheel/rail, spec library-api.md §2.4, §2.5, §2.8): track,
// wheelset, vertical force and profiles go into the element's WheelRailRecord in internal units
// (mm, N, s, rad) — the record a module-1 .inp case gives —; the totals and contact locations
// come from the last WheelRailSolution.

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
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
  return open_target(ire, &icp, access, routine).m1;
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
    spec.profile = std::make_shared<const Profile>(read(options, warnings));
    const double length = format::profile_chord_length(*spec.profile);
    if (!format::is_admissible_profile_length(length))
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
    r.digits.z = 3;  // as CONTACT stores it for every Z > 0
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
  if (itype != 0 && itype != 1) {  // from the extension, any case: .prw, .whl, .slcw are wheels
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
    itype = ext == ".prw" || ext == ".whl" || ext == ".slcw" ? 1 : 0;
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
  // F1 = 1: VPITCH is solved for the prescribed FX_WS.
  const double vpitch = p->result ? p->result->vpitch_rad_s : m.vpitch;
  const double all[6] = {m.vs / vel, m.vy / vel, m.vz / vel, m.vroll, m.vyaw, vpitch};
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
  Vector3 f_tr, f_ws, m_tr, m_ws;
  if (*icp == -1) {
    f_tr = s.force_tr, f_ws = s.force_ws, m_tr = s.moment_tr, m_ws = s.moment_ws;
  } else if (*icp >= 1 && *icp <= static_cast<int>(s.patches.size())) {
    const WheelRailPatch& w = s.patches[static_cast<std::size_t>(*icp - 1)];
    f_tr = w.force_tr, f_ws = w.force_ws, m_tr = w.moment_tr, m_ws = w.moment_ws;
  } else {
    return;
  }
  // The solution is in track coordinates as CONTACT reports it (left wheels included). Forces
  // act on the output body (body sign); the rail-profile frame is the track frame rolled with
  // the rail, the wheel-profile frame that of the wheelset.
  const double a = s.rail_marker_tr.roll_rad;
  auto rail_frame = [a](Vector3 v) {
    return Vector3{v.x, std::cos(a) * v.y + std::sin(a) * v.z,
                   -std::sin(a) * v.y + std::cos(a) * v.z};
  };
  const Vector3 blocks[8] = {f_tr, m_tr, f_ws, m_ws, rail_frame(f_tr), rail_frame(m_tr),
                             f_ws, m_ws};
  const double body = p->units.body, len = p->units.length;
  for (int b = 0; b < 8; ++b) {
    const double scale = body / (b % 2 == 1 ? len : 1.0);  // moments [F·L]
    const double v[3] = {blocks[b].x, blocks[b].y, blocks[b].z};
    for (int c = 0; c < 3; ++c) {
      const int k = 3 * b + c;  // 1-6 track, 7-12 wheelset, 13-18 rail, 19-24 wheel profile
      if (k < *lenarr) values[k] = scale * v[c];
    }
  }
}

CNTC_EXPORT void cntc_getcontactlocation(int* ire, int* icp, int* lenarr, double* values) {
  if (icp == nullptr || lenarr == nullptr || values == nullptr) return;
  Module1Problem* p = wheel_rail(ire, "cntc_getcontactlocation", Access::Module1Patch, *icp);
  if (p == nullptr || !p->result) return;
  const WheelRailSolution& s = *p->result;
  std::vector<double> all(38, 0.0);
  if (*icp >= 1 && *icp <= static_cast<int>(s.patches.size())) {
    const WheelRailPatch& w = s.patches[static_cast<std::size_t>(*icp - 1)];
    const double len = p->units.length;
    const Vector3& r = w.reference_tr;
    const Vector3& q = w.reference_ws;
    const Vector3& rw = w.reference_wheel;
    const ProfileMarker& wm = s.wheel_marker_tr;
    const ProfileMarker& rm = s.rail_marker_tr;
    const ProfileMarker& wmw = s.wheel_marker_ws;
    const double filled[38] = {r.x / len,
                               r.y / len,
                               r.z / len,
                               w.contact_angle_rad,  // 1-4 track
                               r.x / len,
                               w.y_rail_mm / len,
                               w.z_rail_mm / len,
                               w.s_rail_mm / len,  // 5-8 rail
                               w.delta_rail_rad,   // 9
                               rw.x / len,
                               rw.y / len,
                               rw.z / len,
                               w.s_wheel_mm / len,  // 10-13 wheel
                               w.delta_wheel_rad,   // 14
                               w.pressure_centre_x_mm / len,
                               w.pressure_centre_y_mm / len,  // 15-16
                               0.0,
                               s.rail_deflection.dy_mm / len,
                               s.rail_deflection.dz_mm / len,
                               0.0,  // 17; 18-19 massless rail deflections (no side sign); 20
                               wm.position.x / len,
                               wm.position.y / len,
                               wm.position.z / len,  // 21-23
                               wm.roll_rad,
                               wm.yaw_rad,  // 24-25
                               rm.position.y / len,
                               rm.position.z / len,
                               rm.roll_rad,  // 26-28
                               0.0,          // 29
                               q.x / len,
                               q.y / len,
                               q.z / len,
                               w.delta_wheel_rad,  // 30-33
                               wmw.position.x / len,
                               wmw.position.y / len,
                               wmw.position.z / len,  // 34-36
                               wmw.roll_rad,
                               wmw.yaw_rad};  // 37-38
    std::copy(std::begin(filled), std::end(filled), all.begin());
  }
  for (int k = 0; k < std::min(*lenarr, 38); ++k)
    if (k != 28) values[k] = all[static_cast<std::size_t>(k)];  // position 29 is never written
}
