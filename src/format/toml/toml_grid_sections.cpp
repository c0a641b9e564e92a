// TOML case sections for the grid, the geometry and what is computed from the solution (output,
// damping, heat, subsurface points): each fills its part of a CaseRecord and checks it.

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string_view>
#include <system_error>

#include "format/inp/grid_extent.hpp"
#include "format/inp/reader_checks.hpp"
#include "format/toml/toml_sections.hpp"
#include "rollcontact/model/validation.hpp"

namespace rollcontact::format::toml_input {

namespace {

constexpr long long kMaxElements = 2000000;                    // MX*MY limit, as in the .inp reader
constexpr double kMinElementSize = model::kMinElementSize_mm;  // DX, DY [mm]
constexpr int kMaxSubsurfaceBlocks = 10;
constexpr int kMaxSubsurfaceCount = 9999;

}  // namespace

namespace {

void check_elements(Table& g, PotentialContact& pc, int min_size) {
  const auto e = g.opt_integers("elements");
  if (!e) g.fail("missing required key 'elements' ([MX, MY])");
  if (e->size() != 2)
    g.fail_key("elements", fmt::format("expected 2 integers but found {}", e->size()));
  pc.mx = (*e)[0];
  pc.my = (*e)[1];
  if (pc.mx < min_size || pc.my < min_size)
    g.fail_key("elements",
               fmt::format("[{}, {}]: each must be at least {}", pc.mx, pc.my, min_size));
  const long long n = static_cast<long long>(pc.mx) * static_cast<long long>(pc.my);
  if (n > kMaxElements) g.fail_key("elements", fmt::format("MX·MY = {} exceeds 2 000 000", n));
}

}  // namespace

namespace {

void require_positive(Table& t, std::string_view key, double v) {
  if (!(v > 0.0)) t.fail_key(key, fmt::format("{} must be positive", v));
}

}  // namespace

void read_grid(Table& c, CaseRecord& p) {
  Table t = c.table("grid");
  PotentialContact& pc = p.potential;
  const std::array<std::string_view, 4> kinds{"rectangle", "hertz", "hertz_2d", "sdec"};
  std::string_view kind;
  for (std::string_view k : kinds) {
    if (!t.has(k)) continue;
    if (!kind.empty()) t.fail_key(k, fmt::format("give only one of {}", fmt::join(kinds, ", ")));
    kind = k;
  }
  if (kind.empty()) t.fail(fmt::format("missing the grid: one of {}", fmt::join(kinds, ", ")));
  Table g = t.table(kind);
  pc.values = {};
  if (kind == "rectangle") {
    const auto ll = g.opt_reals("lower_left_mm", 2);
    const auto fc = g.opt_reals("first_centre_mm", 2);
    const auto es = g.opt_reals("element_size_mm", 2);
    const auto ur = g.opt_reals("upper_right_mm", 2);
    const auto lc = g.opt_reals("last_centre_mm", 2);
    const int corners = (ll ? 1 : 0) + (fc ? 1 : 0);
    const int sizes = (es ? 1 : 0) + (ur ? 1 : 0) + (lc ? 1 : 0);
    if (corners != 1 || sizes != 1 || (ll && lc) || (fc && ur)) {
      g.fail(
          "give lower_left_mm with element_size_mm or upper_right_mm, or first_centre_mm with "
          "element_size_mm or last_centre_mm");
    }
    const auto& a = ll ? *ll : *fc;
    const auto& b = es ? *es : ur ? *ur : *lc;
    pc.ipotcn = ll ? (es ? 1 : 2) : (es ? 3 : 4);
    pc.values = {a[0], a[1], b[0], b[1]};
    check_elements(g, pc, pc.ipotcn == 4 ? 2 : 1);
    const GridExtent ext = grid_extent(pc);
    if (!(ext.dx >= kMinElementSize) || !(ext.dy >= kMinElementSize)) {
      g.fail(fmt::format("element size DX, DY = {}, {} must be at least 1e-8 mm", ext.dx, ext.dy));
    }
  } else if (kind == "hertz") {
    check_elements(g, pc, 1);
    const double scale = g.real("scale");
    const auto curv = g.opt_reals("curvatures_per_mm", 2);
    const auto a1 = g.opt_real("curvature_x_per_mm");
    const auto aob = g.opt_real("semi_axis_ratio");
    const auto axes = g.opt_reals("semi_axes_mm", 2);
    if (curv && !a1 && !aob && !axes) {
      pc.ipotcn = -1;
      pc.values = {(*curv)[0], (*curv)[1], scale, 0.0};
    } else if (a1 && aob && !curv && !axes) {
      pc.ipotcn = -2;
      pc.values = {*a1, *aob, scale, 0.0};
    } else if (axes && !curv && !a1 && !aob) {
      pc.ipotcn = -3;
      pc.values = {(*axes)[0], (*axes)[1], scale, 0.0};
    } else {
      g.fail(
          "give curvatures_per_mm, or curvature_x_per_mm with semi_axis_ratio, or "
          "semi_axes_mm");
    }
    for (std::size_t k = 0; k < 3; ++k)
      if (!(pc.values[k] > 0.0))
        g.fail(fmt::format("the Hertz values and scale must be positive, not {}", pc.values[k]));
  } else if (kind == "hertz_2d") {
    check_elements(g, pc, 1);
    const double scale = g.real("scale");
    const double bb = g.real("half_width_mm");
    const auto a1 = g.opt_real("curvature_x_per_mm");
    const auto aa = g.opt_real("half_length_mm");
    if (a1.has_value() == aa.has_value())
      g.fail("give either curvature_x_per_mm or half_length_mm");
    pc.ipotcn = a1 ? -4 : -5;
    pc.values = {a1 ? *a1 : *aa, bb, scale, 0.0};
    for (std::size_t k = 0; k < 3; ++k)
      if (!(pc.values[k] > 0.0))
        g.fail(fmt::format("the Hertz values and scale must be positive, not {}", pc.values[k]));
  } else {
    check_elements(g, pc, 1);
    const double aa = g.real("semi_axis_x_mm");
    const auto bb = g.reals("half_width_mm", 2);
    const double scale = g.real("scale");
    pc.ipotcn = -6;
    pc.values = {aa, bb[0], bb[1], scale};
    for (double v : pc.values)
      if (!(v > 0.0)) g.fail(fmt::format("the SDEC values and scale must be positive, not {}", v));
  }
  g.finish();
  t.finish();

  const ControlDigits& d = p.digits;
  if ((d.b == 2 || d.b == 3) && pc.ipotcn > 0)
    t.fail("normal.method \"elliptic\" and \"parabolic\" need a Hertzian grid (hertz, hertz_2d)");
  if ((pc.ipotcn == -6) != (d.b == 4)) t.fail("grid.sdec and normal.method = \"sdec\" go together");
  if ((pc.ipotcn == -4 || pc.ipotcn == -5) && d.n != 1)
    t.fail("grid.hertz_2d requires normal.force_N (N=1)");
  if (pc.ipotcn <= -1 && pc.ipotcn >= -5 && d.n == 0 && p.kinematics.pen < 0.0) {
    t.fail(fmt::format("a Hertzian grid with approach_mm needs approach_mm >= 0, not {}",
                       p.kinematics.pen));
  }
}

void read_geometry(Table& c, CaseRecord& p) {
  const PotentialContact& pc = p.potential;
  UndeformedDistance& ud = p.geometry;
  ud = UndeformedDistance{};
  if (pc.ipotcn < 0) {
    c.forbid("geometry", "a Hertzian grid derives the undeformed distance itself");
    return;
  }
  Table t = c.table("geometry");
  const std::array<std::string_view, 4> kinds{"quadratic", "profile", "sines", "per_element_mm"};
  std::string_view kind;
  for (std::string_view k : kinds) {
    if (!t.has(k)) continue;
    if (!kind.empty()) t.fail_key(k, fmt::format("give only one of {}", fmt::join(kinds, ", ")));
    kind = k;
  }
  if (kind.empty())
    t.fail(fmt::format("missing the undeformed distance: one of {}", fmt::join(kinds, ", ")));
  if (kind == "quadratic") {
    ud.ibase = 1;
    ud.coeffs = t.reals("quadratic", 6);
  } else if (kind == "sines") {
    ud.ibase = 3;
    ud.coeffs = t.reals("sines", 8);
    if (ud.coeffs[6] == 0.0 || ud.coeffs[7] == 0.0)
      t.fail_key("sines",
                 "B7 and B8 must be non-zero (x²/B7 + y²/B8; a large value gives a flat "
                 "direction)");
  } else if (kind == "per_element_mm") {
    ud.ibase = 9;
    ud.values = t.reals("per_element_mm", element_count(pc));
  } else {
    ud.ibase = 2;
    Table pr = t.table("profile");
    ud.coeffs = pr.reals("heights_mm");
    if (ud.coeffs.size() < 2) pr.fail_key("heights_mm", "needs at least 2 values");
    ud.y1 = pr.real("y_first_mm");
    ud.dy1 = pr.real("y_step_mm");
    require_positive(pr, "y_step_mm", ud.dy1);
    ud.xm = pr.real_or("x_centre_mm", 0.0);
    ud.rm = pr.real("x_radius_mm");
    if (ud.rm == 0.0)
      pr.fail_key("x_radius_mm", "0: must be non-zero (a large radius gives a flat x-profile)");
    pr.finish();
  }
  ud.iplan = 1;
  if (auto pl = t.opt_table("planform")) {
    const auto quad = pl->opt_reals("quadratic", 6);
    const auto two = pl->opt_real_rows("two_rectangles", 4);
    const auto patches = pl->opt_real_rows("patches", 4);
    if ((quad ? 1 : 0) + (two ? 1 : 0) + (patches ? 1 : 0) != 1)
      pl->fail("give one of quadratic, two_rectangles, patches");
    if (quad) {
      ud.iplan = 2;
      ud.planform = *quad;
    } else if (two) {
      ud.iplan = 3;
      if (two->size() != 2) pl->fail_key("two_rectangles", "needs exactly 2 rectangles");
      static constexpr std::array<std::string_view, 4> kLim{"xl", "xh", "yl", "yh"};
      for (std::size_t r = 0; r < 2; ++r) {
        const auto& rect = (*two)[r];
        for (std::size_t k = 0; k < 4; k += 2)
          if (rect[k] > rect[k + 1])
            pl->fail_key("two_rectangles",
                         fmt::format("rectangle {}: {} = {} exceeds {} = {}", r + 1, kLim[k],
                                     rect[k], kLim[k + 1], rect[k + 1]));
        ud.planform.insert(ud.planform.end(), rect.begin(), rect.end());
      }
    } else {
      ud.iplan = 4;
      if (patches->empty() || patches->size() > 9999)
        pl->fail_key("patches", "needs 1..9999 rectangles");
      ud.npatch = static_cast<int>(patches->size());
      for (const auto& rect : *patches)
        ud.planform.insert(ud.planform.end(), rect.begin(), rect.end());
      const std::size_t n = patches->size();
      const std::size_t nfac = n * (n - 1) / 2;
      if (nfac > 0) {
        ud.patch_factors = pl->reals("factors", nfac);
      } else {
        pl->forbid("factors", "needs at least 2 patches");
      }
    }
    if (!patches) pl->forbid("factors", "only with patches");
    pl->finish();
  }
  t.finish();
}

void read_output(Table& c, CaseRecord& p) {
  ControlDigits& d = p.digits;
  if (auto t = c.opt_table("output")) {
    d.o = t->integer_in("report_level", d.o, 0, 5);
    d.a = t->choice_or("mat_file", schema::mat_file, d.a);
    d.w = t->integer_in("trace_level", d.w, 0, 9);
    t->finish();
  }
  d.x = 0;
  d.debug = DebugDigits{};
  if (auto t = c.opt_table("debug")) {
    d.x = 1;
    d.debug.p = t->integer_in("profiles", 0, 0, 9);
    d.debug.s = t->integer_in("smoothing", 0, 0, 9);
    d.debug.f = t->integer_in("force_loop", 0, 0, 9);
    d.debug.l = t->integer_in("contact_search", 0, 0, 9);
    d.debug.c = t->integer_in("patches", 0, 0, 9);
    d.debug.i = t->integer_in("influence", 0, 0, 9);
    d.debug.n = t->integer_in("solver", 0, 0, 9);
    d.debug.readln = t->integer_or("input_echo", 0);
    t->finish();
  }
}

void read_damping(Table& c, CaseRecord& p) {
  p.damping = Damping{};
  p.digits.m2 = 0;
  auto t = c.opt_table("damping");
  if (!t) return;
  p.digits.m2 = 2;
  p.damping.enabled = true;
  p.damping.cdampn = t->real_or("normal_time_s", 0.0);
  p.damping.cdampt = t->real_or("tangential_time_s", 0.0);
  p.damping.dfnmax = t->real_or("max_normal_force_rate_N_per_s", 0.0);
  p.damping.dftmax = t->real_or("max_tangential_force_rate_N_per_s", 0.0);
  t->finish();
}

namespace {

void read_heat_body(Table& t, std::string_view key, double& temp, double& cp, double& lambda,
                    double& dens) {
  Table b = t.table(key);
  temp = b.real("temperature_C");
  cp = b.real("heat_capacity_J_per_kg_C");
  lambda = b.real("conductivity_W_per_mm_C");
  dens = b.real("density_kg_per_mm3");
  b.finish();
}

}  // namespace

void read_heat(Table& c, CaseRecord& p) {
  p.digits.h = 0;
  auto t = c.opt_table("heat");
  if (!t) return;
  p.digits.h = 3;
  HeatParameters& h = p.heat;
  read_heat_body(*t, "body1", h.bktemp1, h.heatcp1, h.lambda1, h.dens1);
  read_heat_body(*t, "body2", h.bktemp2, h.heatcp2, h.lambda2, h.dens2);
  if (p.digits.m == 4) {
    h.betapl = t->real_or("plastic_heat_fraction", 0.0);
    if (!(h.betapl >= 0.0 && h.betapl <= 1.0))
      t->fail_key("plastic_heat_fraction", fmt::format("{} outside [0, 1]", h.betapl));
  } else {
    t->forbid("plastic_heat_fraction", "only with material.model = \"interfacial_layer\"");
  }
  if (p.digits.t != 3 && p.digits.t != 0)
    t->fail("temperature calculation requires steady rolling (T=3) or no tangential problem");
  t->finish();
}

namespace {

SubsurfaceBlock read_subsurface_block(Table& b) {
  SubsurfaceBlock s;
  auto count = [&](std::string_view key, std::size_t n) {
    if (n < 1 || n > static_cast<std::size_t>(kMaxSubsurfaceCount))
      b.fail_key(key, fmt::format("needs 1..{} values, not {}", kMaxSubsurfaceCount, n));
  };
  const bool points = b.has("x_mm") || b.has("y_mm");
  const bool ranges = b.has("columns") || b.has("rows");
  const bool lists = b.has("column_list") || b.has("row_list");
  if ((points ? 1 : 0) + (ranges ? 1 : 0) + (lists ? 1 : 0) > 1)
    b.fail("give one selection: columns/rows, column_list/row_list, or x_mm/y_mm");
  const bool z_list = b.has("z_mm");
  const bool z_range = b.has("z_first_mm") || b.has("z_step_mm") || b.has("z_count");
  if (z_list == z_range) b.fail("give either z_mm or z_first_mm, z_step_mm, z_count");
  if (points && !z_list) b.fail("points x_mm, y_mm need the depths as z_mm");
  if (points) {
    s.isubs = 9;
    s.x = b.reals("x_mm");
    s.y = b.reals("y_mm");
    count("x_mm", s.x.size());
    count("y_mm", s.y.size());
  } else if (ranges) {
    s.isubs = z_list ? 6 : 2;
    const auto cols = b.opt_integers("columns");
    const auto rows = b.opt_integers("rows");
    if (!cols || cols->size() != 3) b.fail("columns needs [first, step, last]");
    if (!rows || rows->size() != 3) b.fail("rows needs [first, step, last]");
    s.ixl = (*cols)[0];
    s.ixinc = (*cols)[1];
    s.ixh = (*cols)[2];
    s.iyl = (*rows)[0];
    s.iyinc = (*rows)[1];
    s.iyh = (*rows)[2];
    if (s.ixinc < 1 || s.ixinc > kMaxSubsurfaceCount) b.fail_key("columns", "step outside 1..9999");
    if (s.iyinc < 1 || s.iyinc > kMaxSubsurfaceCount) b.fail_key("rows", "step outside 1..9999");
  } else if (lists) {
    s.isubs = z_list ? 7 : 3;
    const auto ix = b.opt_integers("column_list");
    const auto iy = b.opt_integers("row_list");
    if (!ix || !iy) b.fail("column_list and row_list go together");
    count("column_list", ix->size());
    count("row_list", iy->size());
    s.ix = *ix;
    s.iy = *iy;
    for (auto* list : {&s.ix, &s.iy}) {
      std::sort(list->begin(), list->end());
      list->erase(std::unique(list->begin(), list->end()), list->end());
    }
  } else {
    s.isubs = z_list ? 5 : 1;
  }
  if (z_list) {
    s.z = b.reals("z_mm");
    count("z_mm", s.z.size());
  } else {
    const int nz = b.integer("z_count");
    count("z_count", static_cast<std::size_t>(std::max(nz, 0)));
    s.zl = b.real("z_first_mm");
    s.dz = b.real("z_step_mm");
    require_positive(b, "z_step_mm", s.dz);
    s.z.resize(static_cast<std::size_t>(nz));
    for (std::size_t k = 0; k < s.z.size(); ++k) s.z[k] = s.zl + static_cast<double>(k) * s.dz;
  }
  for (auto* list : {&s.x, &s.y, &s.z}) std::sort(list->begin(), list->end());
  b.finish();
  return s;
}

}  // namespace

void read_subsurface(Table& c, CaseRecord& p) {
  p.digits.s = 0;
  p.subsurface = Subsurface{};
  auto t = c.opt_table("subsurface");
  if (!t) return;
  p.digits.s = 3;
  p.subsurface.matfil = t->choice_or("mat_file", schema::subsurface_file, 0);
  p.subsurface.output = t->integer_in("report", 0, 0, 4);
  std::vector<Table> blocks = t->tables("block");
  if (blocks.size() > static_cast<std::size_t>(kMaxSubsurfaceBlocks))
    t->fail_key("block", fmt::format("more than {} blocks", kMaxSubsurfaceBlocks));
  for (Table& b : blocks) p.subsurface.blocks.push_back(read_subsurface_block(b));
  t->finish();
}

/// Checks that need the grid: per-element arrays and friction rows.
void check_grid_sizes(Table& c, const CaseRecord& p) {
  const std::size_t n = element_count(p.potential);
  const Kinematics& k = p.kinematics;
  if (k.extra_slip_mode == 9 && k.extra_slip.size() != 2 * n) {
    Table t = c.table("tangential");
    t.fail_key("extra_slip_per_element",
               fmt::format("needs 2·MX·MY = {} values (wx, wy per element), not {}", 2 * n,
                           k.extra_slip.size()));
  }
  if (p.digits.v == 3 && p.friction.rows.size() != static_cast<std::size_t>(p.potential.my)) {
    Table t = c.table("friction");
    t.fail_key("rows", fmt::format("needs one entry per grid row (MY = {}), not {}", p.potential.my,
                                   p.friction.rows.size()));
  }
}

}  // namespace rollcontact::format::toml_input
