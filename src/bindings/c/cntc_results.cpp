// cntc_calculate and the module-3 result routines (spec library-api.md §2.7, §2.9).

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>

#include "bindings/c/cntc_export.hpp"
#include "bindings/c/cntc_library.hpp"
#include "format/inp/to_model.hpp"
#include "rollcontact/errors.hpp"

namespace rollcontact::cntc {
namespace {

Module3Problem* problem(const int* ire, const int* icp, Access access, const char* routine,
                        int* code = nullptr) {
  if (ire == nullptr || icp == nullptr) {
    library().log(fmt::format("{}: null handle argument (refused)", routine));
    if (code != nullptr) *code = CNTC_err_icp;
    return nullptr;
  }
  return library().module3(*ire, *icp, access, routine, code);
}

/// The last solution of a problem, or nullptr (logged) before the first calculation.
const Solution* solved(const int* ire, const int* icp, const char* routine) {
  Module3Problem* p = problem(ire, icp, Access::Results, routine);
  if (p == nullptr) return nullptr;
  if (!p->result) {
    library().log(fmt::format("{}: no results yet for ire = {}, icp = {}", routine, *ire, *icp));
    return nullptr;
  }
  return &*p->result;
}

const Units& units_of(const int* ire, const int* icp) {
  return library().module3(*ire, *icp, Access::Results, "units")->units;
}

/// Contact elements in the outer rows and columns of the potential contact: the grid may be
/// too small (CONTACT's positive warning code of calculate).
int elements_at_boundary(const Solution& s) {
  const Grid& g = s.grid;
  int count = 0;
  for (int iy = 0; iy < g.my; ++iy)
    for (int ix = 0; ix < g.mx; ++ix) {
      const bool edge = ix == 0 || iy == 0 || ix == g.mx - 1 || iy == g.my - 1;
      if (edge && s.state[g.index(ix, iy)] != ElementState::Exterior) ++count;
    }
  return count;
}

/// Solves the problem's current case; 0, a positive boundary count or a negative CNTC code.
int calculate(Module3Problem& p) {
  format::CaseRecord record = p.record;
  if (!p.grid_given) {
    library().log("cntc_calculate: no potential contact set (sethertzcontact or setpotcontact)");
    return CNTC_err_discr;
  }
  if (record.potential.ipotcn > 0 && !p.geometry_given) {
    library().log("cntc_calculate: no undeformed distance set (setundeformeddistc)");
    return CNTC_err_input;
  }
  record.case_number = p.cases + 1;
  record.digits.z = record.potential.ipotcn > 0 ? 2 : 0;
  if (p.cases == 0 || !p.result) record.digits.p = 2;  // the first case starts a sequence
  if (record.digits.r >= 2) return 0;                  // check only
  const auto wall0 = std::chrono::steady_clock::now();
  const std::clock_t cpu0 = std::clock();
  int code = 0;
  try {
    const model::PatchProblem problem = format::to_patch_problem(record);
    Solution s = p.solver.solve(problem);
    ++p.cases;
    if (!s.solver.converged) {
      library().log("cntc_calculate: " + s.solver.message);
      code = record.digits.t == 0 ? CNTC_err_norm : CNTC_err_tang;
    } else {
      code = elements_at_boundary(s);
    }
    p.result = std::move(s);
  } catch (const NotSupportedError& e) {
    library().log(std::string("cntc_calculate: ") + e.what());
    code = CNTC_err_other;
  } catch (const Error& e) {
    library().log(std::string("cntc_calculate: ") + e.what());
    code = CNTC_err_input;
  } catch (const std::exception& e) {
    library().log(std::string("cntc_calculate: internal error: ") + e.what());
    code = CNTC_err_other;
  }
  p.wall_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  p.cpu_seconds += static_cast<double>(std::clock() - cpu0) / CLOCKS_PER_SEC;
  return code;
}

/// Copies min(lenarr, n) values of `field` × factor (× body sign when asked) to `out`.
void copy_field(const std::vector<double>& field, const int* lenarr, double* out, double factor) {
  if (lenarr == nullptr || out == nullptr) return;
  const std::size_t n = std::min(field.size(), static_cast<std::size_t>(std::max(0, *lenarr)));
  for (std::size_t i = 0; i < n; ++i) out[i] = field[i] * factor;
}

}  // namespace
}  // namespace rollcontact::cntc

using namespace rollcontact;
using namespace rollcontact::cntc;

