// Results per contact patch (spec library-api.md §2.9): a module-3 problem's solution, or patch
// icp of the last wheel/rail solution. Outputs are in the problem's units, tangential ones with
// the body sign. A left wheel's totals (FS, MN, η, φ) are already in CONTACT's output
// convention; its fields are still those of the mirrored (right-wheel) computation, so they get
// the left-side sign (py, uy, sy) and are numbered in reverse along y. Before a result exists,
// or for a patch that was not found, the outputs are left untouched.

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "bindings/c/cntc_export.hpp"
#include "bindings/c/cntc_library.hpp"

namespace rollcontact::cntc {
namespace {

/// A solved patch as the getters see it.
struct PatchView {
  const Solution* s = nullptr;
  Units units;
  double left = 1.0;                      ///< −1 for a left wheel (C1 = 0, 4)
  bool shift = false;                     ///< T = 1: shifts [mm, mm, rad] instead of creepages
  double xi = 0.0, eta = 0.0, phi = 0.0;  ///< creepages [-, -, rad/mm] or shifts
  double veloc = 0.0;                     ///< [mm/s]
  double chi = 0.0, dq = 1.0;             ///< rolling direction [rad], step [mm] in effect
  Target target;                          ///< the problem, for its settings
  /// The patch's Coulomb coefficient, and per grid row where it varies across the patch (V=1
  /// in module 1, V=3 in module 3): the local friction coefficient where the solution has none.
  double mu = 0.0;
  std::vector<double> mu_rows;
};

std::optional<PatchView> patch_of(const int* ire, const int* icp, const char* routine,
                                  Access access = Access::Results) {
  const Target t = open_target(ire, icp, access, routine);
  if (!t) return std::nullopt;
  PatchView v;
  v.units = t.units();
  v.target = t;
  if (t.m3 != nullptr) {
    if (!t.m3->result) {
      library().log(fmt::format("{}: no results yet for ire = {}, icp = {}", routine, *ire, *icp));
      return std::nullopt;
    }
    const Solution& s = *t.m3->result;
    v.s = &s;
    v.shift = t.m3->record.digits.t == 1;
    v.xi = v.shift ? s.totals.shift_x : s.totals.creep_x;
    v.eta = v.shift ? s.totals.shift_y : s.totals.creep_y;
    v.phi = v.shift ? t.m3->record.kinematics.cphi : s.totals.spin;
    v.veloc = t.m3->record.kinematics.veloc;
    v.chi = s.kinematics.chi;
    v.dq = s.kinematics.dq;
    const format::Friction& f = t.m3->record.friction;
    v.mu = std::min(f.fstat, f.fkin);
    for (const format::FrictionValues& row : f.rows)
      v.mu_rows.push_back(std::min(row.fstat, row.fkin));
    return v;
  }
  const auto& result = t.m1->result;
  const int n = result ? static_cast<int>(result->patches.size()) : 0;
  if (t.icp < 1 || t.icp > n) {
    library().log(fmt::format("{}: ire = {} has no contact patch {} (code {})", routine, *ire,
                              t.icp, CNTC_err_icp));
    return std::nullopt;
  }
  const WheelRailPatch& w = result->patches[static_cast<std::size_t>(t.icp - 1)];
  v.s = &w.solution;
  v.left = t.m1->record.is_left() ? -1.0 : 1.0;
  v.xi = w.xi;
  v.eta = w.eta;
  v.phi = w.phi_per_mm;
  v.veloc = w.veloc_mm_s;
  v.chi = w.chi_rad;
  v.dq = w.dq_mm;
  v.mu = w.friction.static_coefficient;
  v.mu_rows = w.friction.row_coefficients;  // V=1: per row of the patch
  return v;
}

/// The local friction coefficient per element: the solver's where it varies with the slip or
/// the temperature, else the patch's (per row where it varies across the patch).
std::vector<double> local_friction(const PatchView& v) {
  const Solution& s = *v.s;
  if (!s.mu.empty()) return s.mu;
  const Grid& g = s.grid;
  std::vector<double> mu(g.size(), v.mu);
  if (static_cast<int>(v.mu_rows.size()) == g.my)
    for (int iy = 0; iy < g.my; ++iy)
      for (int ix = 0; ix < g.mx; ++ix)
        mu[g.index(ix, iy)] = v.mu_rows[static_cast<std::size_t>(iy)];
  return mu;
}

/// Copies min(lenarr, mx·my) values of `field` × factor, element j = ix + mx·iy; for a left
/// wheel the grid is numbered in reverse along y (§2.9).
void copy_field(const PatchView& v, const std::vector<double>& field, const int* lenarr,
                double* out, double factor) {
  if (lenarr == nullptr || out == nullptr || field.empty()) return;
  const Grid& g = v.s->grid;
  const std::size_t n = std::min(field.size(), static_cast<std::size_t>(std::max(0, *lenarr)));
  for (std::size_t j = 0; j < n; ++j) {
    const int ix = static_cast<int>(j % static_cast<std::size_t>(g.mx));
    const int iy = static_cast<int>(j / static_cast<std::size_t>(g.mx));
    out[j] = field[g.index(ix, v.left < 0.0 ? g.my - 1 - iy : iy)] * factor;
  }
}

}  // namespace
}  // namespace rollcontact::cntc

