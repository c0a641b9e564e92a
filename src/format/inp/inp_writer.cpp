#include "format/inp/inp_writer.hpp"

#include <fmt/format.h>

#include <cmath>
#include <span>
#include <string_view>

#include "format/inp/inp_line_writer.hpp"
#include "format/text/atomic_file.hpp"
#include "format/text/file_names.hpp"
#include "rollcontact/errors.hpp"

namespace rollcontact::format {

namespace {

/// Writes one case in the line order of spec/inp-format.md §4.
class CaseWriter : InpLineWriter {
 public:
  CaseWriter(std::string& out, const CaseRecord& p, const std::filesystem::path& base_dir)
      : InpLineWriter(out, p.case_number), p_(p), base_dir_(base_dir) {}

  void write() {
    control_words();
    solver_lines(p_.solver);
    load_line();
    if (p_.digits.v == 0) friction_lines();
    rolling_line();
    influence_lines();
    material_lines(p_.materials, p_.digits.b, p_.digits.m);
    damping_line(p_.damping);
    if (p_.digits.h != 0) heat_lines(p_.heat, p_.digits.m);
    potential_contact();
    geometry();
    if (p_.digits.v == 3) friction_rows();
    extra_slip();
    if (p_.digits.s != 0) subsurface(p_.subsurface);
  }

 private:
  void control_words() {
    const ControlDigits& d = p_.digits;
    const int s = d.s >= 1 ? 3 : 0;
    const int w1 = d.p * 100000 + d.b * 10000 + d.t * 1000 + d.n * 100 + d.f * 10 + s;
    const int m2 = p_.damping.enabled ? 2 : 0;
    const int w2 = d.v * 1000000 + p_.friction.law * 100000 + 2 * 10000 +
                   p_.materials.influence_type * 1000 + d.m * 100 + 2 * 10 +
                   p_.kinematics.extra_slip_mode;
    group(fmt::format("{:06d}", w1), "P-B-T-N-F-S");
    group(fmt::format("{:0{}d} {}", w2, d.v ? 7 : 6, 10 * d.gapwgt + m2),
          d.v ? "V-L-D-C-M-Z-E  10*GAPWGT+M2" : "L-D-C-M-Z-E  10*GAPWGT+M2");
    control_word3_and_debug(d, p_.solver.method);
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

  void friction_lines() {
    const Friction& f = p_.friction;
    friction_values(f.law, FrictionValues{f.fstat, f.fkin, f.params});
    friction_memory(f);
  }

  void friction_rows() {
    for (const FrictionValues& r : p_.friction.rows) friction_values(p_.friction.law, r);
    friction_memory(p_.friction);
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
      const std::string name = written_input_name(m.influence_file, base_dir_);
      if (name.find('\'') != std::string::npos || name.size() > 240) {
        throw Error(
            fmt::format("case {}: the influence file name '{}' cannot be written to .inp "
                        "(quote character or longer than 240 characters)",
                        p_.case_number, name));
      }
      group(fmt::format("'{}'", name), "CFNAME");
    }
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

  const CaseRecord& p_;
  const std::filesystem::path& base_dir_;
};

}  // namespace

namespace {

void module3_case(std::string& out, const CaseRecord& p, const std::filesystem::path& base_dir) {
  if (p.result_element != 0 || p.contact_problem != 1) {
    out += fmt::format("  3 {} {}  MODULE\n", p.result_element, p.contact_problem);
  } else {
    out += "  3  MODULE\n";
  }
  CaseWriter(out, p, base_dir).write();
}

void module1_case(std::string& out, const WheelRailRecord& r, const std::filesystem::path& base_dir,
                  CompanionFiles& companions) {
  out += r.result_element != 0 ? fmt::format("  1 {}  MODULE\n", r.result_element)
                               : std::string("  1  MODULE\n");
  write_wheelrail_case(out, r, base_dir, companions);
}

void origin_comment(std::string& out, const SourceInfo& source, int case_number) {
  if (!source.file.empty())
    out +=
        fmt::format("% from {} line {} (case {})\n", source.file, source.first_line, case_number);
}

constexpr const char* kHeader =
    "% written by rollcontact (every case explicit: no \"keep\" digits)\n";

}  // namespace

std::string write_inp_string(const std::vector<CaseRecord>& problems,
                             const std::filesystem::path& base_dir) {
  std::string out = kHeader;
  for (const CaseRecord& p : problems) {
    out += "\n";
    origin_comment(out, p.source, p.case_number);
    module3_case(out, p, base_dir);
  }
  out += "\n  0  MODULE\n";
  return out;
}

void write_inp_file(const std::filesystem::path& path, const std::vector<CaseRecord>& problems) {
  write_file_atomically(path, write_inp_string(problems, path.parent_path()));
}

InpText write_inp_text(const std::vector<InputCase>& cases, const std::filesystem::path& base_dir,
                       const std::string& companion_stem) {
  InpText result{kHeader, {}};
  CompanionFiles companions(companion_stem);
  for (const InputCase& c : cases) {
    result.text += "\n";
    if (const auto* p = std::get_if<CaseRecord>(&c)) {
      origin_comment(result.text, p->source, p->case_number);
      module3_case(result.text, *p, base_dir);
    } else {
      const auto& r = std::get<WheelRailRecord>(c);
      origin_comment(result.text, r.source, r.case_number);
      module1_case(result.text, r, base_dir, companions);
    }
  }
  result.text += "\n  0  MODULE\n";
  result.companions = companions.files();
  return result;
}

std::vector<std::filesystem::path> write_inp_input_file(const std::filesystem::path& path,
                                                        const std::vector<InputCase>& cases) {
  const std::filesystem::path dir = path.parent_path();
  const InpText inp = write_inp_text(cases, dir, path.stem().string());
  // A companion must not replace a file the cases read (or the .inp itself).
  const auto same_file = [](const std::filesystem::path& a, const std::filesystem::path& b) {
    std::error_code ec;
    return std::filesystem::weakly_canonical(a, ec) == std::filesystem::weakly_canonical(b, ec);
  };
  for (const CompanionFile& f : inp.companions) {
    const std::filesystem::path target = dir / f.name;
    bool clash = same_file(target, path);
    for (const InputCase& c : cases)
      if (const auto* r = std::get_if<WheelRailRecord>(&c))
        for (const ProfileSpec* ps : {&r->rail, &r->wheel})
          clash = clash || (!ps->path.empty() && same_file(target, ps->path));
    if (clash)  // an input problem: exit status 2, nothing written
      throw InputError(path.string(), 0,
                       fmt::format("the profile table {} would replace a file the cases read: "
                                   "choose another output name",
                                   target.string()));
  }
  std::vector<std::filesystem::path> written;
  for (const CompanionFile& f : inp.companions) {
    write_file_atomically(dir / f.name, f.text);
    written.push_back(dir / f.name);
  }
  write_file_atomically(path, inp.text);
  return written;
}

}  // namespace rollcontact::format
