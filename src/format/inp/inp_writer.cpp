#include "format/inp/inp_writer.hpp"

#include <fmt/format.h>

#include <cmath>
#include <span>
#include <string_view>

#include "format/text/atomic_file.hpp"
#include "rollcontact/errors.hpp"

namespace rollcontact::format {

namespace {

/// Shortest text that reads back to exactly `v` (the .inp reader converts with from_chars).
std::string real(double v) {
  if (!std::isfinite(v))
    throw Error(fmt::format("cannot write the non-finite value {} to .inp", v));
  std::string s = fmt::format("{}", v);
  if (s.find_first_of(".e") == std::string::npos) s += ".";
  return s;
}

/// Writes one case in the line order of spec/inp-format.md §4.
class CaseWriter {
 public:
  CaseWriter(std::string& out, const CaseRecord& p, const std::filesystem::path& base_dir)
      : out_(out), p_(p), base_dir_(base_dir) {}

  void write() {
    control_words();
    solver_lines();
    load_line();
    if (p_.digits.v == 0) friction_lines();
    rolling_line();
    influence_lines();
    material_lines();
    damping_line();
    heat_lines();
    potential_contact();
    geometry();
    if (p_.digits.v == 3) friction_rows();
    extra_slip();
    subsurface();
  }

 private:
  /// One group: values then a `%` comment naming them (labels never reach optional fields).
  void group(const std::string& values, std::string_view names) {
    out_ += fmt::format("  {:<40} % {}\n", values, names);
  }
  /// An array, six values per line (the reader takes up to 50 words per line).
  void array(std::span<const double> v, std::string_view names) {
    out_ += fmt::format("  % {}\n", names);
    for (std::size_t k = 0; k < v.size(); ++k) {
      out_ += (k % 6 == 0 ? "  " : " ") + real(v[k]);
      if (k % 6 == 5 || k + 1 == v.size()) out_ += "\n";
    }
  }
  void int_array(std::span<const int> v) {
    for (std::size_t k = 0; k < v.size(); ++k) {
      out_ += fmt::format("{}{}", k % 10 == 0 ? "  " : " ", v[k]);
      if (k % 10 == 9 || k + 1 == v.size()) out_ += "\n";
    }
  }
  static std::string reals(std::initializer_list<double> v) {
    std::string s;
    for (double x : v) s += (s.empty() ? "" : " ") + real(x);
    return s;
  }

  bool has_memory() const {
    const int law = p_.friction.law;
    return law == 2 || law == 3 || law == 4 || law == 6;
  }

  void control_words() {
    const ControlDigits& d = p_.digits;
    const int s = d.s >= 1 ? 3 : 0;
    const int w1 = d.p * 100000 + d.b * 10000 + d.t * 1000 + d.n * 100 + d.f * 10 + s;
    const int m2 = p_.damping.enabled ? 2 : 0;
    const int w2 = d.v * 1000000 + p_.friction.law * 100000 + 2 * 10000 +
                   p_.materials.influence_type * 1000 + d.m * 100 + 2 * 10 +
                   p_.kinematics.extra_slip_mode;
    const int h = d.h >= 1 ? 3 : 0;
    const int r = d.r == 2 || d.r == 3 ? 3 : 1;
    const int w3 = d.x * 10000000 + h * 1000000 + p_.solver.method * 100000 + d.i * 10000 +
                   d.a * 1000 + d.o * 100 + d.w * 10 + r;
    group(fmt::format("{:06d}", w1), "P-B-T-N-F-S");
    group(fmt::format("{:0{}d} {}", w2, d.v ? 7 : 6, 10 * d.gapwgt + m2),
          d.v ? "V-L-D-C-M-Z-E  10*GAPWGT+M2" : "L-D-C-M-Z-E  10*GAPWGT+M2");
    group(fmt::format("{:0{}d}", w3, d.x ? 8 : 7), d.x ? "X-H-G-I-A-O-W-R" : "H-G-I-A-O-W-R");
    if (d.x == 1) {
      const DebugDigits& g = d.debug;
      const int w4 =
          g.p * 1000000 + g.s * 100000 + g.f * 10000 + g.l * 1000 + g.c * 100 + g.i * 10 + g.n;
      group(fmt::format("{:07d} {}", w4, g.readln), "P-S-F-L-C-I-N  READLN");
    }
  }