using namespace rollcontact;
using namespace rollcontact::cntc;

CNTC_EXPORT void cntc_gethertzcontact(int* ire, int* icp, int* lenarr, double* values) {
  const auto v = patch_of(ire, icp, "cntc_gethertzcontact", Access::Module3);
  if (!v || lenarr == nullptr || values == nullptr) return;
  const double len = v->units.length;
  const HertzReport& h = v->s->hertz;
  const double all[10] = {
      h.a1 * len, h.b1 * len, h.aa / len, h.bb / len, h.rho / len,
      h.cp / len, h.scale,    0.0,        0.0,        h.bb > 0 ? h.aa / h.bb : 0};
  for (int k = 0; k < std::min(*lenarr, 10); ++k) values[k] = all[k];
}

CNTC_EXPORT void cntc_getreferencevelocity(int* ire, int* icp, double* veloc) {
  const auto v = patch_of(ire, icp, "cntc_getreferencevelocity");
  if (!v || veloc == nullptr) return;
  *veloc = v->veloc / v->units.velocity;
}

CNTC_EXPORT void cntc_getnumelements(int* ire, int* icp, int* mx, int* my) {
  const auto v = patch_of(ire, icp, "cntc_getnumelements");
  if (!v || mx == nullptr || my == nullptr) return;
  *mx = v->s->grid.mx;
  *my = v->s->grid.my;
}

CNTC_EXPORT void cntc_getgriddiscretization(int* ire, int* icp, double* dx, double* dy) {
  if (dx == nullptr || dy == nullptr) return;
  if (icp != nullptr && *icp == -1) {  // module 1: the wheel/rail problem's DX, DS (category 7)
    const Target t = open_target(ire, icp, Access::Either, "cntc_getgriddiscretization");
    if (t.m1 == nullptr) return;
    *dx = t.m1->record.discretisation.dx / t.m1->units.length;
    *dy = t.m1->record.discretisation.ds / t.m1->units.length;
    return;
  }
  const auto v = patch_of(ire, icp, "cntc_getgriddiscretization", Access::Either);
  if (!v) return;
  *dx = v->s->grid.dx / v->units.length;
  *dy = v->s->grid.dy / v->units.length;
}

CNTC_EXPORT void cntc_getpotcontact(int* ire, int* icp, int* lenarr, double* values) {
  const auto v = patch_of(ire, icp, "cntc_getpotcontact");
  if (!v || lenarr == nullptr || values == nullptr) return;
  const double len = v->units.length;
  const Grid& g = v->s->grid;
  // [mx, my, xc1, yc1, dx, dy] (the ipotcn = 3 form); left wheel: yc1 = −ycm.
  const double yc1 = v->left < 0.0 ? -g.y_centre(g.my - 1) : g.y_centre(0);
  const double all[6] = {double(g.mx), double(g.my), g.x_centre(0) / len,
                         yc1 / len,    g.dx / len,   g.dy / len};
  for (int k = 0; k < *lenarr; ++k) values[k] = k < 6 ? all[k] : 0.0;
}

CNTC_EXPORT void cntc_getpenetration(int* ire, int* icp, double* pen) {
  const auto v = patch_of(ire, icp, "cntc_getpenetration");
  if (!v || pen == nullptr) return;
  *pen = v->s->totals.pen / v->units.length;
}

CNTC_EXPORT void cntc_getcreepages(int* ire, int* icp, double* vx, double* vy, double* phi) {
  const auto v = patch_of(ire, icp, "cntc_getcreepages");
  if (!v || vx == nullptr || vy == nullptr || phi == nullptr) return;
  const double body = v->units.body, len = v->units.length;
  *vx = body * (v->shift ? v->xi / len : v->xi);
  *vy = body * (v->shift ? v->eta / len : v->eta);
  *phi = body * (v->shift ? v->phi : v->phi * len);
}

