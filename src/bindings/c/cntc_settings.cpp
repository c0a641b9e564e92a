// cntc_* settings of module 3 and the module-independent ones (spec library-api.md §2.2–2.3).
// Each setter writes the problem's CaseRecord — the case as CONTACT's digits and blocks describe
// it — in internal units (mm, N, s, rad), so that calculate solves exactly what the same .inp
// case would. A call with a wrong parameter count or method code is refused: logged, nothing
// stored (§2: "rejected"); values out of range are clamped silently, as CONTACT does.

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "bindings/c/cntc_export.hpp"
#include "bindings/c/cntc_library.hpp"

namespace rollcontact::cntc {
namespace {

/// The parts of a case both modules have, with the problem's units.
struct Common {
  format::ControlDigits& digits;
  format::SolverSettings& solver;
  format::Friction& friction;
  format::Materials& materials;
  Units& units;
  StoredFlags& flags;
  format::Damping& damping;
};

Common common(const Target& t) {
  if (t.m3 != nullptr) {
    auto& r = t.m3->record;
    return {r.digits, r.solver, r.friction, r.materials, t.m3->units, t.m3->flags, r.damping};
  }
  auto& r = t.m1->record;
  return {r.digits, r.solver, r.friction, r.materials, t.m1->units, t.m1->flags, r.damping};
}

int clamp(int v, int lo, int hi) {
  return std::clamp(v, lo, hi);
}

/// The module-1 flags (C1, F1, D, NPOT_MAX); false for any other code.
bool set_wheelrail_flag(Module1Problem& p, int code, int value) {
  switch (code) {
    case CNTC_ic_config:
      p.record.config = clamp(value, 0, 5);
      return true;
    case CNTC_ic_force:
      p.record.digits.f = clamp(value, 0, 3);
      return true;
    case CNTC_ic_discns:
      if (value >= 2 && value <= 9) p.record.discretisation.method = value;
      if (value >= 0 && value <= 9) p.record.digits.d = value;
      return true;
    case CNTC_ic_npomax:
      if (value < 100 || value > 1000000)
        library().log(fmt::format("cntc_setflags: NPOT_MAX = {} clamped to [100, 1e6]", value));
      p.record.npot_max = clamp(value, 100, 1000000);
      return true;
    default:
      return false;
  }
}

/// One flag of cntc_setflags.
void set_flag(const Target& t, int code, int value) {
  if (t.m1 != nullptr && set_wheelrail_flag(*t.m1, code, value)) return;
  Common c = common(t);
  format::ControlDigits& d = c.digits;
  switch (code) {
    case 0:
      return;
    case CNTC_if_units: {
      Units u;
      if (units_for_code(value, u))
        c.units = u;
      else
        library().log(fmt::format("cntc_setflags: unit convention {} unknown (kept)", value));
      return;
    }
    case CNTC_ic_pvtime:
      d.p = clamp(value, 0, 3);
      return;
    case CNTC_ic_bound:
      d.b = clamp(value, 0, 6);
      return;
    case CNTC_ic_tang:
      d.t = clamp(value, 0, 3);
      return;
    case CNTC_ic_norm:
      d.n = clamp(value, 0, 1);
      return;
    case CNTC_ic_force:
      d.f = clamp(value, 0, 2);
      return;
    case CNTC_ic_inflcf:
      if (value >= 2 && value <= 4) c.materials.influence_type = value;
      return;
    case CNTC_ic_exrhs:
      d.e = clamp(value, 0, 3);
      return;
    case CNTC_ic_iestim:
      d.i = clamp(value, 0, 3);
      return;
    case CNTC_ic_matfil:
      d.a = value >= 0 && value <= 2 ? value : 0;
      return;
    case CNTC_ic_output:
      d.o = clamp(value, 0, 5);
      return;
    case CNTC_ic_flow:
      d.w = clamp(value, 0, 9);
      return;
    case CNTC_ic_return:
      d.r = clamp(value, 0, 3);
      return;
    case CNTC_if_ncase:
      (t.m3 != nullptr ? t.m3->cases : t.m1->cases) = std::max(0, value - 1);
      return;
    case CNTC_if_idebug:
      library().set_debug_level(value);
      return;
    case CNTC_ic_sens:
      c.flags.sens = clamp(value, 0, 3);
      return;
    case CNTC_ic_sbsout:
      c.flags.sbsout = clamp(value, 0, 4);
      if (c.flags.sbsout == 3) c.flags.sbsout = 2;
      return;
    case CNTC_ic_sbsfil:
      c.flags.sbsfil = value >= 0 && value <= 2 ? value : 0;
      return;
    case CNTC_ic_xflow:
      c.flags.xflow = value > 0 ? 1 : 0;
      return;
    case CNTC_if_wrtinp:
      c.flags.wrtinp = value;
      return;
    case CNTC_ic_ifmeth:
      c.materials.conformal.if_meth = clamp(value, 0, 1);
      return;
    case CNTC_ic_ifvari:
      c.materials.conformal.variant = clamp(value, 1, 4);
      return;
    case CNTC_ic_npomax:  // module 3: stored for getflags (module 1: its own flag above)
      c.flags.npot_max = clamp(value, 100, 1000000);
      return;
    case CNTC_ic_config:  // module 1 only
    case CNTC_ic_discns:  // module 3 grids come from setpotcontact/sethertzcontact
    case CNTC_ic_mater:   // M is set by setmaterialparameters
    case CNTC_if_licdbg:
    case CNTC_if_openmp:
    case CNTC_if_timers:
      return;
    default:
      library().log(fmt::format("cntc_setflags: unknown parameter code {} ignored", code));
  }
}

/// The value of one flag for cntc_getflags; false for an unknown code.
bool get_flag(const Target& t, int code, int& value) {
  const Common c = common(t);
  const format::ControlDigits& d = c.digits;
  if (t.m1 != nullptr) {
    if (code == CNTC_ic_config) return value = t.m1->record.config, true;
    if (code == CNTC_ic_npomax) return value = t.m1->record.npot_max, true;
  }
  switch (code) {
    case CNTC_if_units:
      value = c.units.code;
      return true;
    case CNTC_ic_pvtime:
      value = d.p;
      return true;
    case CNTC_ic_bound:
      value = d.b;
      return true;
    case CNTC_ic_tang:
      value = d.t;
      return true;
    case CNTC_ic_norm:
      value = d.n;
      return true;
    case CNTC_ic_force:
      value = d.f;
      return true;
    case CNTC_ic_frclaw:
      value = c.friction.law;
      return true;
    case CNTC_ic_discns:
      value = d.d;
      return true;
    case CNTC_ic_inflcf:
      value = c.materials.influence_type;
      return true;
    case CNTC_ic_mater:
      value = d.m;
      return true;
    case CNTC_ic_heat:
      value = d.h;
      return true;
    case CNTC_ic_iestim:
      value = d.i;
      return true;
    case CNTC_ic_matfil:
      value = d.a;
      return true;
    case CNTC_ic_output:
      value = d.o;
      return true;
    case CNTC_ic_flow:
      value = d.w;
      return true;
    case CNTC_ic_return:
      value = d.r;
      return true;
    case CNTC_ic_exrhs:
      value = d.e == 9 ? 1 : d.e;  // per-element values: CONTACT's E = 1
      return true;
    case CNTC_if_ncase:
      value = t.m3 != nullptr ? t.m3->cases : t.m1->cases;
      return true;
    case CNTC_ic_sens:
      value = c.flags.sens;
      return true;
    case CNTC_ic_sbsout:
      value = c.flags.sbsout;
      return true;
    case CNTC_ic_sbsfil:
      value = c.flags.sbsfil;
      return true;
    case CNTC_ic_xflow:
      value = c.flags.xflow;
      return true;
    case CNTC_if_wrtinp:
      value = c.flags.wrtinp;
      return true;
    case CNTC_ic_ifmeth:
      value = c.materials.conformal.if_meth;
      return true;
    case CNTC_ic_ifvari:
      value = c.materials.conformal.variant;
      return true;
    case CNTC_ic_npomax:
      value = c.flags.npot_max;
      return true;
    default:
      return false;
  }
}

/// Combined difference parameter K of the bodies (physics.md §3.1) for the MAXOUT rule.
double difference_parameter(const format::Materials& m) {
  const double g = 2.0 / (1.0 / m.gg1 + 1.0 / m.gg2);
  return 0.25 * g * ((1.0 - 2.0 * m.poiss1) / m.gg1 - (1.0 - 2.0 * m.poiss2) / m.gg2);
}

/// Parameters per friction law L = 0..6 (setfrictionmethod's `lparam`).
constexpr int kFrictionParameters[] = {2, 0, 7, 7, 7, 3, 6};

/// The friction law L (≠ 1) from its CONTACT parameters `lp` in the units `u`, clamped as
/// CONTACT clamps them; Polach (L = 5) becomes the exponential law L = 4.
format::Friction friction_of(int law, const double* lp, const Units& u) {
  format::Friction f;
  switch (law) {
    case 0: {  // the smaller of FSTAT, FKIN for both
      f.law = 0;
      f.fstat = f.fkin = std::max(1e-6, std::min(lp[0], lp[1]));
      break;
    }
    case 2:
    case 3:
    case 4:
      f.law = law;
      f.fkin = std::max(1e-6, lp[0]);
      f.params = {std::max(0.0, lp[1]), std::max(1e-4, lp[2] * u.velocity), std::max(0.0, lp[3]),
                  std::max(1e-4, lp[4] * u.velocity)};
      f.memdst = std::max(0.0, lp[5] * u.length);
      f.mem_s0 = std::max(0.0, lp[6] * u.velocity);
      f.fstat = f.fkin + f.params[0] + f.params[2];
      break;
    case 5: {  // Polach: fkin = a·fstat, fexp1 = fstat − fkin, sabsh1 = ln 2 / b
      const double fstat = lp[0], a = lp[1], b = lp[2] / u.velocity;
      f.law = 4;
      f.fkin = std::max(1e-6, a * fstat);
      f.params = {fstat - f.fkin, std::log(2.0) / b, 0.0, 10000.0};
      f.memdst = 0.001;
      f.mem_s0 = 10.0;
      f.fstat = fstat;
      break;
    }
    default:  // 6: temperature dependent
      f.law = 6;
      f.fkin = f.fstat = std::max(1e-6, lp[0]);
      f.params = {lp[1], std::max(1e-6 - f.fkin, lp[2]), lp[3], 0.0};
      f.memdst = std::max(0.0, lp[4] * u.length);
      f.mem_s0 = std::max(0.0, lp[5] * u.velocity);
  }
  return f;
}

/// cntc_setpotcontact in module 1: [dx, ds, n.a.] (ipotcn 0) or [dx, ds, a_sep [A], d_sep,
/// d_comb, {d_turn, g_miss}] (ipotcn −1), lengths [L].
void set_wheelrail_discretisation(Module1Problem& p, int ipotcn, int nparam, const double* r) {
  constexpr const char* name = "cntc_setpotcontact";
  const bool short_form = ipotcn == 0 && nparam == 3;
  const bool long_form = ipotcn == -1 && nparam >= 5 && nparam <= 7;
  if (!short_form && !long_form)
    return reject(name, fmt::format("module 1 takes ipotcn = 0 with 3 parameters or -1 with 5 to "
                                    "7, not ipotcn = {} with {}",
                                    ipotcn, nparam));
  if (r == nullptr) return reject(name, "null array");
  format::WheelRailDiscretisation& d = p.record.discretisation;
  const double len = p.units.length;
  d.dx = std::max(1e-12, r[0] * len);
  d.ds = std::max(1e-12, r[1] * len);
  if (short_form) return;
  d.a_sep = std::max(0.0, r[2]);
  d.d_sep = std::max(0.0, r[3] * len);
  d.d_comb = std::max(0.0, r[4] * len);
  d.d_turn = nparam >= 6 ? std::max(0.0, r[5] * len) : 2.0 * d.d_sep - d.d_comb;
  d.g_miss = nparam >= 7 ? r[6] * len : -1.0;
}

}  // namespace
}  // namespace rollcontact::cntc

