// Force block, sensitivities and contact statistics of the report (spec/outputs.md §3.3–3.4).

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <ostream>
#include <string>

#include "format/report/number_format.hpp"
#include "format/report/report_internal.hpp"
#include "format/report/report_values.hpp"

namespace rollcontact::format::report {

void write_force_block(std::ostream& os, const CaseRecord& problem, const Solution& solution) {
  const auto& d = problem.digits;
  const auto& t = solution.totals;
  const double eps = problem.solver.eps;
  const double mu = static_friction(problem.friction);
  const bool rolling = d.t == 2 || d.t == 3;
  // Values dominated by round-off print as 0 (CONTACT's filt_sml); the threshold scales with
  // the largest tangential force possible, mu FN.
  const double force_noise = 0.5 * eps * t.fn * mu;

  if (d.o >= 2) {
    line(os, " TOTAL FORCES, TORSIONAL MOMENT, ELASTIC ENERGY, FRICTIONAL POWER");
  } else {
    line(os, "");
  }
  line(os, std::string("     FN          FX          FY          MZ         ELAST.EN.   FRIC.") +
               (rolling ? "POWER" : "WORK"));
  line(os, "  " + sig(t.fn) + sig(filter_small(t.fx, force_noise)) +
               sig(filter_small(t.fy, force_noise)) +
               sig(filter_small(t.mz, std::fabs(force_noise))) + sig(t.elastic_energy) +
               sig(t.frictional_power));

  const double scale = t.fn * mu;
  const double fx_rel = scale != 0.0 ? t.fx / scale : 0.0;
  const double fy_rel = scale != 0.0 ? t.fy / scale : 0.0;
  const EffectiveCreepages c = printed_creepages(problem, solution);
  std::string xlabel, ylabel, xvalue, yvalue;
  if (d.f == 0) {
    xlabel = "FX/FSTAT/FN";
    xvalue = sig(filter_small(fx_rel, 0.5 * eps));
  } else {
    xlabel = rolling ? " CREEP X" : " SHIFT X";
    xvalue = sig(c.x);
  }
  if (d.f <= 1) {
    ylabel = "FY/FSTAT/FN";
    yvalue = sig(filter_small(fy_rel, 0.5 * eps));
  } else {
    ylabel = rolling ? " CREEP Y" : " SHIFT Y";
    yvalue = sig(c.y);
  }
  const double fn_over_g = solution.material.g != 0.0 ? t.fn / solution.material.g : 0.0;
  std::string labels =
      "     FN/G      " + a12(xlabel) + " " + a12(ylabel) + " APPROACH" + " " + "    PMAX    ";
  std::string values = "  " + sig(fn_over_g) + xvalue + yvalue +
                       fmt_sig(12, 6, 4, effective_approach(problem, solution)) + sig(t.pmax);
  if (d.h >= 1) {
    labels += "  MAX(T1,T2)";
    values += sig(std::max(t.max_temp1, t.max_temp2));
  }
  line(os, labels);
  line(os, values);
}

void write_sensitivities(std::ostream& os, const CaseRecord& problem, const Solution& solution) {
  // Only the force iteration (F=1,2) computes derivatives; CONTACT prints 0 for "not calculated".
  const std::string zero = fmt_sig(12, 3, 3, 0.0);
  const Sensitivities& d = solution.sensitivities;
  auto value = [](double v) { return fmt_sig(12, 3, 3, v); };
  line(os, "");
  if (problem.digits.t != 0) {
    line(os, " THE SENSITIVITIES. (FX,FY) MEANS: (FX,FY)/FN/FSTAT.");
    line(os, " A ZERO ENTRY MEANS THAT IT HAS NOT BEEN CALCULATED.");
    line(os, "         DF/DPEN     DF/DKSI     DF/DETA     DF/DPHI");
    line(os, fmt::format("   FN {}{}{}{}", zero, zero, zero, zero));
    line(os, fmt::format("   FX {}{}{}{}", zero, value(d.dfx_dksi), value(d.dfx_deta), zero));
    line(os, fmt::format("   FY {}{}{}{}", zero, value(d.dfy_dksi), value(d.dfy_deta), zero));
  } else {
    line(os, " THE SENSITIVITIES.");
    line(os, " A ZERO MEANS THAT IT HAS NOT BEEN CALCULATED.");
    line(os, "  DFN/DPEN");
    line(os, zero);
  }
}

void write_statistics(std::ostream& os, const CaseRecord& problem, const Solution& solution,
                      bool leading_blank) {
  const auto& s = solution.statistics;
  const bool plast = uses_plasticity(problem);
  line(os, "");
  line(os, " CONTACT STATISTICS");
  line(os, " N: NUMBER OF ELEMENTS IN REGION,  I: NUMBER OF ITERATIONS,");
  line(os, " POT: POTENTIAL CONTACT AREA,  CON: CONTACT,  ADH: ADHESION");
  line(os,
       std::string("    NPOT   NCON   NADH  NSLIP") + (plast ? "  NPLAST" : " ") + " INORM  ITANG");
  std::string v = std::string(leading_blank ? " " : "") + fortran_i(s.npot, 7) +
                  fortran_i(s.ncon, 7) + fortran_i(s.nadh, 7) + fortran_i(s.nslip, 7);
  if (plast) v += fortran_i(s.nplast, 7);
  v += fortran_i(s.inorm, 7) + fortran_i(s.itang, 7);
  line(os, v);
}

}  // namespace rollcontact::format::report