  void solver_lines() {
    const SolverSettings& s = p_.solver;
    group(fmt::format("{} {} {} {} {}", s.maxgs, s.maxin, s.maxnr, s.maxout, real(s.eps)),
          "MAXGS MAXIN MAXNR MAXOUT EPS");
    if (s.method == 2 || s.method == 3) {
      group(fmt::format("{} {} {} {}", real(s.omega_h), real(s.omega_s), s.inislp, real(s.omgslp)),
            "OMEGAH OMEGAS INISLP OMGSLP");
    } else if (s.method == 4) {
      group(fmt::format("{} {}", s.inislp, real(s.omgslp)), "INISLP OMGSLP");
    } else if (s.method == 5) {
      const auto& g = s.gd;
      group(fmt::format("{} {} {} {} {} {} {} {}", real(g.fdecay), real(g.betath), g.kdowfb,
                        real(g.d_ifc), real(g.d_lin), real(g.d_cns), real(g.d_slp), real(g.pow_s)),
            "FDECAY BETATH KDOWFB D_IFC D_LIN D_CNS D_SLP POW_S");
    }
  }

  void load_line() {
    const ControlDigits& d = p_.digits;
    const Kinematics& k = p_.kinematics;
    const double v1 = d.n == 1 ? k.fn : k.pen;
    const double v2 = d.f >= 1 ? k.fx_rel : k.cksi;
    const double v3 = d.f == 2 ? k.fy_rel : k.ceta;
    group(reals({v1, v2, v3, k.cphi, k.spinxo, k.spinyo}),
          fmt::format("{} {} {} CPHI SPINXO SPINYO", d.n == 1 ? "FN" : "PEN",
                      d.f >= 1 ? "FX" : "CKSI", d.f == 2 ? "FY" : "CETA"));
  }

  void friction_values(double fstat, double fkin, const std::array<double, 4>& q) {
    switch (p_.friction.law) {
      case 0:
        group(reals({fstat, fkin}), "FSTAT FKIN");
        break;
      case 2:
        group(reals({fkin, q[0], q[1], q[2], q[3]}), "FKIN FLIN1 SABSH1 FLIN2 SABSH2");
        break;
      case 3:
        group(reals({fkin, q[0], q[1], q[2], q[3]}), "FKIN FRAT1 SABSH1 FRAT2 SABSH2");
        break;
      case 4:
        group(reals({fkin, q[0], q[1], q[2], q[3]}), "FKIN FEXP1 SABSH1 FEXP2 SABSH2");
        break;
      case 6:
        group(reals({fkin, q[0], q[1], q[2]}), "FREF TREF DFHEAT DTHEAT");
        break;
      default:
        throw Error(fmt::format("case {}: friction law L={} cannot be written to .inp",
                                p_.case_number, p_.friction.law));
    }
  }

  void friction_memory() {
    if (has_memory()) group(reals({p_.friction.memdst, p_.friction.mem_s0}), "MEMDST MEM_S0");
  }

  void friction_lines() {
    const Friction& f = p_.friction;
    friction_values(f.fstat, f.fkin, f.params);
    friction_memory();
  }

  void friction_rows() {
    for (const FrictionValues& r : p_.friction.rows) friction_values(r.fstat, r.fkin, r.params);
    friction_memory();
  }

  void rolling_line() {
    const Kinematics& k = p_.kinematics;
    if (p_.digits.t >= 2) group(reals({k.chi, k.dq, k.veloc, k.facphi}), "CHI DQ VELOC FACPHI");
  }

  void influence_lines() {
    const Materials& m = p_.materials;
    if (m.influence_type == 4) {
      const auto& c = m.conformal;
      group(fmt::format("{} {} {}", c.if_meth, c.variant, c.y.size()), "IF_METH VARIANT NN");
      std::vector<double> pairs;
      for (std::size_t k = 0; k < c.y.size(); ++k) {
        pairs.push_back(c.y[k]);
        pairs.push_back(k < c.alpha.size() ? c.alpha[k] : 0.0);
      }
      array(pairs, "Y(k) ALPHA(k)");
    } else if (m.influence_type == 9) {
      const std::filesystem::path file(m.influence_file);
      const std::string name =
          (base_dir_.empty() ? file : file.lexically_proximate(base_dir_)).generic_string();
      if (name.find('\'') != std::string::npos || name.size() > 240) {
        throw Error(
            fmt::format("case {}: the influence file name '{}' cannot be written to .inp "
                        "(quote character or longer than 240 characters)",
                        p_.case_number, name));
      }
      group(fmt::format("'{}'", name), "CFNAME");
    }
  }