using namespace rollcontact::cntc;

CNTC_EXPORT void cntc_setflags(int* ire, int* icp, int* lenflg, int* params, int* values) {
  const Target t = open_target(ire, icp, Access::Settings, "cntc_setflags");
  if (!t) return;
  if (lenflg == nullptr || (*lenflg > 0 && (params == nullptr || values == nullptr)))
    return reject("cntc_setflags", "null array");
  for (int i = 0; i < *lenflg; ++i) set_flag(t, params[i], values[i]);
}

CNTC_EXPORT void cntc_getflags(int* ire, int* icp, int* nparam, int* iparam, int* values) {
  const Target t = open_target(ire, icp, Access::Either, "cntc_getflags");
  if (!t || nparam == nullptr || (*nparam > 0 && (iparam == nullptr || values == nullptr))) return;
  for (int i = 0; i < *nparam; ++i) {
    if (iparam[i] == 0) continue;
    int v = 0;
    if (get_flag(t, iparam[i], v))
      values[i] = v;
    else
      library().log(fmt::format("cntc_getflags: unknown parameter code {}", iparam[i]));
  }
}

CNTC_EXPORT void cntc_setsolverflags(int* ire, int* icp, int* gdigit, int* nints, int* iparam,
                                     int* nreals, double* rparam) {
  constexpr const char* name = "cntc_setsolverflags";
  const Target t = open_target(ire, icp, Access::Settings, name);
  if (!t) return;
  if (gdigit == nullptr || nints == nullptr || nreals == nullptr)
    return reject(name, "null argument");
  const int g = *gdigit;
  static constexpr int ni[] = {4, 0, 5, 5, 5, 5, 1}, nr[] = {1, 0, 4, 4, 2, 8, 1};
  if (g < 0 || g > 6) return reject(name, fmt::format("G = {} outside 0..6", g));
  if (*nints != ni[g] || *nreals != nr[g])
    return reject(name, fmt::format("G = {} needs nints = {}, nreals = {}", g, ni[g], nr[g]));
  if ((ni[g] > 0 && iparam == nullptr) || (nr[g] > 0 && rparam == nullptr))
    return reject(name, "null array");
  if (g == 1 || g == 6) return;  // keep; sensitivity settings (not computed here)
  const Common c = common(t);
  rollcontact::format::SolverSettings& s = c.solver;
  c.digits.g = g;
  s.method = g;
  s.maxgs = std::max(1, iparam[0]);
  s.maxin = std::max(1, iparam[1]);
  s.maxnr = std::max(1, iparam[2]);
  s.maxout = std::max(1, iparam[3]);
  s.eps = std::max(1e-20, rparam[0]);
  if (g == 2 || g == 3) {
    s.inislp = iparam[4];
    s.omega_h = std::max(1e-20, rparam[1]);
    s.omega_s = std::max(1e-20, rparam[2]);
    s.omgslp = std::max(1e-20, rparam[3]);
  } else if (g == 4) {
    s.inislp = iparam[4];
    s.omgslp = std::max(1e-20, rparam[1]);
  }
}

