#include "format/inp/inp_blocks.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "format/text/inp_checks.hpp"

namespace rollcontact::format {

namespace {

constexpr FieldKind kInt = FieldKind::integer;
constexpr FieldKind kReal = FieldKind::real;

/// Maximum number of subsurface blocks per case and of points per coordinate direction.
constexpr int kMaxSubsurfaceBlocks = 10;
constexpr int kMaxSubsurfaceCount = 9999;

}  // namespace

std::optional<int> read_solver_lines(InpStream& in, int g, SolverSettings& solver) {
  const GroupValues it = in.read_group({{"MAXGS", kInt},
                                        {"MAXIN", kInt},
                                        {"MAXNR", kInt},
                                        {"MAXOUT", kInt},
                                        {"EPS", kReal},
                                        {"NPOT_MAX", kInt, true}},
                                       "the iteration line (MAXGS MAXIN MAXNR MAXOUT EPS)");
  require_int_range(in, it.line(0), "MAXGS", it.integer(0), 1, 9999);
  require_int_range(in, it.line(1), "MAXIN", it.integer(1), 1, 999999);
  require_int_range(in, it.line(2), "MAXNR", it.integer(2), 1, 9999);
  require_int_range(in, it.line(3), "MAXOUT", it.integer(3), 1, 9999);
  require_positive(in, it.line(4), "EPS", it.real(4));
  const SolverSettings defaults;
  solver.maxgs = it.integer(0);
  solver.maxin = it.integer(1);
  solver.maxnr = it.integer(2);
  solver.maxout = it.integer(3);
  solver.eps = it.real(4);
  solver.omega_h = defaults.omega_h;
  solver.omega_s = defaults.omega_s;
  solver.inislp = defaults.inislp;
  solver.omgslp = defaults.omgslp;
  solver.gd = defaults.gd;
  solver.method = g;

  if (g == 2 || g == 3) {
    const GroupValues gl =
        in.read_group({{"OMEGAH", kReal}, {"OMEGAS", kReal}, {"INISLP", kInt}, {"OMGSLP", kReal}},
                      fmt::format("the G={} line (OMEGAH OMEGAS INISLP OMGSLP)", g));
    solver.omega_h = gl.real(0);
    solver.omega_s = gl.real(1);
    solver.inislp = gl.integer(2);
    solver.omgslp = gl.real(3);
  } else if (g == 4) {
    const GroupValues gl =
        in.read_group({{"INISLP", kInt}, {"OMGSLP", kReal}}, "the G=4 line (INISLP OMGSLP)");
    solver.inislp = gl.integer(0);
    solver.omgslp = gl.real(1);
  } else if (g == 5) {
    const GroupValues gl = in.read_group({{"FDECAY", kReal},
                                          {"BETATH", kReal},
                                          {"KDOWFB", kInt},
                                          {"D_IFC", kReal},
                                          {"D_LIN", kReal},
                                          {"D_CNS", kReal},
                                          {"D_SLP", kReal},
                                          {"POW_S", kReal}},
                                         "the G=5 line (FDECAY BETATH KDOWFB D_IFC D_LIN D_CNS "
                                         "D_SLP POW_S)");
    solver.gd.fdecay = gl.real(0);
    solver.gd.betath = gl.real(1);
    solver.gd.kdowfb = gl.integer(2);
    solver.gd.d_ifc = gl.real(3);
    solver.gd.d_lin = gl.real(4);
    solver.gd.d_cns = gl.real(5);
    solver.gd.d_slp = gl.real(6);
    solver.gd.pow_s = gl.real(7);
  }
  return it.has(5) ? std::optional<int>(it.integer(5)) : std::nullopt;
}

FrictionValues read_friction_values(InpStream& in, int law, std::string_view what) {
  FrictionValues fv;
  if (law == 0) {
    const GroupValues g = in.read_group({{"FSTAT", kReal}, {"FKIN", kReal}}, what);
    fv.fstat = g.real(0);
    fv.fkin = g.real(1);
    check_coulomb_values(in, fv, g.line(0), g.line(1));
    return fv;
  }
  if (law == 6) {
    const GroupValues g = in.read_group(
        {{"FREF", kReal}, {"TREF", kReal}, {"DFHEAT", kReal}, {"DTHEAT", kReal}}, what);
    fv.fkin = g.real(0);
    fv.fstat = fv.fkin;
    fv.params = {g.real(1), g.real(2), g.real(3), 0.0};
    return fv;
  }
  // Falling friction L=2 (linear), 3 (rational), 4 (exponential): FKIN F1 SABSH1 F2 SABSH2.
  const char* f = law == 2 ? "FLIN" : law == 3 ? "FRAT" : "FEXP";
  const std::string f1 = std::string(f) + "1";
  const std::string f2 = std::string(f) + "2";
  const GroupValues g = in.read_group(
      {{"FKIN", kReal}, {f1, kReal}, {"SABSH1", kReal}, {f2, kReal}, {"SABSH2", kReal}}, what);
  fv.fkin = g.real(0);
  fv.params = {g.real(1), g.real(2), g.real(3), g.real(4)};
  fv.fstat = fv.fkin + fv.params[0] + fv.params[2];
  require_at_least(in, g.line(0), "FKIN", fv.fkin, 0.0);
  // A negative coefficient makes mu fall below FKIN and rise again; a negative SABSH makes the
  // term grow without bound with the slip velocity. 0 switches a term off (SABSH = 0 is read as
  // a tiny reference speed).
  require_at_least(in, g.line(1), f1, g.real(1), 0.0);
  require_at_least(in, g.line(2), "SABSH1", g.real(2), 0.0);
  require_at_least(in, g.line(3), f2, g.real(3), 0.0);
  require_at_least(in, g.line(4), "SABSH2", g.real(4), 0.0);
  return fv;
}

void check_coulomb_values(InpStream& in, FrictionValues& fv, int line_fstat, int line_fkin) {
  if (std::abs(fv.fstat - fv.fkin) > 1e-3 * std::abs(fv.fkin)) {
    in.fail(line_fstat, fmt::format("Coulomb friction (L=0) needs FSTAT = FKIN, but FSTAT = {} "
                                    "and FKIN = {} differ by more than 0.1 %",
                                    fv.fstat, fv.fkin));
  }
  if (fv.fkin < 1e-4 * (1.0 - 1e-12)) {
    in.fail(line_fkin, fmt::format("FKIN = {} must be at least 0.0001", fv.fkin));
  }
  fv.fstat = fv.fkin;
}

void read_friction_memory(InpStream& in, Friction& friction) {
  const GroupValues g = in.read_group({{"MEMDST", kReal}, {"MEM_S0", kReal}},
                                      "the friction memory line (MEMDST MEM_S0)");
  require_at_least(in, g.line(0), "MEMDST", g.real(0), 0.0);
  require_at_least(in, g.line(1), "MEM_S0", g.real(1), 0.0);
  friction.memdst = g.real(0);
  friction.mem_s0 = g.real(1);
}

void assign_friction_values(const FrictionValues& values, Friction& friction) {
  friction.fstat = values.fstat;
  friction.fkin = values.fkin;
  friction.params = values.params;
}

namespace {

/// Modified Fastsim's slope reduction K0_MF, ALFAMF, BETAMF (from value `first` of `g`): the
/// initial slope factor is positive, the others not negative.
void check_slope_reduction(const InpStream& in, const GroupValues& g, std::size_t first) {
  require_positive(in, g.line(first), "K0_MF", g.real(first));
  require_at_least(in, g.line(first + 1), "ALFAMF", g.real(first + 1), 0.0);
  require_at_least(in, g.line(first + 2), "BETAMF", g.real(first + 2), 0.0);
}

}  // namespace

void read_material_block(InpStream& in, int b, int m, Materials& materials) {
  const GroupValues g =
      in.read_group({{"POISS1", kReal}, {"POISS2", kReal}, {"GG1", kReal}, {"GG2", kReal}},
                    "the material line (POISS1 POISS2 GG1 GG2)");
  require_real_range(in, g.line(0), "POISS1", g.real(0), 0.0, 0.5);
  require_real_range(in, g.line(1), "POISS2", g.real(1), 0.0, 0.5);
  require_at_least(in, g.line(2), "GG1", g.real(2), 1e-5);
  require_at_least(in, g.line(3), "GG2", g.real(3), 1e-5);
  materials.poiss1 = g.real(0);
  materials.poiss2 = g.real(1);
  materials.gg1 = g.real(2);
  materials.gg2 = g.real(3);

  if (b == 1) {
    const GroupValues fl = in.read_group({{"FLXZ", kReal}}, "the B=1 layer line (FLXZ)");
    require_positive(in, fl.line(0), "FLXZ", fl.real(0));  // ≤ 0 gave a negative approach
    materials.flxz = fl.real(0);
  }
  materials.model_params = {};
  if (m == 1) {
    const GroupValues ml =
        in.read_group({{"FG1", kReal}, {"FG2", kReal}, {"TC1", kReal}, {"TC2", kReal}},
                      "the M=1 viscoelastic line (FG1 FG2 TC1 TC2)");
    materials.model_params = {ml.real(0), ml.real(1), ml.real(2), ml.real(3)};
  } else if (m == 2) {
    const GroupValues ml =
        in.read_group({{"FLX", kReal}, {"K0_MF", kReal}, {"ALFAMF", kReal}, {"BETAMF", kReal}},
                      "the M=2 line (FLX K0_MF ALFAMF BETAMF)");
    require_positive(in, ml.line(0), "FLX", ml.real(0));
    check_slope_reduction(in, ml, 1);
    materials.model_params = {ml.real(0), ml.real(1), ml.real(2), ml.real(3)};
  } else if (m == 3 || m == 5) {
    const GroupValues ml = in.read_group({{"K0_MF", kReal}, {"ALFAMF", kReal}, {"BETAMF", kReal}},
                                         fmt::format("the M={} line (K0_MF ALFAMF BETAMF)", m));
    check_slope_reduction(in, ml, 0);
    materials.model_params = {ml.real(0), ml.real(1), ml.real(2), 0.0};
  } else if (m == 4) {
    const GroupValues ml =
        in.read_group({{"GG3", kReal}, {"LAYTHK", kReal}, {"TAU_C0", kReal}, {"K_TAU", kReal}},
                      "the M=4 interface-layer line (GG3 LAYTHK TAU_C0 K_TAU)");
    // A critical stress this large means "no plasticity" in CONTACT.
    const double tau_c0 = ml.real(2) >= 1e10 ? 0.0 : ml.real(2);
    materials.model_params = {ml.real(0), ml.real(1), tau_c0, ml.real(3)};
  }
}

void read_damping_line(InpStream& in, Damping& damping) {
  const GroupValues g =
      in.read_group({{"CDAMPN", kReal}, {"CDAMPT", kReal}, {"DFNMAX", kReal}, {"DFTMAX", kReal}},
                    "the damping line (CDAMPN CDAMPT DFNMAX DFTMAX)");
  damping.enabled = true;
  damping.cdampn = g.real(0);
  damping.cdampt = g.real(1);
  damping.dfnmax = g.real(2);
  damping.dftmax = g.real(3);
}

void read_heat_lines(InpStream& in, bool with_betapl, HeatParameters& heat) {
  const GroupValues h1 =
      in.read_group({{"BKTEMP1", kReal}, {"HEATCP1", kReal}, {"LAMBDA1", kReal}, {"DENS1", kReal}},
                    "the heat line of body 1 (BKTEMP1 HEATCP1 LAMBDA1 DENS1)");
  const GroupValues h2 =
      in.read_group({{"BKTEMP2", kReal}, {"HEATCP2", kReal}, {"LAMBDA2", kReal}, {"DENS2", kReal}},
                    "the heat line of body 2 (BKTEMP2 HEATCP2 LAMBDA2 DENS2)");
  // Heat capacity, conductivity and density divide the flash temperatures: positive.
  for (const GroupValues* h : {&h1, &h2}) {
    const char* body = h == &h1 ? "1" : "2";
    require_positive(in, h->line(1), fmt::format("HEATCP{}", body), h->real(1));
    require_positive(in, h->line(2), fmt::format("LAMBDA{}", body), h->real(2));
    require_positive(in, h->line(3), fmt::format("DENS{}", body), h->real(3));
  }
  heat.bktemp1 = h1.real(0);
  heat.heatcp1 = h1.real(1);
  heat.lambda1 = h1.real(2);
  heat.dens1 = h1.real(3);
  heat.bktemp2 = h2.real(0);
  heat.heatcp2 = h2.real(1);
  heat.lambda2 = h2.real(2);
  heat.dens2 = h2.real(3);
  if (with_betapl) {
    const GroupValues bp = in.read_group({{"BETAPL", kReal}}, "the BETAPL line (H=3, M=4)");
    require_real_range(in, bp.line(0), "BETAPL", bp.real(0), 0.0, 1.0);
    heat.betapl = bp.real(0);
  }
}

namespace {

SubsurfaceBlock read_one_subsurface_block(InpStream& in, int isubs, int index) {
  const std::string block = fmt::format("subsurface block {} (ISUBS={})", index, isubs);
  SubsurfaceBlock b;
  b.isubs = isubs;
  auto count = [&](const GroupValues& g, std::size_t i, std::string_view name) {
    require_int_range(in, g.line(i), name, g.integer(i), 1, kMaxSubsurfaceCount);
    return static_cast<std::size_t>(g.integer(i));
  };
  if (isubs == 2 || isubs == 6) {
    const GroupValues gx = in.read_group({{"IXL", kInt}, {"IXINC", kInt}, {"IXH", kInt}},
                                         "the column range (IXL IXINC IXH) of " + block);
    const GroupValues gy = in.read_group({{"IYL", kInt}, {"IYINC", kInt}, {"IYH", kInt}},
                                         "the row range (IYL IYINC IYH) of " + block);
    require_int_range(in, gx.line(1), "IXINC", gx.integer(1), 1, kMaxSubsurfaceCount);
    require_int_range(in, gy.line(1), "IYINC", gy.integer(1), 1, kMaxSubsurfaceCount);
    b.ixl = gx.integer(0);
    b.ixinc = gx.integer(1);
    b.ixh = gx.integer(2);
    b.iyl = gy.integer(0);
    b.iyinc = gy.integer(1);
    b.iyh = gy.integer(2);
  } else if (isubs == 3 || isubs == 7) {
    const GroupValues g = in.read_group({{"NX", kInt}, {"NY", kInt}}, "NX NY of " + block);
    const std::size_t nx = count(g, 0, "NX");
    const std::size_t ny = count(g, 1, "NY");
    b.ix = in.read_integers(nx, "the NX column numbers of " + block);
    b.iy = in.read_integers(ny, "the NY row numbers of " + block);
    for (auto* list : {&b.ix, &b.iy}) {
      std::sort(list->begin(), list->end());
      list->erase(std::unique(list->begin(), list->end()), list->end());
    }
  }
  if (isubs == 1 || isubs == 2 || isubs == 3) {
    const GroupValues g =
        in.read_group({{"NZ", kInt}, {"ZL", kReal}, {"DZ", kReal}}, "NZ ZL DZ of " + block);
    const std::size_t nz = count(g, 0, "NZ");
    require_positive(in, g.line(2), "DZ", g.real(2));
    b.zl = g.real(1);
    b.dz = g.real(2);
    b.z.resize(nz);
    for (std::size_t k = 0; k < nz; ++k) b.z[k] = b.zl + static_cast<double>(k) * b.dz;
  } else if (isubs == 5 || isubs == 6 || isubs == 7) {
    const GroupValues g = in.read_group({{"NZ", kInt}}, "NZ of " + block);
    b.z = in.read_reals(count(g, 0, "NZ"), "the NZ z-values of " + block);
  } else if (isubs == 9) {
    const GroupValues g =
        in.read_group({{"NX", kInt}, {"NY", kInt}, {"NZ", kInt}}, "NX NY NZ of " + block);
    const std::size_t nx = count(g, 0, "NX");
    const std::size_t ny = count(g, 1, "NY");
    const std::size_t nz = count(g, 2, "NZ");
    b.x = in.read_reals(nx, "the NX x-values of " + block);
    b.y = in.read_reals(ny, "the NY y-values of " + block);
    b.z = in.read_reals(nz, "the NZ z-values of " + block);
  }
  for (auto* list : {&b.x, &b.y, &b.z}) std::sort(list->begin(), list->end());
  return b;
}

}  // namespace

void read_subsurface_block(InpStream& in, int s, Subsurface& subsurface,
                           std::vector<std::string>& warnings) {
  const GroupValues g = in.read_group({{"MATFIL_S", kInt}, {"OUTPUT_S", kInt}},
                                      "the subsurface line (MATFIL_S OUTPUT_S)");
  const int matfil = std::clamp(g.integer(0), 0, 2);
  const int output = std::clamp(g.integer(1), 0, 4);
  if (matfil != g.integer(0)) {
    warnings.push_back(fmt::format("MATFIL_S = {} clamped to {}", g.integer(0), matfil));
  }
  if (output != g.integer(1)) {
    warnings.push_back(fmt::format("OUTPUT_S = {} clamped to {}", g.integer(1), output));
  }
  subsurface.matfil = matfil;
  subsurface.output = output;
  if (s != 3) return;

  subsurface.blocks.clear();
  for (;;) {
    const GroupValues gi = in.read_group({{"ISUBS", kInt}}, "the subsurface block (ISUBS)");
    const int isubs = gi.integer(0);
    if (isubs == 0) break;
    if (isubs != 1 && isubs != 2 && isubs != 3 && isubs != 5 && isubs != 6 && isubs != 7 &&
        isubs != 9) {
      in.fail(gi.line(0),
              fmt::format("ISUBS = {} is not a valid value (1, 2, 3, 5, 6, 7, 9; 0 ends the list)",
                          isubs));
    }
    if (static_cast<int>(subsurface.blocks.size()) == kMaxSubsurfaceBlocks) {
      in.fail(gi.line(0), fmt::format("more than {} subsurface blocks", kMaxSubsurfaceBlocks));
    }
    subsurface.blocks.push_back(
        read_one_subsurface_block(in, isubs, static_cast<int>(subsurface.blocks.size()) + 1));
  }
}

void check_rolling_model_digits(InpStream& in, const ControlDigits& d, bool has_heat,
                                const std::string& element, int line2, int line3) {
  if (d.m == 1 && d.t != 3)
    in.fail(line2, fmt::format("M=1 (viscoelastic) requires T=3, not T={}", d.t));
  // v25.1 (spec-additions B3): T=0 is allowed too, the bulk temperatures are then the result.
  if (d.h >= 1 && d.t != 3 && d.t != 0)
    in.fail(line3, fmt::format("H={} (temperature) requires T=3 (or T=0), not T={}", d.h, d.t));
  if (d.h == 1 && !has_heat) {
    in.fail(line3, fmt::format("H=1 uses stored heat parameters, but none were read for {} (use "
                               "H=3)",
                               element));
  }
}

void check_friction_law_digits(InpStream& in, const ControlDigits& d, int law, int line2) {
  if (law == 6 && d.h == 0) in.fail(line2, "L=6 (temperature-dependent friction) requires H≥1");
  if (law == 6 && (d.m == 2 || d.m == 3 || d.m == 5 || d.m == 6 || d.m == 7)) {
    in.fail(line2,
            fmt::format("L=6 (temperature-dependent friction) is not allowed with M={}", d.m));
  }
}

void apply_shared_digit_rules(InpStream& in, ControlDigits& d, bool first, int previous_v,
                              bool has_subsurface, const std::string& element, int line1, int line2,
                              std::string_view kept_grid, std::string_view keep_grid_hint,
                              std::vector<std::string>& warnings) {
  if (first) {
    if (d.p != 2) {
      warnings.push_back(fmt::format("P={} overridden to 2 in the first case of {}", d.p, element));
      d.p = 2;
    }
    if (d.i != 0) {
      warnings.push_back(fmt::format("I={} overridden to 0 in the first case of {}", d.i, element));
      d.i = 0;
    }
    if (d.l == 1) {
      in.fail(line2, fmt::format("L=1 (keep friction) in the first case of {}: no friction law "
                                 "is stored yet",
                                 element));
    }
    if (d.d == 0 || d.d == 1) {
      in.fail(line2, fmt::format("D={} (keep {}) in the first case of {}: {}", d.d, kept_grid,
                                 element, keep_grid_hint));
    }
  }
  if ((d.s == 1 || d.s == 2) && !has_subsurface) {
    in.fail(line1, fmt::format("S={} uses stored subsurface points, but none were read for {} "
                               "(use S=3)",
                               d.s, element));
  }
  if (!first && d.l == 1 && d.v != previous_v) {
    in.fail(line2,
            fmt::format("L=1 (keep friction) while V changes from {} to {}", previous_v, d.v));
  }
}

std::string contact_search_note(int d) {
  switch (d) {
    case 3:
    case 7:
    case 8:
      return fmt::format(
          "D={} (an experimental variant of CONTACT's planar contact search) is solved with the "
          "contact locus of D=2: the reference point and creepages as in D=2",
          d);
    case 6:
    case 9:
      return fmt::format(
          "D={} (a variant of CONTACT's gap grid for steep or oblique views) is solved with the "
          "gap minimised along x of D=5, whose search window moves with the minimum",
          d);
    default:
      return {};
  }
}

}  // namespace rollcontact::format