  void material_lines() {
    const Materials& m = p_.materials;
    const auto& q = m.model_params;
    group(reals({m.poiss1, m.poiss2, m.gg1, m.gg2}), "POISS1 POISS2 GG1 GG2");
    if (p_.digits.b == 1) group(real(m.flxz), "FLXZ");
    switch (p_.digits.m) {
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

  void damping_line() {
    const Damping& d = p_.damping;
    if (d.enabled)
      group(reals({d.cdampn, d.cdampt, d.dfnmax, d.dftmax}), "CDAMPN CDAMPT DFNMAX DFTMAX");
  }

  void heat_lines() {
    if (p_.digits.h == 0) return;
    const HeatParameters& h = p_.heat;
    group(reals({h.bktemp1, h.heatcp1, h.lambda1, h.dens1}), "BKTEMP1 HEATCP1 LAMBDA1 DENS1");
    group(reals({h.bktemp2, h.heatcp2, h.lambda2, h.dens2}), "BKTEMP2 HEATCP2 LAMBDA2 DENS2");
    if (p_.digits.m == 4) group(real(h.betapl), "BETAPL");
  }

  void potential_contact() {
    const PotentialContact& pc = p_.potential;
    const auto& v = pc.values;
    group(fmt::format("{}", pc.ipotcn), "IPOTCN");
    static constexpr std::array<std::string_view, 11> kNames{"AA BNEG BPOS SCALE",
                                                             "AA BB SCALE",
                                                             "A1 BB SCALE",
                                                             "AA BB SCALE",
                                                             "A1 AOB SCALE",
                                                             "A1 B1 SCALE",
                                                             "",
                                                             "XL YL DX DY",
                                                             "XL YL XH YH",
                                                             "XC1 YC1 DX DY",
                                                             "XC1 YC1 XCM YCM"};
    if (pc.ipotcn < -6 || pc.ipotcn == 0 || pc.ipotcn > 4)
      throw Error(fmt::format("case {}: IPOTCN = {} is not valid", p_.case_number, pc.ipotcn));
    const bool four = pc.ipotcn > 0 || pc.ipotcn == -6;
    const std::string values = four ? reals({v[0], v[1], v[2], v[3]}) : reals({v[0], v[1], v[2]});
    group(fmt::format("{} {} {}", pc.mx, pc.my, values),
          fmt::format("MX MY {}", kNames[static_cast<std::size_t>(pc.ipotcn + 6)]));
  }

  void geometry() {
    if (p_.potential.ipotcn < 0) return;
    const UndeformedDistance& g = p_.geometry;
    group(fmt::format("{} {}", g.ibase, g.iplan), "IBASE IPLAN");
    switch (g.ibase) {
      case 1:
        array(g.coeffs, "B(1..6)");
        break;
      case 2:
        group(fmt::format("{} {}", g.coeffs.size(), reals({g.xm, g.rm, g.y1, g.dy1})),
              "NN XM RM Y1 DY1");
        array(g.coeffs, "B(1..NN)");
        break;
      case 3:
        array(g.coeffs, "B(1..8)");
        break;
      case 9:
        array(g.values, "H(1..MX*MY)");
        break;
      default:
        throw Error(fmt::format("case {}: IBASE = {} is not valid", p_.case_number, g.ibase));
    }
    if (g.iplan == 2) {
      array(g.planform, "PL(1..6)");
    } else if (g.iplan == 3) {
      array(g.planform, "XL1 XH1 YL1 YH1 XL2 XH2 YL2 YH2");
    } else if (g.iplan == 4) {
      group(fmt::format("{}", g.npatch), "NPATCH");
      array(g.planform, "XL XH YL YH per patch");
      if (!g.patch_factors.empty()) array(g.patch_factors, "patch factors f12 f13 ...");
    }
  }

  void extra_slip() {
    if (p_.kinematics.extra_slip_mode == 9)
      array(p_.kinematics.extra_slip, "extra rigid slip wx(1) wy(1) wx(2) wy(2) ...");
  }

  void subsurface() {
    if (p_.digits.s == 0) return;
    const Subsurface& s = p_.subsurface;
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
        group(fmt::format("{} {} {}", b.z.size(), real(b.zl), real(b.dz)), "NZ ZL DZ");
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

  std::string& out_;
  const CaseRecord& p_;
  const std::filesystem::path& base_dir_;
};

}  // namespace

std::string write_inp_string(const std::vector<CaseRecord>& problems,
                             const std::filesystem::path& base_dir) {
  std::string out = "% written by rollcontact (every case explicit: no \"keep\" digits)\n";
  for (const CaseRecord& p : problems) {
    out += "\n";
    if (!p.source.file.empty())
      out += fmt::format("% from {} line {} (case {})\n", p.source.file, p.source.first_line,
                         p.case_number);
    if (p.result_element != 0 || p.contact_problem != 1) {
      out += fmt::format("  3 {} {}  MODULE\n", p.result_element, p.contact_problem);
    } else {
      out += "  3  MODULE\n";
    }
    CaseWriter(out, p, base_dir).write();
  }
  out += "\n  0  MODULE\n";
  return out;
}

void write_inp_file(const std::filesystem::path& path, const std::vector<CaseRecord>& problems) {
  write_file_atomically(path, write_inp_string(problems, path.parent_path()));
}

}  // namespace rollcontact::format