CNTC_EXPORT void cntc_setmaterialparameters(int* ire, int* icp, int* mdigit, int* nparam,
                                            double* rparam) {
  constexpr const char* name = "cntc_setmaterialparameters";
  const Target t = open_target(ire, icp, Access::Settings, name);
  if (!t) return;
  if (mdigit == nullptr || nparam == nullptr) return reject(name, "null argument");
  const Common c = common(t);
  const int m = *mdigit;
  static constexpr int needed[] = {4, 8, 8, 7, 8, 7, 4, 4};
  if (m >= 10 && m <= 12) {
    // Damping digit M2 (the material model M stays): 0 none, 1 keep, 2 the four parameters.
    // Module 1 refuses a case where the damping would act (docs/decisions.md), as the .inp route.
    if (m == 12) {
      if (*nparam != 4) return reject(name, "M2 = 2 needs nparam = 4");
      if (rparam == nullptr) return reject(name, "null array");
      c.damping = {true, rparam[0], rparam[1], rparam[2], rparam[3]};  // s, s, N/s, N/s
    } else if (*nparam > 1) {
      return reject(name, fmt::format("M2 = {} takes 0 or 1 parameters", m - 10));
    } else if (m == 10) {
      c.damping = {};
    }
    c.digits.m2 = m - 10;
    return;
  }
  if (m < 0 || m > 7) return reject(name, fmt::format("M = {} outside 0..7 and 10..12", m));
  if (*nparam != needed[m])
    return reject(name, fmt::format("M = {} needs nparam = {}", m, needed[m]));
  if (rparam == nullptr) return reject(name, "null array");
  rollcontact::format::Materials& mat = c.materials;
  const Units& u = c.units;
  mat.poiss1 = rparam[0];
  mat.poiss2 = rparam[1];
  mat.gg1 = rparam[2] * u.pressure();
  mat.gg2 = rparam[3] * u.pressure();
  mat.model_params = {};
  for (int k = 4; k < *nparam; ++k) mat.model_params[static_cast<std::size_t>(k - 4)] = rparam[k];
  auto& mp = mat.model_params;
  if (m == 2) {  // FLX [L³/F], K0_MF, ALFAMF, BETAMF, each at least 1e-6
    for (std::size_t k = 0; k < 4; ++k) mp[k] = std::max(1e-6, mp[k]);
    mp[0] *= u.length * u.length * u.length;
  }
  if (m == 4) {  // GG3 [P], LAYTHK [L], TAU_C0 [P] (≥ 1e10: no plasticity), K_TAU [F/L³]
    mp[0] = std::max(1e-6, mp[0] * u.pressure());
    mp[1] = std::max(1e-9, mp[1] * u.length);
    mp[2] = mp[2] >= 1e10 ? 0.0 : mp[2] * u.pressure();
    mp[3] *= u.pressure() / u.length;
  }
  c.digits.m = m;
  // MAXOUT follows the coupling of the bodies (§2.2).
  const double ak = std::abs(difference_parameter(mat));
  int& maxout = c.solver.maxout;
  if (ak < 1e-4 && maxout >= 2) maxout = 1;
  if (ak >= 1e-4 && maxout <= 1) maxout = 10;
}

