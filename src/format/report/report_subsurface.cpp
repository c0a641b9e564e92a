#include "format/report/report_subsurface.hpp"

#include <fmt/format.h>

#include <ostream>
#include <string>
#include <string_view>

#include "format/report/number_format.hpp"
#include "format/report/report_internal.hpp"

namespace rollcontact::format::report {

namespace {

/// ` ABSMAX SIGHYD =    -0.853 AT (X,Y,Z) = (   0.000,   0.000,   0.000)`: the word left in
/// six columns, the quantity right-aligned in seven, f10.3, coordinates f8.3.
std::string extreme_line(std::string_view word, std::string_view name, const SubsurfaceExtreme& e) {
  return fmt::format(" {:<6}{:>7} ={} AT (X,Y,Z) = ({},{},{})", word, name,
                     fortran_f(e.value, 10, 3), fortran_f(e.x, 8, 3), fortran_f(e.y, 8, 3),
                     fortran_f(e.z, 8, 3));
}

/// OUTPUT_S = 4: one paragraph per point, as CONTACT prints it (Ew.4 numbers).
void write_points(std::ostream& os, const SubsurfaceResult& r) {
  const std::size_t nx = r.x.size(), ny = r.y.size();
  line(os, " ");
  for (std::size_t k = 0; k < r.size(); ++k) {
    line(os, " Position (X,Y,Z):" + fortran_g(r.x[k % nx], 12, 4) +
                 fortran_g(r.y[(k / nx) % ny], 12, 4) + fortran_g(r.z[k / (nx * ny)], 12, 4));
    line(os, " I,Displacement(I); Stress(I,J),J = 1,3");
    const double u[3] = {r.ux[k], r.uy[k], r.uz[k]};
    const double s[3][3] = {{r.sxx[k], r.sxy[k], r.sxz[k]},
                            {r.sxy[k], r.syy[k], r.syz[k]},
                            {r.sxz[k], r.syz[k], r.szz[k]}};
    for (int i = 0; i < 3; ++i) {
      line(os, fortran_i(i + 1, 3) + fortran_e(u[i], 14, 4) + "; " + fortran_e(s[i][0], 12, 4) +
                   fortran_e(s[i][1], 12, 4) + fortran_e(s[i][2], 12, 4));
    }
    line(os,
         "  SigHyd =" + fortran_e(r.sighyd[k], 13, 4) + ", SigVM =" + fortran_e(r.sigvm[k], 13, 4));
    line(os, "");
  }
}

}  // namespace

void write_subsurface_summaries(std::ostream& os, const CaseRecord& problem,
                                const Solution& solution) {
  if (problem.digits.s < 1 || problem.subsurface.output < 1) return;
  for (std::size_t b = 0; b < solution.subsurface.size(); ++b) {
    const SubsurfaceResult& r = solution.subsurface[b];
    if (r.size() == 0) continue;
    line(os, "");
    line(os, " SUBSURFACE STRESSES BLOCK" + fortran_i(static_cast<long long>(b + 1), 3) + ":");
    line(os, " ");
    line(os, extreme_line("ABSMAX", "SIGHYD", r.absmax_sighyd));
    line(os, extreme_line("MAX", "SIGVM", r.max_sigvm));
    line(os, extreme_line("MAX", "SIGTR", r.max_sigtr));
    line(os, extreme_line("MAX", "SIGMA1", r.max_sig1));
    line(os, extreme_line("MIN", "SIGMA3", r.min_sig3));
    line(os, extreme_line("ABSMAX", "SIGXX", r.absmax_sxx));
    line(os, extreme_line("ABSMAX", "SIGYY", r.absmax_syy));
    line(os, extreme_line("ABSMAX", "SIGZZ", r.absmax_szz));
    if (problem.subsurface.output >= 4) write_points(os, r);
  }
}

}  // namespace rollcontact::format::report