CNTC_EXPORT void cntc_getcontactforces(int* ire, int* icp, double* fn, double* tx, double* ty,
                                       double* mz) {
  const auto v = patch_of(ire, icp, "cntc_getcontactforces");
  if (!v || fn == nullptr || tx == nullptr || ty == nullptr || mz == nullptr) return;
  const Totals& t = v->s->totals;
  const double body = v->units.body;
  *fn = t.fn;
  *tx = body * t.fx;
  *ty = body * t.fy;
  *mz = body * t.mz / v->units.length;
}

CNTC_EXPORT void cntc_getcontactpatchareas(int* ire, int* icp, double* carea, double* harea,
                                           double* sarea) {
  const auto v = patch_of(ire, icp, "cntc_getcontactpatchareas");
  if (!v || carea == nullptr || harea == nullptr || sarea == nullptr) return;
  const double element = v->s->grid.element_area() / v->units.area();
  const Statistics& st = v->s->statistics;
  *carea = st.ncon * element;
  *harea = st.nadh * element;
  *sarea = st.nslip * element;
}

CNTC_EXPORT void cntc_getelementdivision(int* ire, int* icp, int* lenarr, int* eldiv) {
  const auto v = patch_of(ire, icp, "cntc_getelementdivision");
  if (!v || lenarr == nullptr || eldiv == nullptr) return;
  std::vector<double> state(v->s->state.size());
  for (std::size_t i = 0; i < state.size(); ++i) state[i] = static_cast<int>(v->s->state[i]);
  std::vector<double> ordered(state.size());
  copy_field(*v, state, lenarr, ordered.data(), 1.0);
  const std::size_t n = std::min(state.size(), static_cast<std::size_t>(std::max(0, *lenarr)));
  for (std::size_t i = 0; i < n; ++i) eldiv[i] = static_cast<int>(ordered[i]);
}

CNTC_EXPORT void cntc_getmaximumpressure(int* ire, int* icp, double* pnmax) {
  const auto v = patch_of(ire, icp, "cntc_getmaximumpressure");
  if (!v || pnmax == nullptr) return;
  double m = 0.0;
  for (double p : v->s->pn) m = std::max(m, std::abs(p));
  *pnmax = m / v->units.pressure();
}

CNTC_EXPORT void cntc_getmaximumtraction(int* ire, int* icp, double* ptmax) {
  const auto v = patch_of(ire, icp, "cntc_getmaximumtraction");
  if (!v || ptmax == nullptr) return;
  double m = 0.0;
  const Solution& s = *v->s;
  for (std::size_t i = 0; i < s.px.size(); ++i) m = std::max(m, std::hypot(s.px[i], s.py[i]));
  *ptmax = m / v->units.pressure();
}

CNTC_EXPORT void cntc_getfielddata(int* ire, int* icp, int* ifld, int* lenarr, double* fld) {
  const auto v = patch_of(ire, icp, "cntc_getfielddata");
  if (!v || ifld == nullptr) return;
  const Solution& s = *v->s;
  const double pressure = 1.0 / v->units.pressure(), length = 1.0 / v->units.length;
  const double body = v->units.body, y = v->left;  // the solution holds the relative slip
  switch (*ifld) {
    case CNTC_fld_h:
      return copy_field(*v, s.h, lenarr, fld, length);
    case CNTC_fld_px:
      return copy_field(*v, s.px, lenarr, fld, body * pressure);
    case CNTC_fld_py:
      return copy_field(*v, s.py, lenarr, fld, body * y * pressure);
    case CNTC_fld_pn:
      return copy_field(*v, s.pn, lenarr, fld, pressure);
    case CNTC_fld_ux:
      return copy_field(*v, s.ux, lenarr, fld, length);
    case CNTC_fld_uy:
      return copy_field(*v, s.uy, lenarr, fld, y * length);
    case CNTC_fld_un:
      return copy_field(*v, s.un, lenarr, fld, length);
    case CNTC_fld_sx:
      return copy_field(*v, s.sx, lenarr, fld, body);
    case CNTC_fld_sy:
      return copy_field(*v, s.sy, lenarr, fld, body * y);
    case CNTC_fld_mu:
      return copy_field(*v, local_friction(*v), lenarr, fld, 1.0);
    case CNTC_fld_taucrt:  // M = 4 with plasticity only
      if (!s.yield_limit.empty()) return copy_field(*v, s.yield_limit, lenarr, fld, pressure);
      break;
    case CNTC_fld_uplsx:
      if (!s.plastic_x.empty()) return copy_field(*v, s.plastic_x, lenarr, fld, length);
      break;
    case CNTC_fld_uplsy:
      if (!s.plastic_y.empty()) return copy_field(*v, s.plastic_y, lenarr, fld, y * length);
      break;
    case CNTC_fld_wx:  // the rigid slip posed, as sx (T = 1, 2, 3 only)
      if (!s.wx.empty()) return copy_field(*v, s.wx, lenarr, fld, body);
      break;
    case CNTC_fld_wy:
      if (!s.wy.empty()) return copy_field(*v, s.wy, lenarr, fld, body * y);
      break;
    case CNTC_fld_temp1:  // [°C]; computed with H >= 1 only
      if (!s.temp1.empty()) return copy_field(*v, s.temp1, lenarr, fld, 1.0);
      break;
    case CNTC_fld_temp2:
      if (!s.temp2.empty()) return copy_field(*v, s.temp2, lenarr, fld, 1.0);
      break;
    default:
      break;
  }
  library().log(fmt::format("cntc_getfielddata: field {} does not exist", *ifld));
}