CNTC_EXPORT void cntc_settimestep(int* ire, int* icp, double* dt) {
  const Target t = open_target(ire, icp, Access::Settings, "cntc_settimestep");
  if (!t || dt == nullptr) return;
  // dt only scales the frictional power of shifts (T = 0, 1), which rollcontact reports per
  // step (outputs.md §4); kept for the interface.
}

CNTC_EXPORT void cntc_setrollingstepsize(int* ire, int* icp, double* chi, double* dq) {
  const Target t = open_target(ire, icp, Access::Settings, "cntc_setrollingstepsize");
  if (!t || chi == nullptr || dq == nullptr) return;
  if (t.m1 != nullptr) {  // module 1: the step relative to DX, no unit; chi is not used
    t.m1->record.discretisation.dqrel = *dq;
    return;
  }
  t.m3->record.kinematics.chi = *chi;
  t.m3->record.kinematics.dq = *dq * t.m3->units.length;
}

CNTC_EXPORT void cntc_setfrictionmethod(int* ire, int* icp, int* imeth, int* nparam,
                                        double* params) {
  constexpr const char* name = "cntc_setfrictionmethod";
  const Target t = open_target(ire, icp, Access::Settings, name);
  if (!t) return;
  if (imeth == nullptr || nparam == nullptr) return reject(name, "null argument");
  const int v = *imeth / 10, law = *imeth % 10;
  if (*imeth < 0 || v > 2) return reject(name, fmt::format("imeth = {} is not 10*V + L", *imeth));
  if (v != 0 && t.m3 != nullptr)
    return reject(name, fmt::format("imeth = {}: module 3 takes V = 0 only", *imeth));
  if (law > 6) return reject(name, fmt::format("L = {} outside 0..6", law));
  if (law == 1) return;  // keep (V is forced to 0)
  const int n = kFrictionParameters[law];
  if (v == 0 && *nparam != n) return reject(name, fmt::format("L = {} needs nparam = {}", law, n));
  if (*nparam > 0 && params == nullptr) return reject(name, "null array");
  const Common c = common(t);
  if (v == 0) {
    c.friction = friction_of(law, params, c.units);
    c.digits.l = c.friction.law;
    if (t.m1 != nullptr) {
      t.m1->record.variable_friction = {};
      t.m1->friction_given = true;
    }
    return;
  }
  // V = 1, 2 (module 1): [nvf, (alpha_i [A] or s_i [L], lparam_i) for i = 1..nvf].
  const int nvf = static_cast<int>(std::lround(params[0]));
  if (nvf < 1 || *nparam != 1 + nvf * (1 + n))
    return reject(name, fmt::format("V = {}, L = {} with nvf = {} needs nparam = {}", v, law, nvf,
                                    1 + std::max(nvf, 1) * (1 + n)));
  rollcontact::format::VariableFriction vf;
  vf.v = v;
  for (int i = 0; i < nvf; ++i) {
    const double* set = params + 1 + i * (1 + n);
    vf.positions.push_back(v == 2 ? set[0] * c.units.length : set[0]);
    const rollcontact::format::Friction f = friction_of(law, set + 1, c.units);
    vf.sets.push_back({f.fstat, f.fkin, f.params});
    if (i == 0) c.friction = f;
  }
  c.digits.l = c.friction.law;
  t.m1->record.variable_friction = std::move(vf);
  t.m1->friction_given = true;
}

