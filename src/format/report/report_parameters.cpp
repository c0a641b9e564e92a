// Module-3 parameter blocks of the report (spec/outputs.md §3.2): digit echo, problem
// description, Hertz data, material, friction and kinematic constants. Texts and column layout
// follow CONTACT's reports so that existing scripts keep parsing them.

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <numbers>
#include <ostream>
#include <string>

#include "format/report/number_format.hpp"
#include "format/report/report_internal.hpp"
#include "format/report/report_values.hpp"

namespace rollcontact::format::report {
namespace {

std::string i2(int v) {
  return fortran_i(v, 2);
}

void write_digit_echo(std::ostream& os, const ControlDigits& d) {
  line(os, " ");
  line(os, fmt::format(
               "  PBTNFS.            PVTIME{}, BOUND {}, TANG  {}, NORM  {}, FORCE {}, STRESS{}",
               i2(d.p), i2(d.b), i2(d.t), i2(d.n), i2(d.f), i2(d.s)));
  if (d.v == 0) {
    line(os, fmt::format(
                 "  LDCMZE.            FRCLAW{}, DISCNS{}, INFLCF{}, MATER {}, RZNORM{}, RZTANG{}",
                 i2(d.l), i2(d.d), i2(d.c), i2(d.m), i2(d.z), i2(d.e)));
  } else {
    line(os, fmt::format(
                 " VLDCMZE.  VARFRC{}, FRCLAW{}, DISCNS{}, INFLCF{}, MATER {}, RZNORM{}, RZTANG{}",
                 i2(d.v), i2(d.l), i2(d.d), i2(d.c), i2(d.m), i2(d.z), i2(d.e)));
  }
  line(os, fmt::format(
               " HGIAOWR.  HEAT  {}, GAUSEI{}, IESTIM{}, MATFIL{}, OUTPUT{}, FLOW  {}, RETURN{}",
               i2(d.h), i2(d.g), i2(d.i), i2(d.a), i2(d.o), i2(d.w), i2(d.r)));
}

void write_problem_description(std::ostream& os, const CaseRecord& problem) {
  const auto& d = problem.digits;
  const char* given = d.n == 0 ? "APPROACH" : "NORMAL FORCE";
  const char* method = d.b == 0   ? "FULL"
                       : d.b == 5 ? "APPROXIMATE KPEC"
                       : d.b == 6 ? "APPROXIMATE ANALYN"
                                  : nullptr;
  if (method != nullptr)
    line(os, fmt::format(" NORMAL PROBLEM WITH PRESCRIBED {}, {} SOLUTION", given, method));
  if (d.b >= 2 && d.b <= 4) {
    const char* bound = d.b == 2 ? "ELLIPTICAL" : d.b == 3 ? "PARABOLICAL" : "SDEC";
    line(os, fmt::format(" NORMAL PROBLEM SKIPPED, {} TRACTION BOUND", bound));
  }
  if (d.t == 0) return;
  if (d.m == 2 || d.m == 3) {
    line(os, " STEADY STATE ROLLING,  \"FASTSIM APPROACH\"");
  } else if (d.m == 5) {
    line(os, " STEADY STATE ROLLING,  \"FASTRIP APPROACH\"");
  } else {
    line(os, d.t == 1   ? " SHIFT TRANSIENT"
             : d.t == 2 ? " TRANSIENT ROLLING"
                        : " STEADY STATE ROLLING");
  }
  line(os, d.f == 0   ? " CREEPAGE PRESCRIBED"
           : d.f == 1 ? " X-FORCE,  Y-CREEPAGE PRESCRIBED"
                      : " TANGENTIAL FORCE PRESCRIBED");
  line(os, frictional_stress_method(problem.solver.maxout));
  if (problem.materials.influence_type == 4)
    line(os, inclination_correction_method(problem.materials.conformal));
}

// Hertz data of Hertzian potential contacts; labels pad to column 43 so values start at 44.
void write_hertz_block(std::ostream& os, const CaseRecord& problem, const Solution& solution) {
  const int ipotcn = problem.potential.ipotcn;
  const auto& hz = solution.hertz;
  const auto& grid = solution.grid;
  const double aob = hz.bb != 0.0 ? hz.aa / hz.bb : 0.0;
  const std::string pad13(13, ' ');
  const char* kind = ipotcn <= -6 ? "SDEC" : ipotcn <= -4 ? "2D HERTZIAN" : "3D HERTZIAN";
  line(os, "");
  line(os, fmt::format(" {} GEOMETRY WITH PRESCRIBED {}", kind,
                       problem.digits.n == 0 ? "APPROACH" : "NORMAL FORCE"));
  switch (ipotcn) {
    case -1:
      line(os, " CURVATURE PRESCRIBED, A1,B1: " + pad13 + g12(hz.a1) + g12(hz.b1));
      break;
    case -2:
      line(os, " CURVATURE AND ELLIPTIC. PRESCRB, A1,AA/BB:" + g12(hz.a1) + g12(aob));
      break;
    case -4:
      line(os, " CURVATURE PRESCRIBED, A1,BB: " + pad13 + g12(hz.a1) + g12(hz.bb));
      break;
    case -6:
      line(os, " SEMIAXES PRESCRIBED, AA,BNEG,BPOS:" + std::string(8, ' ') + g12(hz.aa) +
                   g12(problem.potential.values[1]) + g12(problem.potential.values[2]));
      break;
    default:  // -3, -5
      line(os, " SEMIAXES PRESCRIBED, AA,BB:  " + pad13 + g12(hz.aa) + g12(hz.bb));
      break;
  }
  if (ipotcn != -1 && ipotcn != -6)
    line(os, " THE CURVATURES A1,B1 ARE:    " + pad13 + g12(hz.a1) + g12(hz.b1));
  if (ipotcn != -3 && ipotcn != -6)
    line(os, " BASIC SEMIAXES AA,BB, RATIO  " + pad13 + g12(hz.aa) + g12(hz.bb) + g12(aob));
  if (ipotcn != -6)
    line(os, " EFFECTIVE RAD.CURV RHO, SEMI-AXIS CP      " + g12(hz.rho) + g12(hz.cp));
  line(os, " POTENTIAL CONTACT, SCALE:    " + pad13 + g12(grid.xl) + g12(grid.yl) + g12(hz.scale));
  line(os, " DISCRETISATION MX,MY, DX,DY: " + pad13 + fortran_i(grid.mx, 6) +
               fortran_i(grid.my, 6) + g12(grid.dx) + g12(grid.dy));
}

void write_material_block(std::ostream& os, const CaseRecord& problem, const Solution& solution) {
  const auto& d = problem.digits;
  const auto& m = problem.materials;
  const auto& mp = m.model_params;
  const auto& cm = solution.material;
  line(os, "");
  line(os, " MATERIAL CONSTANTS");
  line(os, "     NU          G           AK          EPS");
  line(os, "  " + g12(cm.nu) + g12(cm.g) + g12(cm.k) + g12(problem.solver.eps));
  line(os, "");
  line(os, "    POISS(1)    POISS(2)     GG(1)       GG(2)");
  line(os, "  " + g12(m.poiss1) + g12(m.poiss2) + g12(m.gg1) + g12(m.gg2));
  // Not printed for lack of data in CaseRecord: damping (M2=2).
  if (d.h >= 1) {
    const HeatParameters& h = problem.heat;
    line(os, "");
    line(os, "     BKTEMP      HEATCP      LAMBDA      DENSITY");
    line(os, "  " + g12(h.bktemp1) + g12(h.heatcp1) + g12(h.lambda1) + g12(h.dens1));
    line(os, "  " + g12(h.bktemp2) + g12(h.heatcp2) + g12(h.lambda2) + g12(h.dens2));
  }
  if (d.m == 1) {
    // The solver's effective constants (zero when the case was not solved).
    const CombinedMaterial& rv = solution.viscoelastic_effective;
    const double veloc = effective_kinematics(solution).veloc;
    line(os, "");
    line(os, " VISCOELASTIC MATERIAL CONSTANTS");
    line(os, "     NUV         GV          AKV");
    line(os, "  " + g12(rv.nu) + g12(rv.g) + g12(rv.k));
    line(os, "");
    line(os, "     FG(1)       FG(2)       TC(1)       TC(2)       VT(1)       VT(2)");
    line(os, "  " + g12(mp[0]) + g12(mp[1]) + sig(mp[2]) + sig(mp[3]) + sig(mp[2] * veloc) +
                 sig(mp[3] * veloc));
  }
  const SimplifiedReport& simp = solution.simplified;
  if (d.m == 2) {
    line(os, "");
    line(os, " SIMPLIFIED THEORY MATERIAL CONSTANTS");
    line(os, "     FLX");
    line(os, "  " + g12(simp.present ? simp.flx1 : mp[0]));
  }
  if (d.m == 3 || d.m == 5) {
    // Effective flexibilities (after blending) from the Fastsim set-up; 0 when not solved.
    line(os, "");
    line(os, " SIMPLIFIED THEORY MATERIAL CONSTANTS");
    line(os, "     FLX1        FLX2        FLX3");
    line(os, "  " + g12(simp.flx1) + g12(simp.flx2) + g12(simp.flx3));
  }
  if (d.m == 2 || d.m == 3 || d.m == 5) {
    const std::size_t first = d.m == 2 ? 1 : 0;
    const double k0 = mp[first], alfa = mp[first + 1], beta = mp[first + 2];
    // k = k0 (alfa + (1 - alfa)/(1 + beta eps)) equals k0 for alfa = 1 whatever eps is.
    const double k_eff = simp.present ? simp.k_eff : alfa == 1.0 ? k0 : 0.0;
    line(os, "");
    line(os,
         fmt::format(" MODIFIED {} SLOPE REDUCTION PARAMETERS", d.m == 5 ? "FASTRIP" : "FASTSIM"));
    line(os, "     K0_MF       ALFAMF      BETAMF      K_EFF");
    line(os, "  " + g12(k0) + g12(alfa) + g12(beta) + g12(k_eff));
  }
  if (d.m == 4) {
    line(os, "");
    line(os, " INTERFACIAL LAYER PARAMETERS");
    line(os, "     GG3         LAYTHK      TAU_C0      K_TAU");
    line(os, "  " + g12(mp[0]) + g12(mp[1]) + g12(mp[2]) + g12(mp[3]));
  }
}

}  // namespace

std::string inclination_correction_method(const Materials::Conformal& c) {
  return fmt::format(" USING CONFORMAL IF-CORRECTION: BLANCO(v{}), {} CURVATURE", c.variant,
                     c.if_meth == 1 ? "VARYING" : "CONSTANT");
}

std::string frictional_stress_method(int maxout) {
  if (maxout <= 1) return " JOHNSON\"S METHOD IS USED FOR THE FRICTIONAL STRESS";
  return fmt::format(" PANAGIOTOPOULOS\" METHOD IS USED FOR THE FRICTIONAL STRESS. MAXOUT={}",
                     fortran_i(maxout, 3));
}

// Header of the law's parameter columns; `prefix` holds the IY column for per-row friction.
std::string friction_header(int law, const std::string& prefix) {
  switch (law) {
    case 2:
    case 3:
    case 4: {
      const char* n1 = law == 2 ? "FLIN1" : law == 3 ? "FRAT1" : "FEXP1";
      const char* n2 = law == 2 ? "FLIN2" : law == 3 ? "FRAT2" : "FEXP2";
      return prefix + fmt::format("   FKIN        {}       SABSH1      {}       SABSH2", n1, n2);
    }
    case 6:
      return prefix + "   FREF        TREF        DFHEAT      DTHEAT";
    default:
      return prefix + "   FSTAT       FKIN";
  }
}

std::string friction_values(int law, double fstat, double fkin, const std::array<double, 4>& p) {
  switch (law) {
    case 2:
    case 3:
    case 4:
      return g12(fkin) + g12(p[0]) + g12(p[1]) + g12(p[2]) + g12(p[3]);
    case 6:  // FREF is stored in fkin, TREF DFHEAT DTHEAT in params
      return g12(fkin) + g12(p[0]) + g12(p[1]) + g12(p[2]);
    default:
      return g12(fstat) + g12(fkin);
  }
}

void write_friction_block(std::ostream& os, const Friction& fr, int output_digit) {
  line(os, "");
  line(os, " FRICTION LAW PARAMETERS");
  if (fr.rows.empty()) {
    line(os, friction_header(fr.law, "  "));
    line(os, "  " + friction_values(fr.law, fr.fstat, fr.fkin, fr.params));
    return;
  }
  // V=3: one row per grid row; below O=4 only the first and last two, the rest as "...".
  line(os, friction_header(fr.law, "      IY      "));
  const int nvf = static_cast<int>(fr.rows.size());
  for (int ivf = 1; ivf <= nvf; ++ivf) {
    const auto& r = fr.rows[static_cast<std::size_t>(ivf - 1)];
    if (output_digit >= 4 || ivf <= 2 || ivf >= nvf - 1) {
      line(os,
           "  " + fortran_i(ivf, 8) + "    " + friction_values(fr.law, r.fstat, r.fkin, r.params));
    } else if (ivf == 3) {
      line(os, std::string(22, ' ') + "...");
    }
  }
}

namespace {

void write_kinematics_block(std::ostream& os, const CaseRecord& problem, const Solution& solution) {
  const auto& d = problem.digits;
  const auto& kin = problem.kinematics;
  const EffectiveKinematics ek = effective_kinematics(solution);
  const std::string veloc = sig(ek.veloc), cksi = sig(kin.cksi), ceta = sig(kin.ceta),
                    cphi = sig(kin.cphi);
  const std::string fxrel = sig(kin.fx_rel), fyrel = sig(kin.fy_rel);
  std::string values = d.f == 0   ? cksi + ceta + cphi
                       : d.f == 1 ? fxrel + ceta + cphi
                                  : fxrel + fyrel + cphi;
  const char* tail = d.f == 0   ? "   CKSI        CETA        CPHI"
                     : d.f == 1 ? " FX/FSTAT/FN   CETA        CPHI"
                                : " FX/FSTAT/FN FY/FSTAT/FN   CPHI";
  line(os, "");
  line(os, " KINEMATIC CONSTANTS");
  if (d.t <= 1) {
    line(os, fmt::format("     DT          VELOC    {}", tail));
    line(os, "  " + fortran_f(ek.dt, 8, 3) + "    " + veloc + values);
  } else {
    line(os, fmt::format("     CHI         DQ          VELOC    {}", tail));
    line(os, "  " + g12(ek.chi) + g12(ek.dq) + veloc + values);
  }
  line(os, "");
  if (std::max(std::fabs(kin.spinxo), std::fabs(kin.spinyo)) >= 1e-20) {
    line(os, "     SPINXO      SPINYO");
    line(os, "  " + g12(kin.spinxo) + g12(kin.spinyo));
    line(os, "");
  }
}

}  // namespace

void write_parameter_blocks(std::ostream& os, const CaseRecord& problem, const Solution& solution) {
  const auto& d = problem.digits;
  write_digit_echo(os, d);
  write_problem_description(os, problem);
  if (d.z >= 1 && problem.potential.hertzian()) write_hertz_block(os, problem, solution);
  if (d.c >= 2) write_material_block(os, problem, solution);
  if (d.l != 1) write_friction_block(os, problem.friction, d.o);
  write_kinematics_block(os, problem, solution);
}

}  // namespace rollcontact::format::report
