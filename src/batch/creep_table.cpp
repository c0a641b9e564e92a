// The creep-force table of Vollebregt et al. (VSD 2012): case enumeration, problems, parallel
// solution and CSV. See creep_table.hpp.

#include "batch/creep_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <istream>
#include <numbers>
#include <ostream>
#include <sstream>

#include "batch/parallel.hpp"
#include "geometry/hertz.hpp"
#include "rollcontact/errors.hpp"
#include "simplified/flexibility.hpp"
#include "simplified/kalker_coefficients.hpp"

namespace rollcontact::batch {

namespace {

// The parameter grid of the paper (section 4).
constexpr std::array<double, 5> ellipticities{0.2, 0.5, 1.0, 2.0, 5.0};
constexpr std::array<double, 5> semi_axes_a{4.0, 6.0, 9.0, 12.0, 20.0};  // [mm], per a/b
constexpr std::array<double, 4> spins{0.0, 0.5, 1.0, 2.0};
constexpr std::array<double, 7> angles{-90.0, -60.0, -30.0, 0.0, 30.0, 60.0, 90.0};  // [deg]
constexpr std::array<double, 23> magnitudes{0.0, 0.1, 0.2, 0.3, 0.4, 0.5,  0.7, 0.9,
                                            1.1, 1.4, 1.7, 2.0, 2.5, 3.0,  3.5, 4.0,
                                            5.0, 6.0, 7.0, 8.0, 9.0, 10.0, 12.0};
static_assert(ellipticities.size() * spins.size() * angles.size() * magnitudes.size() ==
              table_case_count);

constexpr const char* header =
    "case,a_over_b,spin,angle_deg,magnitude,fx_rel,fy_rel,mz_rel,slip_percent,converged";

}  // namespace

TableMethod parse_table_method(const std::string& name) {
  if (name == "exact") return TableMethod::Exact;
  if (name == "fastsim1") return TableMethod::Fastsim1;
  if (name == "fastsim3") return TableMethod::Fastsim3;
  if (name == "fastrip") return TableMethod::FaStrip;
  throw InputError("--method", 0, "unknown method (exact, fastsim1, fastsim3, fastrip)", name);
}

std::string table_method_name(TableMethod method) {
  switch (method) {
    case TableMethod::Exact:
      return "exact";
    case TableMethod::Fastsim1:
      return "fastsim1";
    case TableMethod::Fastsim3:
      return "fastsim3";
    case TableMethod::FaStrip:
      return "fastrip";
  }
  return "?";
}

int effective_bound(const TableSettings& s) {
  if (s.bound >= 0) return s.bound;
  return s.method == TableMethod::Exact ? 0 : 2;
}

std::vector<TableCase> table_cases() {
  std::vector<TableCase> cases;
  cases.reserve(table_case_count);
  for (std::size_t ie = 0; ie < ellipticities.size(); ++ie)
    for (double spin : spins)
      for (double angle : angles)
        for (double m : magnitudes) {
          TableCase tc;
          tc.number = static_cast<int>(cases.size()) + 1;
          tc.a_over_b = ellipticities[ie];
          tc.a = semi_axes_a[ie];
          tc.b = tc.a / tc.a_over_b;
          tc.spin = spin;
          tc.angle_deg = angle;
          tc.magnitude = m;
          cases.push_back(tc);
        }
  return cases;
}

TableCreepages table_creepages(const TableCase& tc) {
  const double estar = table_g / (1.0 - table_nu);
  const HertzReport hz =
      geometry::hertz_from_semiaxes(tc.a, tc.b, geometry::HertzLoad::Force, table_fn, estar);
  TableCreepages cr;
  cr.rho = hz.rho;
  cr.c = std::sqrt(tc.a * tc.b);
  const double theta = tc.angle_deg * std::numbers::pi / 180.0;
  const double scale = tc.magnitude * table_mu * cr.c / cr.rho;
  // cos(±90°) is 6e-17, not 0: snap so that pure lateral cases have exactly ξ = 0.
  const double cs = std::abs(tc.angle_deg) == 90.0 ? 0.0 : std::cos(theta);
  cr.cksi = scale * cs;
  cr.ceta = scale * std::sin(theta);
  cr.cphi = table_mu * tc.spin / cr.rho;
  return cr;
}

model::PatchProblem table_problem(const TableCase& tc, const TableSettings& s) {
  if (s.mx < 5) throw InputError("--mx", 0, fmt::format("must be at least 5, got {}", s.mx));
  const TableCreepages cr = table_creepages(tc);
  model::PatchProblem p;
  // Every case on its own: results independent of the order of solution.
  p.sequence.continue_previous = false;
  const int bound = effective_bound(s);
  p.normal.pressure = bound == 2   ? model::PressureModel::EllipticHertzian
                      : bound == 3 ? model::PressureModel::ParabolicHertzian
                                   : model::PressureModel::ExactHalfSpace;
  p.normal.kind = model::NormalLoadKind::Force;
  p.normal.force_N = table_fn;
  p.tangential.kind = model::TangentialKind::SteadyRolling;
  p.tangential.prescribed = model::TangentialPrescribed::Creepages;
  p.tangential.creepage = {cr.cksi, cr.ceta, cr.cphi};
  p.solver.tolerance = s.eps;
  p.rolling.velocity_mm_per_s = table_veloc;
  p.rolling.direction_rad = 0.0;
  p.friction = {table_mu, table_mu};
  p.bodies.body1 = p.bodies.body2 = {table_nu, table_g};
  p.potential.ipotcn = -3;
  p.potential.mx = p.potential.my = s.mx;
  // mx − 4 elements over each axis of the Hertz ellipse, two free columns/rows on either side.
  const double scale = static_cast<double>(s.mx) / static_cast<double>(s.mx - 4);
  p.potential.values = {tc.a, tc.b, scale, 0.0};
  // Steady rolling on the contact-fixed grid: one element per step.
  p.rolling.step_mm = 2.0 * scale * tc.a / s.mx;
  // No slope reduction of Modified Fastsim: k0 = α∞ = β = 1.
  switch (s.method) {
    case TableMethod::Exact:
      p.bodies.compliance = model::TangentialCompliance::ExactHalfSpace;
      break;
    case TableMethod::Fastsim1: {
      p.bodies.compliance = model::TangentialCompliance::FastsimOneFlexibility;
      const auto coef = simplified::kalker_coefficients(tc.a_over_b, table_nu);
      const auto l = simplified::kalker_flexibilities({tc.a, tc.b}, coef, table_g);
      // One flexibility for all three creepages: the plain mean of Kalker's L1, L2, L3.
      p.bodies.simplified = {(l.l1 + l.l2 + l.l3) / 3.0, 1.0, 1.0, 1.0};
      break;
    }
    case TableMethod::Fastsim3:
    case TableMethod::FaStrip:
      p.bodies.compliance = s.method == TableMethod::Fastsim3
                                ? model::TangentialCompliance::FastsimThreeFlexibilities
                                : model::TangentialCompliance::FaStrip;
      p.bodies.simplified = {0.0, 1.0, 1.0, 1.0};
      break;
  }
  return p;
}

TableRow solve_table_case(const TableCase& tc, const TableSettings& s, PatchSolver& solver) {
  TableRow row;
  row.tc = tc;
  try {
    const model::PatchProblem p = table_problem(tc, s);
    const Solution sol = solver.solve(p);
    const double mufn = table_mu * sol.totals.fn;
    const double c = std::sqrt(tc.a * tc.b);
    row.fx_rel = sol.totals.fx / mufn;
    row.fy_rel = sol.totals.fy / mufn;
    row.mz_rel = sol.totals.mz / (mufn * c);
    row.slip_percent =
        sol.statistics.ncon > 0 ? 100.0 * sol.statistics.nslip / sol.statistics.ncon : 0.0;
    row.converged = sol.solver.converged;
    row.message = sol.solver.message;
  } catch (const Error& e) {
    // A failing case must stay visible in the table, not abort the other 3219.
    row.fx_rel = row.fy_rel = row.mz_rel = row.slip_percent = std::nan("");
    row.converged = false;
    row.message = e.what();
  }
  return row;
}

std::vector<TableRow> run_table(std::span<const TableCase> cases, const TableSettings& s,
                                int threads, const std::function<void(std::size_t)>& progress) {
  const std::size_t n = cases.size();
  std::vector<TableRow> rows(n);
  if (n == 0) return rows;
  // One PatchSolver per worker; cyclic order: neighbouring cases (same ellipse, same grid) on
  // different workers, so every worker keeps its cached operators for 644 cases in a row.
  std::vector<PatchSolver> solvers(worker_count(n, threads));
  parallel_for(
      n, {threads, Schedule::Cyclic},
      [&](std::size_t worker, std::size_t i) {
        rows[i] = solve_table_case(cases[i], s, solvers[worker]);
      },
      progress);
  return rows;
}

std::string encode_table_row(const TableRow& row) {
  const double values[4] = {row.fx_rel, row.fy_rel, row.mz_rel, row.slip_percent};
  std::string bytes(sizeof values + 1, '\0');
  std::memcpy(bytes.data(), values, sizeof values);
  bytes[sizeof values] = row.converged ? '1' : '0';
  return bytes + row.message;
}

TableRow decode_table_row(const std::string& bytes, const TableCase& tc) {
  double values[4];
  if (bytes.size() < sizeof values + 1)
    throw Error(fmt::format("table case {}: truncated result from another process", tc.number));
  std::memcpy(values, bytes.data(), sizeof values);
  TableRow row;
  row.tc = tc;
  row.fx_rel = values[0];
  row.fy_rel = values[1];
  row.mz_rel = values[2];
  row.slip_percent = values[3];
  row.converged = bytes[sizeof values] == '1';
  row.message = bytes.substr(sizeof values + 1);
  return row;
}

std::vector<TableRow> run_table_distributed(std::span<const TableCase> cases,
                                            const TableSettings& s, Distribution& distribution) {
  PatchSolver solver;
  const std::vector<std::string> blobs = distribution.map_gather(
      cases.size(), default_chunk(cases.size(), distribution.size()),
      [&](std::size_t i) { return encode_table_row(solve_table_case(cases[i], s, solver)); });
  std::vector<TableRow> rows;
  rows.reserve(blobs.size());
  for (std::size_t i = 0; i < blobs.size(); ++i)
    rows.push_back(decode_table_row(blobs[i], cases[i]));
  return rows;
}

std::vector<int> parse_case_selection(const std::string& text, std::size_t total) {
  std::vector<int> out;
  if (text.empty()) {
    for (std::size_t i = 1; i <= total; ++i) out.push_back(static_cast<int>(i));
    return out;
  }
  auto number = [&](std::string_view item) {
    int v = 0;
    const auto r = std::from_chars(item.data(), item.data() + item.size(), v);
    if (item.empty() || r.ec != std::errc() || r.ptr != item.data() + item.size())
      throw InputError("--cases", 0, "expected a case number", std::string(item));
    if (v < 1 || static_cast<std::size_t>(v) > total)
      throw InputError("--cases", 0, fmt::format("case {} is outside 1..{}", v, total));
    return v;
  };
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    const auto dash = item.find('-');
    if (dash == std::string::npos) {
      out.push_back(number(item));
    } else {
      const std::string_view view(item);
      const int lo = number(view.substr(0, dash)), hi = number(view.substr(dash + 1));
      if (hi < lo) throw InputError("--cases", 0, "empty range", item);
      for (int v = lo; v <= hi; ++v) out.push_back(v);
    }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::string table_csv_header() {
  return header;
}

void write_table_csv(std::ostream& out, std::span<const TableRow> rows) {
  out << header << '\n';
  for (const TableRow& r : rows)
    out << fmt::format("{},{:g},{:g},{:g},{:g},{:.8g},{:.8g},{:.8g},{:.4f},{}\n", r.tc.number,
                       r.tc.a_over_b, r.tc.spin, r.tc.angle_deg, r.tc.magnitude, r.fx_rel, r.fy_rel,
                       r.mz_rel, r.slip_percent, r.converged ? 1 : 0);
}

std::vector<TableRow> read_table_csv(std::istream& in, const std::string& name) {
  std::string line;
  if (!std::getline(in, line)) throw InputError(name, 0, "empty file");
  if (!line.empty() && line.back() == '\r') line.pop_back();
  const std::string required(header, std::string_view(header).rfind(','));
  bool with_converged = false;
  if (line == header)
    with_converged = true;
  else if (line != required)
    throw InputError(name, 1, "expected the header '" + required + "[,converged]'");
  std::vector<TableRow> rows;
  int lineno = 1;
  const std::size_t ncol = with_converged ? 10 : 9;
  while (std::getline(in, line)) {
    ++lineno;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    std::vector<std::string_view> f;
    std::string_view rest(line);
    for (;;) {
      const auto comma = rest.find(',');
      f.push_back(rest.substr(0, comma));
      if (comma == std::string_view::npos) break;
      rest.remove_prefix(comma + 1);
    }
    if (f.size() != ncol)
      throw InputError(name, lineno, fmt::format("expected {} values, found {}", ncol, f.size()));
    std::array<double, 9> v{};
    for (std::size_t k = 0; k < 9; ++k) {
      const auto r = std::from_chars(f[k].data(), f[k].data() + f[k].size(), v[k]);
      if (f[k].empty() || r.ec != std::errc() || r.ptr != f[k].data() + f[k].size())
        throw InputError(name, lineno, "expected a number", std::string(f[k]));
    }
    TableRow row;
    row.tc.number = static_cast<int>(v[0]);
    row.tc.a_over_b = v[1];
    row.tc.spin = v[2];
    row.tc.angle_deg = v[3];
    row.tc.magnitude = v[4];
    row.fx_rel = v[5];
    row.fy_rel = v[6];
    row.mz_rel = v[7];
    row.slip_percent = v[8];
    if (with_converged) {
      if (f[9] != "0" && f[9] != "1")
        throw InputError(name, lineno, "converged must be 0 or 1", std::string(f[9]));
      row.converged = f[9] == "1";
    }
    rows.push_back(row);
  }
  return rows;
}

void check_table_settings(const TableSettings& s) {
  const int bound = effective_bound(s);
  if (bound != 0 && bound != 2 && bound != 3)
    throw InputError("--bound", 0, fmt::format("must be 0, 2 or 3, got {}", bound));
  if (s.mx < 5) throw InputError("--mx", 0, fmt::format("must be at least 5, got {}", s.mx));
}

std::vector<TableCase> select_table_cases(const std::string& selection) {
  const std::vector<TableCase> all = table_cases();
  std::vector<TableCase> cases;
  for (int number : parse_case_selection(selection, all.size()))
    cases.push_back(all[static_cast<std::size_t>(number - 1)]);
  return cases;
}

std::vector<TableRow> read_table_csv_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, 0, "cannot open the reference table");
  return read_table_csv(in, path);
}

}  // namespace rollcontact::batch