CNTC_EXPORT void cntc_gettractions(int* ire, int* icp, int* lenarr, double* pn, double* px,
                                   double* py) {
  int f_pn = CNTC_fld_pn, f_px = CNTC_fld_px, f_py = CNTC_fld_py;
  cntc_getfielddata(ire, icp, &f_pn, lenarr, pn);
  cntc_getfielddata(ire, icp, &f_px, lenarr, px);
  cntc_getfielddata(ire, icp, &f_py, lenarr, py);
}

CNTC_EXPORT void cntc_getmicroslip(int* ire, int* icp, int* lenarr, double* sx, double* sy) {
  int f_sx = CNTC_fld_sx, f_sy = CNTC_fld_sy;
  cntc_getfielddata(ire, icp, &f_sx, lenarr, sx);
  cntc_getfielddata(ire, icp, &f_sy, lenarr, sy);
}

CNTC_EXPORT void cntc_getdisplacements(int* ire, int* icp, int* lenarr, double* un, double* ux,
                                       double* uy) {
  int f_un = CNTC_fld_un, f_ux = CNTC_fld_ux, f_uy = CNTC_fld_uy;
  cntc_getfielddata(ire, icp, &f_un, lenarr, un);
  cntc_getfielddata(ire, icp, &f_ux, lenarr, ux);
  cntc_getfielddata(ire, icp, &f_uy, lenarr, uy);
}

CNTC_EXPORT void cntc_getcalculationtime(int* ire, int* icp, double* tcpu, double* twall) {
  if (tcpu == nullptr || twall == nullptr) return;
  const Target t = open_target(ire, icp, Access::Results, "cntc_getcalculationtime");
  if (t.m3 != nullptr) {
    *tcpu = t.m3->cpu_seconds;
    *twall = t.m3->wall_seconds;
  } else if (t.m1 != nullptr) {
    *tcpu = t.m1->cpu_seconds;
    *twall = t.m1->wall_seconds;
  }
}

CNTC_EXPORT void cntc_resetcalculationtime(int* ire, int* icp) {
  const Target t = open_target(ire, icp, Access::Results, "cntc_resetcalculationtime");
  if (t.m3 != nullptr) t.m3->cpu_seconds = t.m3->wall_seconds = 0.0;
  if (t.m1 != nullptr) t.m1->cpu_seconds = t.m1->wall_seconds = 0.0;
}

CNTC_EXPORT void cntc_getmaximumtemperature(int* ire, int* icp, double* t1max, double* t2max) {
  const auto v = patch_of(ire, icp, "cntc_getmaximumtemperature");
  if (!v || t1max == nullptr || t2max == nullptr) return;
  // Maxima over the contact [°C] (no unit conversion); 0 and 0 without the calculation (H = 0).
  *t1max = v->s->totals.max_temp1;
  *t2max = v->s->totals.max_temp2;
}

