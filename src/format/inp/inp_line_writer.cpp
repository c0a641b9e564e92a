// The .inp lines both modules share: see the header.

#include "format/inp/inp_line_writer.hpp"

#include <fmt/format.h>

#include <cmath>

#include "rollcontact/errors.hpp"

namespace rollcontact::format {

std::string inp_real(double v) {
  if (!std::isfinite(v))
    throw Error(fmt::format("cannot write the non-finite value {} to .inp", v));
  std::string s = fmt::format("{}", v);
  if (s.find_first_of(".e") == std::string::npos) s += ".";
  return s;
}

void InpLineWriter::group(const std::string& values, std::string_view names) {
  out_ += fmt::format("  {:<40} % {}\n", values, names);
}

void InpLineWriter::array(std::span<const double> v, std::string_view names) {
  out_ += fmt::format("  % {}\n", names);
  for (std::size_t k = 0; k < v.size(); ++k) {
    out_ += (k % 6 == 0 ? "  " : " ") + inp_real(v[k]);
    if (k % 6 == 5 || k + 1 == v.size()) out_ += "\n";
  }
}

void InpLineWriter::int_array(std::span<const int> v) {
  for (std::size_t k = 0; k < v.size(); ++k) {
    out_ += fmt::format("{}{}", k % 10 == 0 ? "  " : " ", v[k]);
    if (k % 10 == 9 || k + 1 == v.size()) out_ += "\n";
  }
}

std::string InpLineWriter::reals(std::initializer_list<double> v) {
  std::string s;
  for (double x : v) s += (s.empty() ? "" : " ") + inp_real(x);
  return s;
}

void InpLineWriter::control_word3_and_debug(const ControlDigits& d, int solver_method) {
  const int h = d.h >= 1 ? 3 : 0;
  const int r = d.r == 2 || d.r == 3 ? 3 : 1;
  const int w3 = d.x * 10000000 + h * 1000000 + solver_method * 100000 + d.i * 10000 + d.a * 1000 +
                 d.o * 100 + d.w * 10 + r;
  group(fmt::format("{:0{}d}", w3, d.x ? 8 : 7), d.x ? "X-H-G-I-A-O-W-R" : "H-G-I-A-O-W-R");
  if (d.x == 1) {
    const DebugDigits& g = d.debug;
    const int w4 =
        g.p * 1000000 + g.s * 100000 + g.f * 10000 + g.l * 1000 + g.c * 100 + g.i * 10 + g.n;
    group(fmt::format("{:07d} {}", w4, g.readln), "P-S-F-L-C-I-N  READLN");
  }
}

void InpLineWriter::solver_lines(const SolverSettings& s, int npot_max) {
  if (npot_max > 0) {
    group(fmt::format("{} {} {} {} {} {}", s.maxgs, s.maxin, s.maxnr, s.maxout, inp_real(s.eps),
                      npot_max),
          "MAXGS MAXIN MAXNR MAXOUT EPS NPOT_MAX");
  } else {
    group(fmt::format("{} {} {} {} {}", s.maxgs, s.maxin, s.maxnr, s.maxout, inp_real(s.eps)),
          "MAXGS MAXIN MAXNR MAXOUT EPS");
  }
  if (s.method == 2 || s.method == 3) {
    group(fmt::format("{} {} {} {}", inp_real(s.omega_h), inp_real(s.omega_s), s.inislp,
                      inp_real(s.omgslp)),
          "OMEGAH OMEGAS INISLP OMGSLP");
  } else if (s.method == 4) {
    group(fmt::format("{} {}", s.inislp, inp_real(s.omgslp)), "INISLP OMGSLP");
  } else if (s.method == 5) {
    const auto& g = s.gd;
    group(fmt::format("{} {} {} {} {} {} {} {}", inp_real(g.fdecay), inp_real(g.betath), g.kdowfb,
                      inp_real(g.d_ifc), inp_real(g.d_lin), inp_real(g.d_cns), inp_real(g.d_slp),
                      inp_real(g.pow_s)),
          "FDECAY BETATH KDOWFB D_IFC D_LIN D_CNS D_SLP POW_S");
  }
}

void InpLineWriter::friction_values(int law, const FrictionValues& v, std::string_view prefix_name,
                                    double prefix) {
  const auto& q = v.params;
  std::string values, names;
  switch (law) {
    case 0:
      values = reals({v.fstat, v.fkin});
      names = "FSTAT FKIN";
      break;
    case 2:
    case 3:
    case 4: {
      values = reals({v.fkin, q[0], q[1], q[2], q[3]});
      const char* f = law == 2 ? "FLIN" : law == 3 ? "FRAT" : "FEXP";
      names = fmt::format("FKIN {0}1 SABSH1 {0}2 SABSH2", f);
      break;
    }
    case 6:
      values = reals({v.fkin, q[0], q[1], q[2]});
      names = "FREF TREF DFHEAT DTHEAT";
      break;
    default:
      throw Error(
          fmt::format("case {}: friction law L={} cannot be written to .inp", case_number_, law));
  }
  if (prefix_name.empty()) {
    group(values, names);
  } else {
    group(inp_real(prefix) + " " + values, fmt::format("{} {}", prefix_name, names));
  }
}

void InpLineWriter::friction_memory(const Friction& f) {
  if (f.law == 2 || f.law == 3 || f.law == 4 || f.law == 6)
    group(reals({f.memdst, f.mem_s0}), "MEMDST MEM_S0");
}

void InpLineWriter::material_lines(const Materials& m, int b, int material_model) {
  const auto& q = m.model_params;
  group(reals({m.poiss1, m.poiss2, m.gg1, m.gg2}), "POISS1 POISS2 GG1 GG2");
  if (b == 1) group(inp_real(m.flxz), "FLXZ");
  switch (material_model) {
    case 1:
      group(reals({q[0], q[1], q[2], q[3]}), "FG1 FG2 TC1 TC2");
      break;
    case 2:
      group(reals({q[0], q[1], q[2], q[3]}), "FLX K0_MF ALFAMF BETAMF");
      break;
    case 3:
    case 5:
      group(reals({q[0], q[1], q[2]}), "K0_MF ALFAMF BETAMF");
      break;
    case 4:
      group(reals({q[0], q[1], q[2], q[3]}), "GG3 LAYTHK TAU_C0 K_TAU");
      break;
    default:
      break;
  }
}

void InpLineWriter::damping_line(const Damping& d) {
  if (d.enabled)
    group(reals({d.cdampn, d.cdampt, d.dfnmax, d.dftmax}), "CDAMPN CDAMPT DFNMAX DFTMAX");
}

void InpLineWriter::heat_lines(const HeatParameters& h, int material_model) {
  group(reals({h.bktemp1, h.heatcp1, h.lambda1, h.dens1}), "BKTEMP1 HEATCP1 LAMBDA1 DENS1");
  group(reals({h.bktemp2, h.heatcp2, h.lambda2, h.dens2}), "BKTEMP2 HEATCP2 LAMBDA2 DENS2");
  if (material_model == 4) group(inp_real(h.betapl), "BETAPL");
}

void InpLineWriter::subsurface(const Subsurface& s) {
  group(fmt::format("{} {}", s.matfil, s.output), "MATFIL_S OUTPUT_S");
  for (const SubsurfaceBlock& b : s.blocks) {
    group(fmt::format("{}", b.isubs), "ISUBS");
    if (b.isubs == 2 || b.isubs == 6) {
      group(fmt::format("{} {} {}", b.ixl, b.ixinc, b.ixh), "IXL IXINC IXH");
      group(fmt::format("{} {} {}", b.iyl, b.iyinc, b.iyh), "IYL IYINC IYH");
    } else if (b.isubs == 3 || b.isubs == 7) {
      group(fmt::format("{} {}", b.ix.size(), b.iy.size()), "NX NY");
      int_array(b.ix);
      int_array(b.iy);
    }
    if (b.isubs == 1 || b.isubs == 2 || b.isubs == 3) {
      group(fmt::format("{} {} {}", b.z.size(), inp_real(b.zl), inp_real(b.dz)), "NZ ZL DZ");
    } else if (b.isubs == 9) {
      group(fmt::format("{} {} {}", b.x.size(), b.y.size(), b.z.size()), "NX NY NZ");
      array(b.x, "X");
      array(b.y, "Y");
      array(b.z, "Z");
    } else {
      group(fmt::format("{}", b.z.size()), "NZ");
      array(b.z, "Z");
    }
  }
  group("0", "ISUBS = 0: end of the blocks");
}

}  // namespace rollcontact::format
