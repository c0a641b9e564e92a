// The O = 5 table of quantities per contact element (spec/outputs.md §3.6).

#include <cmath>
#include <numbers>
#include <ostream>
#include <span>
#include <string>

#include "format/report/number_format.hpp"
#include "format/report/report_internal.hpp"
#include "format/report/report_values.hpp"

namespace rollcontact::format::report {
namespace {

double at(std::span<const double> f, std::size_t i) {
  return i < f.size() ? f[i] : 0.0;
}

void write_header(std::ostream& os, int t, int h) {
  line(os, "");
  line(os, " QUANTITIES DISTRIBUTED OVER THE CONTACT AREA:");
  line(os, " \"H-PEN\" IS THE UNDEFORMED DISTANCE WITH THE APPROACH TAKEN INTO ACCOUNT.");
  if (t == 0) {
    line(os, " PN IS THE NORMAL PRESSURE, PT IS THE TANGENTIAL TRACTION (2-VECTOR).");
    line(os, " X, H AND PEN ARE IN MM, PN AND PT ARE IN N/MM^2, AND ARGUMENTS ARE IN DEGREES.");
    line(os, "");
    line(os, "     X          H-PEN        PN       ABS(PT)        ARG(PT)");
    return;
  }
  const std::string columns =
      "     X         H-PEN        PN      TRCBND    ABS(PT)     ARG(PT;-S)  ABS(S)      ";
  line(os, " PN IS THE NORMAL PRESSURE, PT THE TANGENTIAL TRACTION (2-VECTOR).");
  if (t == 1) {
    line(os, " S IS THE SLIP DISTANCE PER STEP, WHICH IS OPPOSITE TO THE TANGENTIAL TRACTION.");
    line(os, " RIGID SHIFT(X, Y) ARE THE (X, Y) COMPONENTS OF THE RIGID SHIFT DISTANCE W.");
    line(os,
         " X, H, PEN, S AND W ARE IN MM, PN AND PT ARE IN N/MM^2, AND ARGUMENTS ARE IN DEGREES.");
    line(os, "");
    line(os, "");
    line(os, columns + "RIGID SHIFT(X, Y)");
    return;
  }
  line(os, " S IS THE RELATIVE SLIP VELOCITY, WHICH IS OPPOSITE TO THE TANGENTIAL TRACTION.");
  // H >= 1: the surface temperatures take the place of the rigid slip (spec/outputs.md §3.6).
  if (h >= 1)
    line(os, " TEMP1, TEMP2 ARE THE SURFACE TEMPERATURES OF BODY 1 AND BODY 2 IN DEGREES C.");
  else
    line(os, " RIGID SLIP(X, Y) ARE THE (X, Y) COMPONENTS OF THE RELATIVE RIGID SLIP VELOCITY W.");
  line(os,
       " X, H AND PEN ARE IN MM, PN AND PT ARE IN N/MM^2, S AND W ARE DIMENSIONLESS, ARGUMENT IS "
       "IN DEGREES.");
  line(os, "");
  line(os, columns + (h >= 1 ? " TEMP1      TEMP2" : "RIGID SLIP(X, Y)"));
}

/// The rows: every contact element (O ≥ 6: every element) by grid row.
void write_rows(std::ostream& os, const ElementTableInputs& in, const Solution& solution) {
  const Grid& g = solution.grid;
  for (int iy = 0; iy < g.my; ++iy) {
    bool row_started = false;
    for (int ix = 0; ix < g.mx; ++ix) {
      const std::size_t i = g.index(ix, iy);
      const ElementState state = solution.state[i];
      if (state == ElementState::Exterior && in.o < 6) continue;
      if (!row_started) {
        line(os, "");
        line(os, " Y = " + fortran_g(g.y_centre(iy), 12, 4) + " ROW" + fortran_i(iy + 1, 3) +
                     " OF THE POTENTIAL CONTACT");
        line(os, "");
        row_started = true;
      }
      const double x = g.x_centre(ix);
      const double pn = at(solution.pn, i), px = at(solution.px, i), py = at(solution.py, i);
      const double h_pen = at(solution.h, i) - in.pen;
      const double pt_abs = std::hypot(px, py);
      const double pt_arg = std::atan2(py, px) * 180.0 / std::numbers::pi;
      if (in.t == 0) {
        line(os, " " + fortran_g(x, 12, 4) + fortran_g(h_pen, 12, 4) + fortran_g(pn, 12, 4) +
                     fortran_g(pt_abs, 12, 4) + fortran_f(pt_arg, 10, 1));
        continue;
      }
      // Traction bound mu p_n: exact for Coulomb friction; for slip-dependent laws the Solution
      // has no local mu, and |p_t| equals the bound in slip.
      double trcbnd = in.mu * pn;
      if (in.friction_law != 0 && state == ElementState::Slip) trcbnd = pt_abs;
      const double s_abs =
          state == ElementState::Slip ? std::hypot(at(solution.sx, i), at(solution.sy, i)) : 0.0;
      // H >= 1: the surface temperatures TEMP1, TEMP2 [°C] replace the rigid slip pair.
      const bool heat = in.h >= 1 && solution.temp1.size() == g.size();
      const double last1 = heat ? solution.temp1[i] : at(in.wx, i);
      const double last2 = heat ? solution.temp2[i] : at(in.wy, i);
      line(os, " " + fortran_g(x, 12, 4) + fortran_g(h_pen, 11, 3) + fortran_g(pn, 11, 3) +
                   fortran_g(trcbnd, 11, 3) + fortran_g(pt_abs, 11, 3) + fortran_f(pt_arg, 10, 1) +
                   "  " + fortran_g(s_abs, 11, 3) + fortran_g(last1, 11, 3) +
                   fortran_g(last2, 11, 3));
    }
  }
}

}  // namespace

void write_element_table(std::ostream& os, const ElementTableInputs& in, const Solution& solution) {
  if (solution.state.size() != solution.grid.size()) return;
  write_header(os, in.t, in.h);
  write_rows(os, in, solution);
}

void write_element_table(std::ostream& os, const CaseRecord& problem, const Solution& solution) {
  const auto& d = problem.digits;
  const Grid& g = solution.grid;
  const EffectiveKinematics ek = effective_kinematics(solution);
  const EffectiveCreepages c = printed_creepages(problem, solution);
  const auto& kin = problem.kinematics;
  const bool rolling = d.t >= 2;
  // Rigid slip (T=2,3) or shift (T=1) per element, physics.md §5, from the printed creepages;
  // E=2/E=3 drop a spin term.
  const double offset = rolling ? ek.dq * kin.facphi : 0.0;
  const bool spin_x = d.e != 3, spin_y = d.e != 2;
  std::vector<double> wx(g.size(), 0.0), wy(g.size(), 0.0);
  for (int iy = 0; iy < g.my; ++iy)
    for (int ix = 0; ix < g.mx; ++ix) {
      const std::size_t i = g.index(ix, iy);
      const double x = g.x_centre(ix), y = g.y_centre(iy);
      wx[i] = c.x - (spin_x ? c.phi * (y - kin.spinyo + std::sin(ek.chi) * offset) : 0.0);
      wy[i] = c.y + (spin_y ? c.phi * (x - kin.spinxo + std::cos(ek.chi) * offset) : 0.0);
    }
  ElementTableInputs in;
  in.t = d.t;
  in.h = d.h;
  in.o = d.o;
  in.pen = effective_approach(problem, solution);
  in.mu = static_friction(problem.friction);
  in.friction_law = problem.friction.law;
  in.wx = wx;
  in.wy = wy;
  write_element_table(os, in, solution);
}

}  // namespace rollcontact::format::report
