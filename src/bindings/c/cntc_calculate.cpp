// cntc_calculate (spec library-api.md §2.7): the problem's record becomes the model problem
// through the same adapters as an .inp case, and its own solver solves it. No exception leaves.

#include <fmt/format.h>

#include <chrono>
#include <ctime>

#include "bindings/c/cntc_export.hpp"
#include "bindings/c/cntc_library.hpp"
#include "format/inp/to_model.hpp"
#include "format/inp/to_wheelrail.hpp"
#include "rollcontact/errors.hpp"

namespace rollcontact::cntc {
namespace {

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

/// Runs `solve` with the problem's timers, turning exceptions into CONTACT's codes.
template <class Problem, class Solve>
int timed(Problem& p, Solve&& solve) {
  const auto wall0 = std::chrono::steady_clock::now();
  const std::clock_t cpu0 = std::clock();
  int code = 0;
  try {
    code = solve();
  } catch (const NotSupportedError& e) {
    library().log(std::string("cntc_calculate: ") + e.what());
    code = CNTC_err_other;
  } catch (const GeometryError& e) {
    library().log(std::string("cntc_calculate: ") + e.what());
    code = CNTC_err_search;
  } catch (const Error& e) {  // inconsistent settings: calculate has no input-error code
    library().log(std::string("cntc_calculate: ") + e.what());
    code = CNTC_err_other;
  } catch (const std::exception& e) {
    library().log(std::string("cntc_calculate: internal error: ") + e.what());
    code = CNTC_err_other;
  }
  p.wall_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  p.cpu_seconds += static_cast<double>(std::clock() - cpu0) / CLOCKS_PER_SEC;
  return code;
}

/// Module 3: 0, a positive boundary count or a negative CNTC code.
int calculate(Module3Problem& p) {
  format::CaseRecord record = p.record;
  if (!p.grid_given) {
    library().log("cntc_calculate: no potential contact set (sethertzcontact or setpotcontact)");
    return CNTC_err_discr;
  }
  if (record.potential.ipotcn > 0 && !p.geometry_given) {
    library().log("cntc_calculate: no undeformed distance set (setundeformeddistc)");
    return CNTC_err_other;
  }
  record.case_number = p.cases + 1;
  record.digits.z = record.potential.ipotcn > 0 ? 2 : 0;
  if (p.cases == 0 || !p.result) record.digits.p = 2;  // the first case starts a sequence
  if (record.digits.r >= 2) return 0;                  // check only
  return timed(p, [&] {
    Solution s = p.solver.solve(format::to_patch_problem(record));
    ++p.cases;
    int code = elements_at_boundary(s);
    if (!s.solver.converged) {
      library().log("cntc_calculate: " + s.solver.message);
      code = record.digits.t == 0 ? CNTC_err_norm : CNTC_err_tang;
    }
    p.result = std::move(s);
    return code;
  });
}

/// Module 1: 0 or a negative CNTC code, checked in CONTACT's order: profiles (−32), friction
/// (−33), then the solve (−25 contact search and geometry, −26 vertical-force iteration).
int calculate(Module1Problem& p) {
  format::WheelRailRecord record = p.record;
  if (record.rail.profile->y.empty() || !p.rail_error.empty() || record.wheel.profile->y.empty() ||
      !p.wheel_error.empty()) {
    library().log("cntc_calculate: rail or wheel profile missing or invalid");
    return CNTC_err_profil;
  }
  if (!p.friction_given) {
    library().log("cntc_calculate: no friction set (cntc_setfrictionmethod)");
    return CNTC_err_frclaw;
  }
  // A transient sequence (T = 1, 2) carries its tractions on the grid of its first case.
  const format::WheelRailDiscretisation& grid = record.discretisation;
  const bool transient = record.digits.t == 1 || record.digits.t == 2;
  if (transient && p.cases > 0 && p.result && record.digits.p != 2 &&
      (grid.dx != p.sequence_dx || grid.ds != p.sequence_ds)) {
    library().log(fmt::format(
        "cntc_calculate: DX, DS = {}, {} mm changed within a transient sequence (was {}, {})",
        grid.dx, grid.ds, p.sequence_dx, p.sequence_ds));
    return CNTC_err_discr;
  }
  record.case_number = p.cases + 1;
  if (record.digits.r >= 2) return 0;  // check only
  return timed(p, [&] {
    WheelRailSolution s = p.solver.solve(format::to_wheelrail_problem(record));
    ++p.cases;
    p.sequence_dx = record.discretisation.dx;
    p.sequence_ds = record.discretisation.ds;
    int code = 0;
    if (!s.converged) {
      library().log("cntc_calculate: " + s.message);
      code = CNTC_err_ftot;
    }
    p.result = std::move(s);
    return code;
  });
}

/// Locks the problem for the calculation (305 when another thread holds it) and solves it.
template <class Problem>
int locked_calculate(Problem& p) {
  std::unique_lock lock(p.busy, std::try_to_lock);
  if (!lock.owns_lock()) return 305;
  return calculate(p);
}

void run(int* ire, int* icp, int* ierror, bool lock, Access access, const char* routine) {
  int code = 0;
  const Target t = open_target(ire, icp, access, routine, &code);
  if (t.m3 != nullptr) code = lock ? locked_calculate(*t.m3) : calculate(*t.m3);
  if (t.m1 != nullptr) code = lock ? locked_calculate(*t.m1) : calculate(*t.m1);
  if (ierror != nullptr) *ierror = code;
}

}  // namespace
}  // namespace rollcontact::cntc

using rollcontact::cntc::Access;

CNTC_EXPORT void cntc_calculate(int* ire, int* icp, int* ierror) {
  rollcontact::cntc::run(ire, icp, ierror, true, Access::Settings, "cntc_calculate");
}

CNTC_EXPORT void cntc_calculate3(int* ire, int* icp, int* ierror) {
  rollcontact::cntc::run(ire, icp, ierror, false, Access::Module3, "cntc_calculate3");
}

CNTC_EXPORT void cntc_calculate1(int* ire, int* ierror) {
  int icp = -1;
  rollcontact::cntc::run(ire, &icp, ierror, false, Access::Module1, "cntc_calculate1");
}