CNTC_EXPORT void cntc_calculate3(int* ire, int* icp, int* ierror) {
  int code = 0;
  Module3Problem* p = problem(ire, icp, Access::Settings, "cntc_calculate", &code);
  if (p == nullptr) {
    if (ierror != nullptr) *ierror = code;
    return;
  }
  const int result = calculate(*p);
  if (ierror != nullptr) *ierror = result;
}

CNTC_EXPORT void cntc_calculate(int* ire, int* icp, int* ierror) {
  int code = 0;
  Module3Problem* p = problem(ire, icp, Access::Settings, "cntc_calculate", &code);
  if (p == nullptr) {
    if (ierror != nullptr) *ierror = code;
    return;
  }
  std::unique_lock lock(p->busy, std::try_to_lock);
  if (!lock.owns_lock()) {  // another thread is calculating this (ire, icp)
    if (ierror != nullptr) *ierror = 305;
    return;
  }
  const int result = calculate(*p);
  if (ierror != nullptr) *ierror = result;
}

CNTC_EXPORT void cntc_gethertzcontact(int* ire, int* icp, int* lenarr, double* values) {
  const Solution* s = solved(ire, icp, "cntc_gethertzcontact");
  if (s == nullptr || lenarr == nullptr || values == nullptr) return;
  const Units& u = units_of(ire, icp);
  const HertzReport& h = s->hertz;
  const double all[10] = {h.a1 * u.length,
                          h.b1 * u.length,
                          h.aa / u.length,
                          h.bb / u.length,
                          h.rho / u.length,
                          h.cp / u.length,
                          h.scale,
                          0.0,
                          0.0,
                          h.bb > 0.0 ? h.aa / h.bb : 0.0};
  for (int k = 0; k < std::min(*lenarr, 10); ++k) values[k] = all[k];
}

CNTC_EXPORT void cntc_getreferencevelocity(int* ire, int* icp, double* veloc) {
  Module3Problem* p = problem(ire, icp, Access::Results, "cntc_getreferencevelocity");
  if (p == nullptr || veloc == nullptr) return;
  *veloc = p->record.kinematics.veloc / p->units.velocity;
}

CNTC_EXPORT void cntc_getnumelements(int* ire, int* icp, int* mx, int* my) {
  const Solution* s = solved(ire, icp, "cntc_getnumelements");
  if (s == nullptr || mx == nullptr || my == nullptr) return;
  *mx = s->grid.mx;
  *my = s->grid.my;
}

CNTC_EXPORT void cntc_getgriddiscretization(int* ire, int* icp, double* dx, double* dy) {
  const Solution* s = solved(ire, icp, "cntc_getgriddiscretization");
  if (s == nullptr || dx == nullptr || dy == nullptr) return;
  const Units& u = units_of(ire, icp);
  *dx = s->grid.dx / u.length;
  *dy = s->grid.dy / u.length;
}

CNTC_EXPORT void cntc_getpotcontact(int* ire, int* icp, int* lenarr, double* values) {
  const Solution* s = solved(ire, icp, "cntc_getpotcontact");
  if (s == nullptr || lenarr == nullptr || values == nullptr) return;
  const Units& u = units_of(ire, icp);
  const Grid& g = s->grid;
  const double all[6] = {
      double(g.mx),    double(g.my),   g.x_centre(0) / u.length, g.y_centre(0) / u.length,
      g.dx / u.length, g.dy / u.length};
  for (int k = 0; k < *lenarr; ++k) values[k] = k < 6 ? all[k] : 0.0;
}

CNTC_EXPORT void cntc_getpenetration(int* ire, int* icp, double* pen) {
  const Solution* s = solved(ire, icp, "cntc_getpenetration");
  if (s == nullptr || pen == nullptr) return;
  *pen = s->totals.pen / units_of(ire, icp).length;
}

CNTC_EXPORT void cntc_getcreepages(int* ire, int* icp, double* vx, double* vy, double* phi) {
  const Solution* s = solved(ire, icp, "cntc_getcreepages");
  if (s == nullptr || vx == nullptr || vy == nullptr || phi == nullptr) return;
  const Module3Problem* p = problem(ire, icp, Access::Results, "cntc_getcreepages");
  const Units& u = p->units;
  const bool shift = p->record.digits.t == 1;
  const Totals& t = s->totals;
  *vx = u.body * (shift ? t.shift_x / u.length : t.creep_x);
  *vy = u.body * (shift ? t.shift_y / u.length : t.creep_y);
  *phi = u.body * (shift ? p->record.kinematics.cphi : t.spin * u.length);
}