CNTC_EXPORT void cntc_getsensitivities(int* ire, int* icp, int* lenout, int* lenin, double* sens) {
  const auto v = patch_of(ire, icp, "cntc_getsensitivities");
  if (!v || lenout == nullptr || lenin == nullptr || sens == nullptr) return;
  // sens(lenout, lenin) column-major; outputs fn, fx, fy, mz; inputs pen, ξ, η, φ. What the
  // solver computed (the normal stiffness, the creep-force derivatives of the force
  // iteration); zeros elsewhere (not computed).
  const Sensitivities& d = v->s->sensitivities;
  const double len = v->units.length, y = v->left;
  double all[4][4] = {};
  all[0][0] = d.dfn_dpen * len;  // [F/L]
  all[1][1] = d.dfx_dksi;
  all[1][2] = y * d.dfx_deta;
  all[2][1] = y * d.dfy_dksi;
  all[2][2] = d.dfy_deta;
  for (int j = 0; j < *lenin; ++j)
    for (int i = 0; i < *lenout; ++i) sens[i + j * *lenout] = i < 4 && j < 4 ? all[i][j] : 0.0;
}

CNTC_EXPORT void cntc_getparameters(int* ire, int* icp, int* itask, int* lenarr, double* values) {
  const auto v = patch_of(ire, icp, "cntc_getparameters");
  if (!v || itask == nullptr || lenarr == nullptr || values == nullptr) return;
  const Target& t = v->target;
  const format::Materials& m = t.m3 != nullptr ? t.m3->record.materials : t.m1->record.materials;
  const format::Friction& f = t.m3 != nullptr ? t.m3->record.friction : t.m1->record.friction;
  const int mdigit = t.m3 != nullptr ? t.m3->record.digits.m : t.m1->record.digits.m;
  const double len = v->units.length, pressure = v->units.pressure();
  const double tau_c0 = mdigit == 4 ? m.model_params[2] : 0.0;
  std::vector<double> out;
  if (*itask == 1) {
    const auto& k = t.m3 != nullptr ? t.m3->record.kinematics : format::Kinematics{};
    out = {v->veloc / v->units.velocity,
           v->chi,
           v->dq / len,
           k.spinxo / len,
           k.spinyo / len,
           tau_c0 / pressure};
  } else if (*itask == 2) {
    const CombinedMaterial& c = v->s->material;
    const SimplifiedReport& sr = v->s->simplified;
    const double flx = 1.0 / (len * len * len);  // [L³/F]
    const auto& mp = m.model_params;
    const bool one_flx = mdigit == 2, fastsim = mdigit == 2 || mdigit == 3 || mdigit == 5;
    const double k0 = fastsim ? mp[one_flx ? 1 : 0] : 0.0;
    const double alfa = fastsim ? mp[one_flx ? 2 : 1] : 0.0;
    const double beta = fastsim ? mp[one_flx ? 3 : 2] : 0.0;
    const bool layer = mdigit == 4;
    const format::Damping& damping = t.m3 != nullptr ? t.m3->record.damping : t.m1->record.damping;
    out = {m.gg1 / pressure,
           m.gg2 / pressure,
           c.g / pressure,
           m.poiss1,
           m.poiss2,
           c.nu,
           c.k,
           sr.flx1 * flx,
           sr.flx2 * flx,
           sr.flx3 * flx,
           k0,
           alfa,
           beta,
           sr.k_eff,
           layer ? mp[0] / pressure : 0.0,
           layer ? mp[1] / len : 0.0,
           tau_c0 / pressure,
           layer ? mp[3] / (pressure / len) : 0.0,
           damping.cdampn,
           damping.cdampt,
           damping.dfnmax,
           damping.dftmax};
  } else if (*itask == 3) {
    const format::VariableFriction* vf = t.m1 != nullptr && t.m1->record.variable_friction.v != 0
                                             ? &t.m1->record.variable_friction
                                             : nullptr;
    const std::size_t nvf = vf != nullptr ? vf->sets.size() : 1;
    out = {double(f.law), double(nvf), f.memdst, f.mem_s0};
    for (std::size_t i = 0; i < nvf; ++i) {
      out.push_back(vf != nullptr ? vf->positions[i] : 0.0);
      out.push_back(vf != nullptr ? vf->sets[i].fstat : f.fstat);
      out.push_back(vf != nullptr ? vf->sets[i].fkin : f.fkin);
    }
  } else {
    return;  // any other task writes nothing (§2.9)
  }
  for (int k = 0; k < std::min(*lenarr, static_cast<int>(out.size())); ++k)
    values[k] = out[static_cast<std::size_t>(k)];
}