CNTC_EXPORT void cntc_setpotcontact(int* ire, int* icp, int* ipotcn, int* nparam, double* rparam) {
  constexpr const char* name = "cntc_setpotcontact";
  const Target t = open_target(ire, icp, Access::Settings, name);
  if (!t) return;
  if (ipotcn == nullptr || nparam == nullptr) return reject(name, "null argument");
  if (t.m1 != nullptr) return set_wheelrail_discretisation(*t.m1, *ipotcn, *nparam, rparam);
  Module3Problem* p = t.m3;
  if (*ipotcn < 1 || *ipotcn > 4 || *nparam != 6)
    return reject(name, fmt::format("ipotcn = {}, nparam = {}: module 3 takes ipotcn 1..4 with "
                                    "6 parameters",
                                    *ipotcn, *nparam));
  if (rparam == nullptr) return reject(name, "null array");
  rollcontact::model::PotentialContact& pc = p->record.potential;
  pc.ipotcn = *ipotcn;
  pc.mx = std::max(1, static_cast<int>(std::lround(rparam[0])));
  pc.my = std::max(1, static_cast<int>(std::lround(rparam[1])));
  for (std::size_t k = 0; k < 4; ++k) pc.values[k] = rparam[k + 2] * p->units.length;
  p->grid_given = true;
}

