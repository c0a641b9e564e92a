#include "format/inp/inp_module3.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <string_view>
#include <system_error>

#include "format/inp/grid_extent.hpp"
#include "format/inp/inp_blocks.hpp"
#include "format/inp/inp_control.hpp"
#include "format/inp/reader_checks.hpp"
#include "format/text/file_names.hpp"
#include "format/text/inp_checks.hpp"
#include "rollcontact/model/validation.hpp"

namespace rollcontact::format {

namespace {

constexpr FieldKind kInt = FieldKind::integer;
constexpr FieldKind kReal = FieldKind::real;
constexpr FieldKind kAngle = FieldKind::angle;

constexpr long long kMaxElements = 2000000;                    // MX*MY limit
constexpr double kMinElementSize = model::kMinElementSize_mm;  // DX, DY [mm]

std::size_t element_count(const PotentialContact& pc) {
  return static_cast<std::size_t>(pc.mx) * static_cast<std::size_t>(pc.my);
}

/// Lines of the IPOTCN value and of the grid values after it.
struct PotentialLines {
  int ipotcn = 0;
  int grid = 0;
};

/// IPOTCN line and the line of grid values (D=2).
PotentialLines read_potential_contact(InpStream& in, PotentialContact& pc) {
  const GroupValues g = in.read_group({{"IPOTCN", kInt}}, "the IPOTCN line");
  const int ipotcn = g.integer(0);
  if (ipotcn < -6 || ipotcn == 0 || ipotcn > 4) {
    in.fail(g.line(0), fmt::format("IPOTCN = {} is not a valid value (-6..-1, 1..4)", ipotcn));
  }
  static constexpr std::array<std::array<std::string_view, 4>, 11> kNames{{
      {"AA", "BNEG", "BPOS", "SCALE"},  // -6
      {"AA", "BB", "SCALE", ""},        // -5
      {"A1", "BB", "SCALE", ""},        // -4
      {"AA", "BB", "SCALE", ""},        // -3
      {"A1", "AOB", "SCALE", ""},       // -2
      {"A1", "B1", "SCALE", ""},        // -1
      {"", "", "", ""},                 //  0
      {"XL", "YL", "DX", "DY"},         //  1
      {"XL", "YL", "XH", "YH"},         //  2
      {"XC1", "YC1", "DX", "DY"},       //  3
      {"XC1", "YC1", "XCM", "YCM"},     //  4
  }};
  const auto& n = kNames[static_cast<std::size_t>(ipotcn + 6)];
  const bool four = ipotcn > 0 || ipotcn == -6;
  const std::string what = fmt::format("the IPOTCN={} line (MX MY {} {} {}{}{})", ipotcn, n[0],
                                       n[1], n[2], four ? " " : "", n[3]);
  const GroupValues v =
      four ? in.read_group({{"MX", kInt},
                            {"MY", kInt},
                            {n[0], kReal},
                            {n[1], kReal},
                            {n[2], kReal},
                            {n[3], kReal}},
                           what)
           : in.read_group(
                 {{"MX", kInt}, {"MY", kInt}, {n[0], kReal}, {n[1], kReal}, {n[2], kReal}}, what);
  const int line = v.line(1);
  const int mx = v.integer(0);
  const int my = v.integer(1);
  const int min_size = ipotcn == 4 ? 2 : 1;
  if (mx < min_size) in.fail(v.line(0), fmt::format("MX = {} must be at least {}", mx, min_size));
  if (my < min_size) in.fail(v.line(1), fmt::format("MY = {} must be at least {}", my, min_size));
  const long long nelem = static_cast<long long>(mx) * static_cast<long long>(my);
  if (nelem > kMaxElements) {
    in.fail(line, fmt::format("MX·MY = {} exceeds 2 000 000", nelem));
  }
  pc.ipotcn = ipotcn;
  pc.mx = mx;
  pc.my = my;
  pc.values = {v.real(2), v.real(3), v.real(4), four ? v.real(5) : 0.0};
  if (ipotcn > 0) {
    const GridExtent ext = grid_extent(pc);
    // The element size at its line (the model's limits; a larger one overflows the kernels).
    for (const auto& [name, size] : {std::pair{"DX", ext.dx}, std::pair{"DY", ext.dy}}) {
      if (!(size >= kMinElementSize && size <= model::kMaxElementSize_mm)) {
        in.fail(line, fmt::format("{} = {} outside [1e-8, {:g}] mm", name, size,
                                  model::kMaxElementSize_mm));
      }
    }
  } else {
    // Hertzian options: curvatures / semi-axes / ratio and SCALE must be positive.
    const std::size_t nreal = four ? 4 : 3;
    for (std::size_t k = 0; k < nreal; ++k) {
      require_positive(in, v.line(k + 2), n[k], v.real(k + 2));
    }
  }
  return {g.line(0), line};
}

/// Undeformed distance block (Z=2 with IPOTCN > 0), spec §4.3.
void read_geometry(InpStream& in, const PotentialContact& pc, UndeformedDistance& ud) {
  const GroupValues g = in.read_group({{"IBASE", kInt}, {"IPLAN", kInt}},
                                      "the undeformed-distance line (IBASE IPLAN)");
  const int ibase = g.integer(0);
  const int iplan = g.integer(1);
  if (ibase != 1 && ibase != 2 && ibase != 3 && ibase != 9) {
    in.fail(g.line(0), fmt::format("IBASE = {} is not a valid value (1, 2, 3, 9)", ibase));
  }
  if (iplan < 1 || iplan > 4) {
    in.fail(g.line(1), fmt::format("IPLAN = {} is not a valid value (1..4)", iplan));
  }
  ud = UndeformedDistance{};
  ud.ibase = ibase;
  ud.iplan = iplan;
  if (ibase == 1) {
    ud.coeffs = in.read_reals(6, "B(1..6) of the IBASE=1 block");
  } else if (ibase == 2) {
    const GroupValues h =
        in.read_group({{"NN", kInt}, {"XM", kReal}, {"RM", kReal}, {"Y1", kReal}, {"DY1", kReal}},
                      "the IBASE=2 line (NN XM RM Y1 DY1)");
    require_int_range(in, h.line(0), "NN", h.integer(0), 2, 1000000);
    require_positive(in, h.line(4), "DY1", h.real(4));
    if (h.real(2) == 0.0) {
      in.fail(h.line(2),
              "RM = 0: the x-radius of the IBASE=2 profile must be non-zero (a large "
              "RM gives a flat x-profile)");
    }
    ud.xm = h.real(1);
    ud.rm = h.real(2);
    ud.y1 = h.real(3);
    ud.dy1 = h.real(4);
    ud.coeffs =
        in.read_reals(static_cast<std::size_t>(h.integer(0)), "B(1..NN) of the IBASE=2 block");
  } else if (ibase == 3) {
    ud.coeffs = in.read_reals(8, "B(1..8) of the IBASE=3 block");
    for (std::size_t k = 6; k < 8; ++k) {
      if (ud.coeffs[k] == 0.0) {
        in.fail(in.last_line(), fmt::format("B{} = 0: IBASE=3 divides by B7 and B8 (x²/B7 + "
                                            "y²/B8; a large value gives a flat direction)",
                                            k + 1));
      }
    }
  } else {
    ud.values = in.read_reals(element_count(pc), "H(1..MX·MY) of the IBASE=9 block");
  }
  if (iplan == 2) {
    ud.planform = in.read_reals(6, "PL(1..6) of the IPLAN=2 block");
  } else if (iplan == 3) {
    ud.planform = in.read_reals(8, "XL1 XH1 YL1 YH1 XL2 XH2 YL2 YH2 of the IPLAN=3 block");
    static constexpr std::array<std::string_view, 8> kLim{"XL1", "XH1", "YL1", "YH1",
                                                          "XL2", "XH2", "YL2", "YH2"};
    for (std::size_t k = 0; k < 8; k += 2) {
      if (ud.planform[k] > ud.planform[k + 1]) {
        in.fail(in.last_line(), fmt::format("IPLAN=3: {} = {} exceeds {} = {}", kLim[k],
                                            ud.planform[k], kLim[k + 1], ud.planform[k + 1]));
      }
    }
  } else if (iplan == 4) {
    const GroupValues np = in.read_group({{"NPATCH", kInt}}, "the IPLAN=4 line (NPATCH)");
    require_int_range(in, np.line(0), "NPATCH", np.integer(0), 1, 9999);
    const auto npatch = static_cast<std::size_t>(np.integer(0));
    ud.npatch = np.integer(0);
    ud.planform = in.read_reals(4 * npatch, "the XL XH YL YH patch limits of the IPLAN=4 block");
    const std::size_t nfac = npatch * (npatch - 1) / 2;
    if (nfac > 0) ud.patch_factors = in.read_reals(nfac, "the patch factors of the IPLAN=4 block");
  }
}

std::string_view friction_law_name(int law) {
  switch (law) {
    case 0:
      return "FSTAT FKIN";
    case 2:
      return "FKIN FLIN1 SABSH1 FLIN2 SABSH2";
    case 3:
      return "FKIN FRAT1 SABSH1 FRAT2 SABSH2";
    case 4:
      return "FKIN FEXP1 SABSH1 FEXP2 SABSH2";
    default:
      return "FREF TREF DFHEAT DTHEAT";
  }
}

/// The case being read: the stream, the record, the stored state of its contact problem and
/// the lines of its control words (where errors about digits are reported).
struct CaseContext {
  InpStream& in;
  CaseRecord& p;
  Module3Stored& st;
  bool first;  ///< the first case of this contact problem
  int l1, l2, l3;
  std::string element;  ///< "result element R [contact problem C]" for messages
};

/// Consistency rules that depend on the digits only (spec/inp-format.md §3.2).
void check_digits(CaseContext& c) {
  InpStream& in = c.in;
  ControlDigits& d = c.p.digits;
  apply_shared_digit_rules(in, d, c.first, c.st.last.digits.v, c.st.has_subsurface, c.element, c.l1,
                           c.l2, "grid", "no grid is stored yet, use D=2", c.p.source.warnings);
  if (d.d != 0 && d.z == 0) {
    in.fail(c.l2, fmt::format("D={} requires Z=1 or 2: a new grid needs the undeformed distance "
                              "to be rebuilt",
                              d.d));
  }
  if (!c.first && (c.st.last.digits.t >= 2) != (d.t >= 2) && d.c == 0) {
    in.fail(c.l2, fmt::format("switching from T={} to T={} (rolling <-> non-rolling) requires C≠0",
                              c.st.last.digits.t, d.t));
  }
  check_rolling_model_digits(in, d, c.st.has_heat, c.element, c.l2, c.l3);
  if (d.b == 4 && d.n != 1) in.fail(c.l1, "B=4 (SDEC) requires N=1");
  if ((d.b == 5 || d.b == 6) && d.n != 0) {
    in.fail(c.l1, fmt::format("B={} requires N=0 (approach prescribed)", d.b));
  }
}

/// Line 7: the normal load and the creepages or tangential forces.
void read_load_line(InpStream& in, const ControlDigits& d, Kinematics& k) {
  const std::string_view v1 = d.n == 0 ? "PEN" : "FN";
  const std::string_view v2 = d.f == 0 ? "CKSI" : "FX";
  const std::string_view v3 = d.f == 2 ? "FY" : "CETA";
  const GroupValues g = in.read_group({{v1, kReal},
                                       {v2, kReal},
                                       {v3, kReal},
                                       {"CPHI", kReal},
                                       {"SPINXO", kReal, true},
                                       {"SPINYO", kReal, true}},
                                      fmt::format("the load line ({} {} {} CPHI)", v1, v2, v3));
  if (d.n == 0) {
    k.pen = g.real(0);
  } else {
    k.fn = g.real(0);
    if (!(k.fn > 0.0)) in.fail(g.line(0), fmt::format("FN = {} must be positive (N=1)", k.fn));
  }
  if (d.f == 0) {
    k.cksi = g.real(1);
  } else {
    k.fx_rel = g.real(1);
    if (!(std::abs(k.fx_rel) <= 1.0)) {
      in.fail(g.line(1), fmt::format("relative force |FX| = {} exceeds 1", std::abs(k.fx_rel)));
    }
  }
  if (d.f == 2) {
    k.fy_rel = g.real(2);
    const double ft2 = k.fx_rel * k.fx_rel + k.fy_rel * k.fy_rel;
    if (!(ft2 <= 1.0)) {
      in.fail(g.line(2), fmt::format("relative forces FX² + FY² = {:.6g} exceed 1", ft2));
    }
  } else {
    k.ceta = g.real(2);
  }
  k.cphi = g.real(3);
  // SPINXO alone is ignored: the spin centre needs both coordinates.
  const bool spin_centre = g.has(4) && g.has(5);
  k.spinxo = spin_centre ? g.real(4) : 0.0;
  k.spinyo = spin_centre ? g.real(5) : 0.0;
}

/// Lines 8-9: the friction law (L=1 keeps it), and the rules that tie it to H and M.
void read_friction_law(CaseContext& c) {
  InpStream& in = c.in;
  const ControlDigits& d = c.p.digits;
  Friction& friction = c.p.friction;
  if (d.l != 1) {
    friction.law = d.l;
    friction.rows.clear();
    if (d.v == 0) {
      const FrictionValues fv = read_friction_values(
          in, d.l, fmt::format("the friction line (L={}: {})", d.l, friction_law_name(d.l)));
      assign_friction_values(fv, friction);
      if (friction_law_has_memory(d.l)) read_friction_memory(in, friction);
    }
  }
  check_friction_law_digits(in, d, friction.law, c.l2);
}

/// Line 10: rolling direction, step and velocity (new materials with T=2, 3).
void read_rolling_line(CaseContext& c, bool new_materials) {
  InpStream& in = c.in;
  const ControlDigits& d = c.p.digits;
  Kinematics& k = c.p.kinematics;
  if (new_materials && (d.t == 2 || d.t == 3)) {
    const GroupValues g =
        in.read_group({{"CHI", kAngle}, {"DQ", kReal}, {"VELOC", kReal}, {"FACPHI", kReal, true}},
                      "the rolling line (CHI DQ VELOC)");
    k.chi = g.real(0);
    k.dq = g.real(1);
    k.veloc = g.real(2);
    k.facphi = g.has(3) ? g.real(3) : 1.0 / 6.0;
    const double eps = c.p.solver.eps;
    if (!(k.dq >= eps))
      in.fail(g.line(1), fmt::format("DQ = {} must be at least EPS = {}", k.dq, eps));
    if (!(k.veloc >= eps)) {
      in.fail(g.line(2), fmt::format("VELOC = {} must be at least EPS = {}", k.veloc, eps));
    }
  }
  if (d.m == 1 && std::abs(k.chi) > 1e-9) {
    in.fail(c.l2,
            fmt::format("M=1 (viscoelastic) requires rolling direction CHI = 0, not {:.6g} rad",
                        k.chi));
  }
}

/// Line 11 (C=4): the conformal correction table.
void read_conformal_line(InpStream& in, Materials::Conformal& cf) {
  const GroupValues g = in.read_group({{"IF_METH", kInt}, {"VARIANT", kInt}, {"NN", kInt}},
                                      "the C=4 line (IF_METH VARIANT NN)");
  require_int_range(in, g.line(0), "IF_METH", g.integer(0), 0, 1);
  require_int_range(in, g.line(1), "VARIANT", g.integer(1), 1, 4);
  require_int_range(in, g.line(2), "NN", g.integer(2), 1, 9999);
  const auto nn = static_cast<std::size_t>(g.integer(2));
  const auto pairs = in.read_reals(2 * nn, "the C=4 table (Y(k) ALPHA(k), k=1..NN)",
                                   [](std::size_t k) { return k % 2 == 1; });
  cf.if_meth = g.integer(0);
  cf.variant = g.integer(1);
  cf.y.resize(nn);
  cf.alpha.resize(nn);
  for (std::size_t k = 0; k < nn; ++k) {
    cf.y[k] = pairs[2 * k];
    cf.alpha[k] = pairs[2 * k + 1];
  }
}

/// Lines 13-18: materials (new materials only), damping and heat.
void read_material_damping_heat(CaseContext& c, bool new_materials) {
  const ControlDigits& d = c.p.digits;
  if (new_materials) {
    read_material_block(c.in, d.b, d.m, c.p.materials);
    c.p.materials.influence_type = d.c;
  }
  if (d.m2 == 0) c.p.damping.enabled = false;
  if (d.m2 == 2) read_damping_line(c.in, c.p.damping);
  if (d.h == 3) {
    read_heat_lines(c.in, d.m == 4, c.p.heat);
    c.st.has_heat = true;
  }
}

/// Checks of the IPOTCN value against the digits and the load.
void check_potential_contact(CaseContext& c, int ipotcn_line) {
  InpStream& in = c.in;
  const ControlDigits& d = c.p.digits;
  const PotentialContact& pc = c.p.potential;
  if ((d.b == 2 || d.b == 3) && pc.ipotcn > 0) {
    in.fail(ipotcn_line,
            fmt::format("B={} requires a Hertzian IPOTCN (< 0), not IPOTCN = {}", d.b, pc.ipotcn));
  }
  if ((pc.ipotcn == -6) != (d.b == 4)) {
    in.fail(ipotcn_line, fmt::format("IPOTCN = -6 (SDEC) and B=4 go together (IPOTCN = {}, B={})",
                                     pc.ipotcn, d.b));
  }
  if ((pc.ipotcn == -4 || pc.ipotcn == -5) && d.n != 1) {
    in.fail(ipotcn_line, fmt::format("IPOTCN = {} (2-D Hertz) requires N=1", pc.ipotcn));
  }
  if (pc.ipotcn <= -1 && pc.ipotcn >= -5 && d.n == 0 && c.p.kinematics.pen < 0.0) {
    in.fail(ipotcn_line, fmt::format("Hertzian IPOTCN = {} with N=0 requires PEN ≥ 0, not {}",
                                     pc.ipotcn, c.p.kinematics.pen));
  }
}

/// The grid against the stored influence coefficients and the previous grid; then remembers
/// the grid of the coefficients when they are recomputed (C ≠ 0).
void check_grid_against_stored(CaseContext& c, int grid_line) {
  InpStream& in = c.in;
  const ControlDigits& d = c.p.digits;
  const PotentialContact& pc = c.p.potential;
  Module3Stored& st = c.st;
  const GridExtent ext = grid_extent(pc);
  if (d.d != 0 && d.c == 0 && st.has_coefficients) {
    if (pc.mx > st.coef_mx || pc.my > st.coef_my) {
      in.fail(grid_line,
              fmt::format("D={} with C=0: grid {}x{} is larger than the {}x{} grid of the stored "
                          "influence coefficients (use C=1)",
                          d.d, pc.mx, pc.my, st.coef_mx, st.coef_my));
    }
    if (ext.known && st.coef_dx_known &&
        (differs(ext.dx, st.coef_dx, 1e-6) || differs(ext.dy, st.coef_dy, 1e-6))) {
      in.fail(grid_line,
              fmt::format("D={} with C=0: element size DX, DY = {}, {} differs from {}, {} of the "
                          "stored influence coefficients (use C=1)",
                          d.d, ext.dx, ext.dy, st.coef_dx, st.coef_dy));
    }
  }
  if (!c.first && d.d == 2 && (d.p != 2 || d.i != 0)) {
    const GridExtent old = grid_extent(st.last.potential);
    if (ext.known && old.known) {
      if (differs(ext.dx, old.dx, 1e-6) || differs(ext.dy, old.dy, 1e-6)) {
        in.fail(grid_line,
                fmt::format("P={}, I={} with a new grid (D=2): DX, DY = {}, {} must equal the "
                            "previous {}, {}",
                            d.p, d.i, ext.dx, ext.dy, old.dx, old.dy));
      }
      if (!is_multiple(ext.xl - old.xl, old.dx) || !is_multiple(ext.yl - old.yl, old.dy)) {
        in.fail(grid_line,
                fmt::format(
                    "P={}, I={} with a new grid (D=2): the grid offset ({:.6g}, {:.6g}) must be "
                    "a whole number of elements DX, DY",
                    d.p, d.i, ext.xl - old.xl, ext.yl - old.yl));
      }
    }
  }
  if (d.c != 0) {
    st.has_coefficients = true;
    st.coef_mx = pc.mx;
    st.coef_my = pc.my;
    st.coef_dx_known = ext.known;
    st.coef_dx = ext.dx;
    st.coef_dy = ext.dy;
  }
}

/// Line 19: the potential contact area (D=2) and its checks. Errors about the grid go to the
/// MX MY .. line when it was read in this case, otherwise to the control word that kept it.
void read_and_check_grid(CaseContext& c) {
  int ipotcn_line = c.l1;
  int grid_line = c.l2;
  if (c.p.digits.d == 2) {
    const PotentialLines lines = read_potential_contact(c.in, c.p.potential);
    ipotcn_line = lines.ipotcn;
    grid_line = lines.grid;
  }
  check_potential_contact(c, ipotcn_line);
  check_grid_against_stored(c, grid_line);
}

/// Line 20: the undeformed distance of a non-Hertzian grid (Z=2 reads, Z=1 keeps).
void read_undeformed_distance(CaseContext& c) {
  const PotentialContact& pc = c.p.potential;
  if (pc.ipotcn <= 0) return;
  const ControlDigits& d = c.p.digits;
  if (d.z == 2) {
    read_geometry(c.in, pc, c.p.geometry);
    c.st.has_geometry = true;
  } else if (!c.st.has_geometry) {
    c.in.fail(c.l2, fmt::format("Z={} uses the stored undeformed distance, but no IBASE block was "
                                "read for {} (use Z=2)",
                                d.z, c.element));
  }
  if (c.p.geometry.ibase == 9 && c.p.geometry.values.size() != element_count(pc)) {
    c.in.fail(c.l2, fmt::format("the stored IBASE=9 undeformed distance has {} values but the "
                                "grid has {} elements (use Z=2)",
                                c.p.geometry.values.size(), element_count(pc)));
  }
}

/// Line 21 (V=3): the friction values per grid row.
void read_friction_rows(CaseContext& c) {
  InpStream& in = c.in;
  const ControlDigits& d = c.p.digits;
  const PotentialContact& pc = c.p.potential;
  Friction& friction = c.p.friction;
  const int law = friction.law;
  if (d.v == 3 && d.l != 1) {
    const auto my = static_cast<std::size_t>(pc.my);
    friction.rows.resize(my);
    for (std::size_t iy = 0; iy < my; ++iy) {
      friction.rows[iy] =
          read_friction_values(in, law,
                               fmt::format("the friction line of grid row {} (V=3, L={}: {})",
                                           iy + 1, law, friction_law_name(law)));
    }
    assign_friction_values(friction.rows.front(), friction);
    if (friction_law_has_memory(law)) read_friction_memory(in, friction);
  }
  if (d.v == 3 && friction.rows.size() != static_cast<std::size_t>(pc.my)) {
    in.fail(c.l2, fmt::format("V=3 with L=1 keeps {} friction rows but the grid has MY = {} rows",
                              friction.rows.size(), pc.my));
  }
}

/// Line 22: extra rigid slip per element (E=9 reads, E=1 keeps, others clear).
void read_extra_slip(CaseContext& c) {
  const ControlDigits& d = c.p.digits;
  const std::size_t n = element_count(c.p.potential);
  Kinematics& k = c.p.kinematics;
  if (d.e == 9) {
    k.extra_slip_mode = 9;
    k.extra_slip = c.in.read_reals(2 * n, "the E=9 extra rigid slip (wx wy per element)");
  } else if (d.e != 1) {
    k.extra_slip_mode = d.e;
    k.extra_slip.clear();
  } else if (k.extra_slip_mode == 9 && k.extra_slip.size() != 2 * n) {
    c.in.fail(c.l2, fmt::format("E=1 keeps {} extra slip values but the grid needs 2·MX·MY = {}",
                                k.extra_slip.size(), 2 * n));
  }
}

}  // namespace

void Module3Reader::read_coefficient_file(InpStream& in, CaseRecord& p) const {
  const GroupValues g = in.read_group({{"CFNAME", FieldKind::string}}, "the C=9 line ('CFNAME')");
  const std::filesystem::path resolved = resolve_input_name(base_dir_, g.text(0));
  p.materials.influence_file = resolved.string();
  std::error_code ec;
  if (!std::filesystem::is_regular_file(resolved, ec)) {
    const std::string message = fmt::format("influence coefficient file '{}' not found", g.text(0));
    if (options_.missing_files_are_errors) in.fail(g.line(0), message, g.text(0));
    p.source.case_error = fmt::format("{}:{}: {}", in.file(), g.line(0), message);
  }
}

CaseRecord Module3Reader::read_case(InpStream& in, int reid, int cpid, int module_line,
                                    int case_number) {
  Module3Stored& st = stored_[{reid, cpid}];
  const bool first = !st.has_case;
  CaseRecord p = first ? CaseRecord{} : st.last;
  p.case_number = case_number;
  p.result_element = reid;
  p.contact_problem = cpid;
  p.source = SourceInfo{};
  p.source.file = in.file();
  p.source.module_line = module_line;

  // Lines 1-4: control words.
  const ControlWords cw = read_control_words_module3(in);
  p.digits = cw.digits;
  p.source.digit_lines = cw.lines;
  p.source.first_line = cw.lines[0];
  CaseContext c{in,
                p,
                st,
                first,
                cw.lines[0],
                cw.lines[1],
                cw.lines[2],
                cpid == 1 ? fmt::format("result element {}", reid)
                          : fmt::format("result element {} contact problem {}", reid, cpid)};
  const ControlDigits& d = p.digits;
  check_digits(c);

  if (d.g != 1) read_solver_lines(in, d.g, p.solver);  // lines 5-6 (G=1 keeps them)
  if (p.solver.method == 5) p.source.warnings.push_back(kGdSteadyNote);
  read_load_line(in, d, p.kinematics);  // line 7
  read_friction_law(c);                 // lines 8-9
  const bool new_materials = d.c == 2 || d.c == 3 || d.c == 4 || d.c == 9;
  read_rolling_line(c, new_materials);                           // line 10
  if (d.c == 4) read_conformal_line(in, p.materials.conformal);  // line 11
  if (d.c == 9) {                                                // line 12
    read_coefficient_file(in, p);
  } else if (new_materials) {
    p.materials.influence_file.clear();
  }
  read_material_damping_heat(c, new_materials);  // lines 13-18
  read_and_check_grid(c);                        // line 19
  read_undeformed_distance(c);                   // line 20
  read_friction_rows(c);                         // line 21
  read_extra_slip(c);                            // line 22
  if (d.s >= 2) {                                // line 23: subsurface points
    read_subsurface_block(in, d.s, p.subsurface, p.source.warnings);
    if (d.s == 3) st.has_subsurface = true;
  }

  // Overrides after reading. The inclination correction (C=4) couples the problems whatever K
  // is, and keeps MAXOUT (spec-additions.md §B8).
  if (p.solver.maxout > 1 && std::abs(material_k(p.materials)) < 1e-10 &&
      p.materials.influence_type != 4) {
    p.source.warnings.push_back(fmt::format(
        "MAXOUT = {} overridden to 1: the materials are quasi-identical (K = 0)", p.solver.maxout));
    p.solver.maxout = 1;
  }

  st.last = p;
  st.has_case = true;
  return p;
}

}  // namespace rollcontact::format
