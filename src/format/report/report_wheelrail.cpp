// The module-1 (wheel/rail) blocks of the report (spec/outputs.md §3.8): vertical-force trace,
// problem echo, wheelset position, total forces on the rail, and per contact patch its reference
// location, kinematic constants, forces, statistics and element-division picture.

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <ostream>
#include <string>

#include "format/report/number_format.hpp"
#include "format/report/report_conformal.hpp"
#include "format/report/report_internal.hpp"
#include "format/report/report_subsurface.hpp"
#include "format/report/report_values.hpp"
#include "format/report/report_wheelrail_inputs.hpp"
#include "format/report/report_writer.hpp"

namespace rollcontact::format {

namespace {

using report::g12;
using report::line;
using report::sig;
std::string f4(double v) {
  return fortran_f(v, 12, 4);
}

void write_trace(std::ostream& os, const WheelRailSolution& s) {
  for (const VerticalForceStep& t : s.trace)
    line(os, fmt::format("    {:6d}, NR,  z_ws, Fz: {}{}, dFz/dz:{}", t.iteration, f4(t.z_ws_mm),
                         fmt_sig(12, 4, 4, t.fz_N), fmt_sig(12, 4, 4, t.dfz_dz_N_per_mm)));
}

/// A flexible wheelset's deviations and rates (spec/wheelrail-advanced.md §5.1), when any is set.
void write_wheel_deviations(std::ostream& os, const WheelDeviations& d) {
  if (!d.any_above(1e-10)) return;
  line(os, "");
  line(os, " FLEXIBLE WHEEL-SET DEVIATIONS");
  line(os, "     DXWHL       DYWHL       DZWHL       DROLLW      DYAWW       DPITCHW");
  line(os, "  " + sig(d.dx) + sig(d.dy) + sig(d.dz) + sig(d.droll) + sig(d.dyaw) + sig(d.dpitch));
  line(os, "");
  line(os, "     VXWHL       VYWHL       VZWHL       VROLLW      VYAWW       VPITCHW");
  line(os, "  " + sig(d.vx) + sig(d.vy) + sig(d.vz) + sig(d.vroll) + sig(d.vyaw) + sig(d.vpitch));
}

void write_problem_echo(std::ostream& os, const WheelRailRecord& r, const WheelRailSolution& s) {
  const ControlDigits& d = r.digits;
  const std::size_t n = s.patches.size();
  line(os, "");
  line(os, fmt::format(" WHEEL-{} CONTACT, {} WHEEL, {:2d} CONTACT {}",
                       r.is_roller() ? "ROLLER" : "RAIL", r.is_left() ? "LEFT" : "RIGHT", n,
                       n == 1 ? "PATCH" : "PATCHES"));
  line(os, "");
  line(os, fmt::format(" CPBTNFS.  CONFIG {}, PVTIME {}, BOUND {:2d}, TANG {:3d}, NORM {:3d}, "
                       "FORCE {:2d}, STRESS {}",
                       r.config, d.p, d.b, d.t, d.n, d.f, d.s));
  line(os, fmt::format(" VLDCMZE.  VARFRC {}, FRCLAW {}, DISCNS {}, INFLCF {}, MATER {:2d}, "
                       "ZTRACK {}, EWHEEL {}",
                       d.v, d.l, d.d, d.c, d.m, d.z, d.e));
  line(os, fmt::format(" HGIAOWR.  HEAT {:3d}, GAUSEI {}, IESTIM {}, MATFIL {}, OUTPUT {}, "
                       "FLOW {:3d}, RETURN {}",
                       d.h, d.g, d.i, d.a, d.o, d.w, d.r));
  report::write_wheelrail_problem_lines(os, r);
  report::write_wheelrail_input_blocks(os, r, s.material);
  const RailDeflection& rd = s.rail_deflection;
  if (rd.active) {  // F = 3, in every case (outputs.md §3.8), also those that keep the track
    line(os, "");
    line(os, " MASSLESS RAIL DEFLECTION");
    line(os, "     KY_RAIL     DY_DEFL     FY_RAIL     KZ_RAIL     DZ_DEFL     FZ_RAIL");
    line(os, "  " + f4(rd.ky_N_per_mm) + f4(rd.dy_mm) + sig(rd.fy_N) + f4(rd.kz_N_per_mm) +
                 f4(rd.dz_mm) + sig(rd.fz_N));
  }
  line(os, "");
  line(os, " WHEEL-SET POSITION AND VELOCITY");
  // A roller rig: the wheelset's position X_WS and the roller's angular velocity RPITCH.
  line(os, std::string("     ") + (r.is_roller() ? "X_WS" : "S_WS") +
               "        Y_WS        Z_WS        ROLL_WS     YAW_WS      PITCH_WS");
  const WheelsetMotion& m = r.motion;
  line(os, "  " + sig(m.s) + sig(m.y) + f4(s.z_ws_mm) + sig(m.roll) + sig(m.yaw) + sig(m.pitch));
  line(os, "");
  line(os, std::string("     ") + (r.is_roller() ? "RPITCH " : "VX_WS  ") +
               "     VY_WS       VZ_WS       VROLL_WS    VYAW_WS     VPITCH_WS");
  line(os, "  " + sig(r.is_roller() ? m.rpitch : m.vs) + sig(m.vy) + sig(m.vz) + sig(m.vroll) +
               sig(m.vyaw) + fmt_sig(12, 8, 8, s.vpitch_rad_s));  // solved for F=1
  write_wheel_deviations(os, r.wheel_deviations);
  line(os, "");
}

void write_totals(std::ostream& os, const WheelRailRecord& r, const WheelRailSolution& s) {
  line(os, "");
  // O ≥ 4 adds the moments about the rail profile's marker (track coordinates) and about the
  // wheel profile's marker (wheelset coordinates), as cntc_getglobalforces returns them.
  const bool moments = r.digits.o >= 4;
  line(os, fmt::format(" TOTAL FORCES {}ON {}", moments ? "AND MOMENTS " : "",
                       r.is_roller() ? "ROLLER" : "RAIL"));
  line(os, "     FX(TR)      FY(TR)      FZ(TR)      FX(WS)      FY(WS)      FZ(WS)");
  line(os, sig(s.force_tr.x) + sig(s.force_tr.y) + sig(s.force_tr.z) + sig(s.force_ws.x) +
               sig(s.force_ws.y) + sig(s.force_ws.z));
  if (!moments) return;
  line(os, "");
  line(os, "    MX@R(TR)    MY@R(TR)    MZ@R(TR)    MX@W(WS)    MY@W(WS)    MZ@W(WS)");
  line(os, sig(s.moment_tr.x) + sig(s.moment_tr.y) + sig(s.moment_tr.z) + sig(s.moment_ws.x) +
               sig(s.moment_ws.y) + sig(s.moment_ws.z));
}

/// The planar patch's force block (FN FX FS MN …, FN/G FX/FSTAT/FN …).
void write_planar_forces(std::ostream& os, const WheelRailRecord& r, const WheelRailPatch& w,
                         double mu);

void write_patch(std::ostream& os, const WheelRailRecord& r, const CaseRecord& identity,
                 const WheelRailPatch& w, int k) {
  const ControlDigits& d = r.digits;
  line(os, "");
  line(os, fmt::format(" ----- DATA FOR CONTACT PATCH {:2d} -----", k));
  if (d.o >= 2) {
    line(os, "");
    line(os, " CONTACT REFERENCE LOCATION");
    line(os, "     XCP(TR)     YCP(TR)     ZCP(TR)    DELTCP(TR)   YCP(R)      ZCP(R)");
    line(os, f4(w.reference_tr.x) + f4(w.reference_tr.y) + f4(w.reference_tr.z) +
                 f4(w.contact_angle_rad) + f4(w.y_rail_mm) + f4(w.z_rail_mm));
    line(os, "");
    line(os, "     XCP(W)      YCP(W)      ZCP(W)");
    line(os, f4(w.reference_wheel.x) + f4(w.reference_wheel.y) + f4(w.reference_wheel.z));
    if (w.conformal.active) report::write_conformal_diagnostics(os, w);
    if (!w.conformal.row_friction.empty()) {
      report::write_row_friction(os, w.conformal);
    } else if (r.variable_friction.v != 0) {  // the patch's own coefficients (V=1, 2)
      line(os, "");
      line(os, " FRICTION LAW PARAMETERS");
      line(os, "     FSTAT       FKIN");
      line(os, "  " + g12(w.friction.static_coefficient) + g12(w.friction.kinetic_coefficient));
    }
    report::write_patch_simplified(os, r, w.solution);
    line(os, "");
    line(os, " KINEMATIC CONSTANTS");
    line(os, "     CHI         DQ          VELOC       CKSI        CETA        CPHI");
    line(os, "  " + g12(w.chi_rad) + g12(w.dq_mm) + sig(w.veloc_mm_s) + sig(w.xi) + sig(w.eta) +
                 sig(w.phi_per_mm));
  }
  // V=1,2: the relative forces are scaled by the patch's own coefficient, as CONTACT does.
  const double mu =
      r.variable_friction.v != 0 ? w.friction.static_coefficient : static_friction(r.friction);
  if (w.conformal.active) {
    // V=1 prints relative forces unscaled (wheelrail-advanced.md §3.3); otherwise by the
    // patch's coefficient, as the planar block.
    const double mu_c = r.variable_friction.v == 1 ? 1.0 : w.friction.static_coefficient;
    report::write_conformal_forces(os, w, mu_c, r.solver.eps, d.h >= 1);
  } else {
    write_planar_forces(os, r, w, mu);
  }
  if (d.o >= 2) report::write_statistics(os, identity, w.solution, false);
  if (d.o >= 3) {
    line(os, "");
    line(os, " FORM OF THE CONTACT, ADHESION AND SLIP-AREA`S:");
    write_element_division(os, w.solution, d.t, w.chi_rad);
    if (w.conformal.active) report::write_curved_reference(os, w.conformal);
  }
  if (d.o >= 5) {
    // The patch's quantities per element, as module 3's table: its approach, its coefficient
    // of friction and the rigid slip its tangential problem posed.
    report::ElementTableInputs in;
    in.t = d.t;
    in.h = d.h;
    in.o = d.o;
    in.pen = w.solution.totals.pen;
    in.mu = w.friction.static_coefficient;
    in.friction_law = r.friction.law;
    in.wx = w.solution.wx;
    in.wy = w.solution.wy;
    report::write_element_table(os, in, w.solution);
  }
  // S ≥ 1: the subsurface stress summaries of the patch, in its own coordinates.
  if (d.s >= 1) {
    CaseRecord with_points = identity;
    with_points.subsurface = r.subsurface;
    report::write_subsurface_summaries(os, with_points, w.solution);
  }
}

void write_planar_forces(std::ostream& os, const WheelRailRecord& r, const WheelRailPatch& w,
                         double mu) {
  const ControlDigits& d = r.digits;
  const Totals& t = w.solution.totals;
  const double noise = 0.5 * r.solver.eps * t.fn * mu;
  line(os, "");
  line(os, " TOTAL FORCES, TORSIONAL MOMENT, ELASTIC ENERGY, FRICTIONAL POWER");
  line(os, "     FN          FX          FS          MN         ELAST.EN.   FRIC.POWER");
  line(os, "  " + sig(t.fn) + sig(filter_small(t.fx, noise)) + sig(filter_small(t.fy, noise)) +
               sig(filter_small(t.mz, noise)) + sig(t.elastic_energy) + sig(t.frictional_power));
  const double scale = t.fn * mu;
  // H ≥ 1: the patch's highest surface temperature, as module 3 prints it.
  line(os, std::string("     FN/G      FX/FSTAT/FN FS/FSTAT/FN   APPROACH     PMAX    ") +
               (d.h >= 1 ? "  MAX(T1,T2)" : ""));
  const double g = w.solution.material.g;
  line(os, "  " + sig(g != 0 ? t.fn / g : 0.0) +
               sig(filter_small(scale != 0 ? t.fx / scale : 0.0, 0.5 * r.solver.eps)) +
               sig(filter_small(scale != 0 ? t.fy / scale : 0.0, 0.5 * r.solver.eps)) +
               fmt_sig(12, 6, 4, t.pen) + sig(t.pmax) +
               (d.h >= 1 ? sig(std::max(t.max_temp1, t.max_temp2)) : ""));
}

}  // namespace

void write_wheelrail_case_report(std::ostream& os, const WheelRailRecord& record,
                                 const CaseRecord& identity, const WheelRailSolution& solution) {
  write_case_header(os, identity);
  report::write_profile_reading(os, record);
  write_trace(os, solution);
  for (const std::string& w : solution.warnings) line(os, " WARNING: " + w);
  if (!solution.converged)
    line(os, " WARNING: the solver did not converge: " +
                 (solution.message.empty() ? std::string("(no details)") : solution.message));
  const ControlDigits& d = record.digits;
  if (d.r >= 2 || d.o <= 0) return;
  if (d.o >= 2) write_problem_echo(os, record, solution);
  write_totals(os, record, solution);
  int k = 0;
  for (const WheelRailPatch& w : solution.patches) write_patch(os, record, identity, w, ++k);
  if (solution.patches.empty()) {
    line(os, "");
    line(os, " ----- NO CONTACT FOUND -----");
  }
}

}  // namespace rollcontact::format