CNTC_EXPORT void cntc_settangentialforces(int* ire, int* icp, double* fx, double* fy) {
  const Target t = open_target(ire, icp, Access::Settings, "cntc_settangentialforces");
  if (!t || fx == nullptr || fy == nullptr) return;
  if (t.m1 != nullptr) {  // module 1: the total longitudinal force [F] (F1 = 1); fy unused
    t.m1->record.motion.fx = *fx;
    return;
  }
  Module3Problem* p = t.m3;
  double x = *fx, y = *fy;
  const double length = std::hypot(x, y);
  if (length > 1.0) {
    x /= length;
    y /= length;
  }
  p->record.kinematics.fx_rel = x;
  p->record.kinematics.fy_rel = y;
}

CNTC_EXPORT void cntc_setreferencevelocity(int* ire, int* icp, double* veloc) {
  Module3Problem* p = open_target(ire, icp, Access::Module3, "cntc_setreferencevelocity").m3;
  if (p == nullptr || veloc == nullptr) return;
  p->record.kinematics.veloc = std::max(1e-9, std::abs(*veloc) * p->units.velocity);
}

CNTC_EXPORT void cntc_sethertzcontact(int* ire, int* icp, int* ipotcn, int* nparam,
                                      double* rparam) {
  constexpr const char* name = "cntc_sethertzcontact";
  Module3Problem* p = open_target(ire, icp, Access::Module3, name).m3;
  if (p == nullptr) return;
  if (ipotcn == nullptr || nparam == nullptr) return reject(name, "null argument");
  const int ip = *ipotcn;
  if (ip < -6 || ip > -1) return reject(name, fmt::format("ipotcn = {} outside -6..-1", ip));
  const int needed = ip == -6 ? 6 : 5;
  if (*nparam != needed)
    return reject(name, fmt::format("ipotcn = {} needs nparam = {}", ip, needed));
  if (rparam == nullptr) return reject(name, "null array");
  const double len = p->units.length;
  rollcontact::model::PotentialContact& pc = p->record.potential;
  pc.ipotcn = ip;
  pc.mx = std::max(1, static_cast<int>(std::lround(rparam[0])));
  pc.my = std::max(1, static_cast<int>(std::lround(rparam[1])));
  pc.values = {};
  // Per value: lengths scale with L, curvatures [1/L] inversely, ratios not at all.
  for (int k = 2; k < needed; ++k) {
    const bool last = k == needed - 1;  // SCALE [-]
    const bool curvature = (k == 2 && (ip == -1 || ip == -2 || ip == -4)) || (k == 3 && ip == -1);
    const bool ratio = last || (k == 3 && ip == -2);
    double value = rparam[k];
    if (curvature)
      value = std::max(1e-12, value / len);
    else if (!ratio)
      value = std::max(1e-6, value * len);
    else
      value = std::max(1e-6, value);
    pc.values[static_cast<std::size_t>(k - 2)] = value;
  }
  if (ip == -4 || ip == -5) p->record.digits.b = 2;
  p->grid_given = true;
}