CNTC_EXPORT void cntc_getcontactforces(int* ire, int* icp, double* fn, double* tx, double* ty,
                                       double* mz) {
  const Solution* s = solved(ire, icp, "cntc_getcontactforces");
  if (s == nullptr || fn == nullptr || tx == nullptr || ty == nullptr || mz == nullptr) return;
  const Units& u = units_of(ire, icp);
  *fn = s->totals.fn;
  *tx = u.body * s->totals.fx;
  *ty = u.body * s->totals.fy;
  *mz = u.body * s->totals.mz / u.length;
}

CNTC_EXPORT void cntc_getcontactpatchareas(int* ire, int* icp, double* carea, double* harea,
                                           double* sarea) {
  const Solution* s = solved(ire, icp, "cntc_getcontactpatchareas");
  if (s == nullptr || carea == nullptr || harea == nullptr || sarea == nullptr) return;
  const double element = s->grid.element_area() / units_of(ire, icp).area();
  const Statistics& st = s->statistics;
  *carea = st.ncon * element;
  *harea = st.nadh * element;
  *sarea = st.nslip * element;
}

CNTC_EXPORT void cntc_getelementdivision(int* ire, int* icp, int* lenarr, int* eldiv) {
  const Solution* s = solved(ire, icp, "cntc_getelementdivision");
  if (s == nullptr || lenarr == nullptr || eldiv == nullptr) return;
  const std::size_t n = std::min(s->state.size(), static_cast<std::size_t>(std::max(0, *lenarr)));
  for (std::size_t i = 0; i < n; ++i) eldiv[i] = static_cast<int>(s->state[i]);
}

CNTC_EXPORT void cntc_getmaximumpressure(int* ire, int* icp, double* pnmax) {
  const Solution* s = solved(ire, icp, "cntc_getmaximumpressure");
  if (s == nullptr || pnmax == nullptr) return;
  double m = 0.0;
  for (double v : s->pn) m = std::max(m, std::abs(v));
  *pnmax = m / units_of(ire, icp).pressure();
}

CNTC_EXPORT void cntc_getmaximumtraction(int* ire, int* icp, double* ptmax) {
  const Solution* s = solved(ire, icp, "cntc_getmaximumtraction");
  if (s == nullptr || ptmax == nullptr) return;
  double m = 0.0;
  for (std::size_t i = 0; i < s->px.size(); ++i) m = std::max(m, std::hypot(s->px[i], s->py[i]));
  *ptmax = m / units_of(ire, icp).pressure();
}

CNTC_EXPORT void cntc_getfielddata(int* ire, int* icp, int* ifld, int* lenarr, double* fld) {
  const Solution* s = solved(ire, icp, "cntc_getfielddata");
  if (s == nullptr || ifld == nullptr) return;
  const Units& u = units_of(ire, icp);
  const double pressure = 1.0 / u.pressure(), length = 1.0 / u.length;
  const double slip = u.body;  // the solution holds the relative slip already
  switch (*ifld) {
    case CNTC_fld_h:
      return copy_field(s->h, lenarr, fld, length);
    case CNTC_fld_px:
      return copy_field(s->px, lenarr, fld, u.body * pressure);
    case CNTC_fld_py:
      return copy_field(s->py, lenarr, fld, u.body * pressure);
    case CNTC_fld_pn:
      return copy_field(s->pn, lenarr, fld, pressure);
    case CNTC_fld_ux:
      return copy_field(s->ux, lenarr, fld, length);
    case CNTC_fld_uy:
      return copy_field(s->uy, lenarr, fld, length);
    case CNTC_fld_un:
      return copy_field(s->un, lenarr, fld, length);
    case CNTC_fld_sx:
      return copy_field(s->sx, lenarr, fld, slip);
    case CNTC_fld_sy:
      return copy_field(s->sy, lenarr, fld, slip);
    default:
      library().log(fmt::format("cntc_getfielddata: field {} does not exist", *ifld));
  }
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
  Module3Problem* p = problem(ire, icp, Access::Results, "cntc_getcalculationtime");
  if (p == nullptr || tcpu == nullptr || twall == nullptr) return;
  *tcpu = p->cpu_seconds;
  *twall = p->wall_seconds;
}

CNTC_EXPORT void cntc_resetcalculationtime(int* ire, int* icp) {
  Module3Problem* p = problem(ire, icp, Access::Results, "cntc_resetcalculationtime");
  if (p == nullptr) return;
  p->cpu_seconds = p->wall_seconds = 0.0;
}