CNTC_EXPORT void cntc_setpenetration(int* ire, int* icp, double* pen) {
  Module3Problem* p = open_target(ire, icp, Access::Module3, "cntc_setpenetration").m3;
  if (p == nullptr || pen == nullptr) return;
  p->record.digits.n = 0;
  p->record.kinematics.pen = *pen * p->units.length;
}

CNTC_EXPORT void cntc_setnormalforce(int* ire, int* icp, double* fn) {
  Module3Problem* p = open_target(ire, icp, Access::Module3, "cntc_setnormalforce").m3;
  if (p == nullptr || fn == nullptr) return;
  p->record.digits.n = 1;
  p->record.kinematics.fn = *fn;
}

CNTC_EXPORT void cntc_setundeformeddistc(int* ire, int* icp, int* ibase, int* nparam,
                                         double* prmudf) {
  constexpr const char* name = "cntc_setundeformeddistc";
  Module3Problem* p = open_target(ire, icp, Access::Module3, name).m3;
  if (p == nullptr) return;
  if (ibase == nullptr || nparam == nullptr || (*nparam > 0 && prmudf == nullptr))
    return reject(name, "null argument");
  const double len = p->units.length;
  rollcontact::model::UndeformedDistance g;
  g.ibase = *ibase;
  const int n = *nparam;
  switch (*ibase) {
    case 1:  // b1..b3 [1/L], b4, b5 [-], b6 [L]
      if (n != 6) return reject(name, "ibase = 1 needs nparam = 6");
      g.coeffs = {prmudf[0] / len, prmudf[1] / len, prmudf[2] / len,
                  prmudf[3],       prmudf[4],       prmudf[5] * len};
      break;
    case 2: {  // nn, xm, rm, y1, dy1, h(1..nn) [L]
      if (n < 5) return reject(name, "ibase = 2 needs nparam = 5 + nn");
      const int nn = static_cast<int>(std::lround(prmudf[0]));
      if (nn < 1 || n != 5 + nn) return reject(name, "ibase = 2 needs nparam = 5 + nn");
      g.xm = prmudf[1] * len;
      g.rm = prmudf[2] * len;
      g.y1 = prmudf[3] * len;
      g.dy1 = prmudf[4] * len;
      for (int k = 0; k < nn; ++k) g.coeffs.push_back(prmudf[5 + k] * len);
      break;
    }
    case 3:  // b1 [L], b2 [1/L], b3, b4 [L], b5 [1/L], b6, b7, b8 [L]
      if (n != 8) return reject(name, "ibase = 3 needs nparam = 8");
      g.coeffs = {prmudf[0] * len, prmudf[1] / len, prmudf[2] * len, prmudf[3] * len,
                  prmudf[4] / len, prmudf[5] * len, prmudf[6] * len, prmudf[7] * len};
      break;
    case 9: {
      const auto& pc = p->record.potential;
      if (!p->grid_given || pc.ipotcn < 0)
        return reject(name, "ibase = 9 needs the potential contact (setpotcontact) first");
      if (n != pc.mx * pc.my)
        return reject(name, fmt::format("ibase = 9 needs nparam = mx*my = {}", pc.mx * pc.my));
      g.values.assign(prmudf, prmudf + n);
      for (double& v : g.values) v *= len;
      break;
    }
    default:
      return reject(name, fmt::format("ibase = {} not one of 1, 2, 3, 9", *ibase));
  }
  p->record.geometry = std::move(g);
  p->geometry_given = true;
}

CNTC_EXPORT void cntc_setcreepages(int* ire, int* icp, double* vx, double* vy, double* phi) {
  Module3Problem* p = open_target(ire, icp, Access::Module3, "cntc_setcreepages").m3;
  if (p == nullptr || vx == nullptr || vy == nullptr || phi == nullptr) return;
  rollcontact::format::Kinematics& k = p->record.kinematics;
  const Units& u = p->units;
  const bool shift = p->record.digits.t == 1;
  // Shifts [L] and a rotation [rad], or creepages [-] and spin [A/L]. The body sign of the
  // unit convention applies to outputs only (§1.4): an MBS code passes CONTACT the creepages
  // as they are in SIMPACK units too, and gets the forces on the wheel back.
  k.cksi = *vx * (shift ? u.length : 1.0);
  k.ceta = *vy * (shift ? u.length : 1.0);
  k.cphi = *phi / (shift ? 1.0 : u.length);
}
