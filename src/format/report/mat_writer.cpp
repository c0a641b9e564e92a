#include "format/report/mat_writer.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstddef>
#include <initializer_list>
#include <string_view>
#include <utility>
#include <vector>

#include "format/inp/to_wheelrail.hpp"
#include "format/report/number_format.hpp"
#include "format/report/report_values.hpp"
#include "format/text/atomic_file.hpp"

namespace rollcontact::format {

namespace {

constexpr int kWidth = 14;  // every column; the two leading integers share the first one

/// g14.6, CONTACT's number column.
std::string g14(double v) {
  return fortran_g(v, kWidth, 6);
}

/// `i6,8x`: an integer in a 14-wide column, left part.
std::string i6x8(long long v) {
  return fortran_i(v, 6) + std::string(8, ' ');
}

/// `i7,1x,i4,2x`: the two leading integers of a row.
std::string two_ints(long long a, long long b) {
  return fortran_i(a, 7) + " " + fortran_i(b, 4) + "  ";
}

/// Names each followed by a number of blanks, as in CONTACT's Fortran formats ('GG1',11x, ...).
std::string names(std::initializer_list<std::pair<std::string_view, int>> items) {
  std::string s;
  for (const auto& [name, blanks] : items) {
    s += name;
    s += std::string(static_cast<std::size_t>(blanks), ' ');
  }
  return s;
}

/// A comment line: fixed names (each with its trailing blanks), then `count` filler markers
/// `  -` separated by 11 blanks (Fortran `(a3,:,11x)`: no blanks after the last one), then
/// `last` when not empty. Without markers the trailing blanks of the names are not written
/// (Fortran X editing does not extend a record).
std::string comment_line(std::string text, int count, std::string_view last = {}) {
  std::vector<std::string> items(static_cast<std::size_t>(std::max(0, count)), "  -");
  if (!last.empty()) items.emplace_back(last);
  if (items.empty()) {
    while (!text.empty() && text.back() == ' ') text.pop_back();
    return text;
  }
  for (std::size_t k = 0; k < items.size(); ++k) {
    if (k > 0) text += std::string(11, ' ');
    text += items[k];
  }
  return text;
}

/// `count` zero columns (g14.6), for the columns beyond a line's own values.
std::string zeros(int count) {
  std::string s;
  for (int k = 0; k < count; ++k) s += g14(0.0);
  return s;
}

/// Column names after I and IGS, in the order the values are written.
std::vector<std::string> value_columns(bool rolling, bool plastic, bool heat) {
  std::vector<std::string> c{
      "H", "MU", "PN", "PX", "PY", "UN", "UX", "UY", rolling ? "SREL" : "SHFT"};
  if (plastic) c.insert(c.end(), {"TAUCRT", "UPLSX", "UPLSY"});
  if (heat) c.insert(c.end(), {"TEMP1", "TEMP2"});
  return c;
}

void material_lines(std::string& out, const CaseRecord& problem, const SimplifiedReport& simp,
                    int ncol) {
  const ControlDigits& d = problem.digits;
  const Materials& m = problem.materials;
  const auto& mp = m.model_params;
  const std::string lead =
      names({{"%    T", 4}, {"M", 6}, {"GG1", 11}, {"GG2", 11}, {"POISS1", 8}});
  std::string head;
  std::string values = two_ints(d.t, d.m) + g14(m.gg1) + g14(m.gg2) + g14(m.poiss1);
  if (d.m == 0) {
    head = comment_line(lead + names({{"POISS2", 8}}), ncol - 6);
    values += g14(m.poiss2) + zeros(ncol - 6);
  } else if (d.m == 1) {
    head = comment_line(
        lead + names({{"POISS2", 8}, {"FG1", 11}, {"FG2", 11}, {"TC1", 11}, {"TC2", 11}}),
        ncol - 10);
    values += g14(m.poiss2);
    for (const double v : mp) values += g14(v);
    values += zeros(ncol - 10);
  } else if (d.m == 4) {
    head = comment_line(
        lead + names({{"POISS2", 8}, {"GG3", 11}, {"LAYTHK", 8}, {"TAU_C0", 8}, {"K_TAU", 9}}),
        ncol - 10);
    values += g14(m.poiss2);
    for (const double v : mp) values += g14(v);
    values += zeros(ncol - 10);
  } else {
    // M=2,3,5-7 (simplified theories): POISS2 is skipped for lack of columns, as in CONTACT.
    // M=2 gives one flexibility for all three directions; M=3,5 derive them in the solver:
    // the effective ones it used where the case was solved, zeros otherwise.
    head = comment_line(lead + names({{"FLX1", 10},
                                      {"FLX2", 10},
                                      {"FLX3", 10},
                                      {"K0_MF", 9},
                                      {"ALFAMF", 8},
                                      {"BETAMF", 8}}),
                        ncol - 11);
    const double flx = d.m == 2 ? mp[0] : 0.0;
    const bool solved = d.m != 2 && simp.present;
    const std::size_t k0 = d.m == 2 ? 1 : 0;
    values += g14(solved ? simp.flx1 : flx) + g14(solved ? simp.flx2 : flx) +
              g14(solved ? simp.flx3 : flx) + g14(mp[k0]) + g14(mp[k0 + 1]) + g14(mp[k0 + 2]) +
              zeros(ncol - 11);
  }
  out += head + "\n" + values + "\n";
}

void friction_lines(std::string& out, const CaseRecord& problem, double veloc, int ncol) {
  const Friction& f = problem.friction;
  const int law = f.law;
  const std::string lead = names({{"%    L", 4}, {"H", 6}, {"VELOC", 9}});
  std::string head;
  std::string values = two_ints(law, problem.digits.h) + g14(veloc);
  if (law == 0) {
    head = comment_line(lead + names({{"FSTAT", 9}, {"FKIN", 10}}), ncol - 5);
    values += g14(f.fstat) + g14(f.fkin) + zeros(ncol - 5);
  } else if (law == 6) {
    head = comment_line(lead + names({{"FREF", 10},
                                      {"TREF", 10},
                                      {"DFHEAT", 8},
                                      {"DTHEAT", 8},
                                      {"MEMDST", 8},
                                      {"MEM_S0", 8}}),
                        ncol - 10);
    values += g14(f.fkin) + g14(f.params[0]) + g14(f.params[1]) + g14(f.params[2]) + g14(f.memdst) +
              g14(f.mem_s0);
    // CONTACT pads this line with one zero more than the others (zeros j=10..ncol).
    values += zeros(ncol - 8);
  } else {
    const std::string_view p = law == 2 ? "FLIN" : law == 3 ? "FRAT" : "FEXP";
    head = comment_line(lead + names({{"FKIN", 10},
                                      {fmt::format("{}1", p), 9},
                                      {"SABSH1", 8},
                                      {fmt::format("{}2", p), 9},
                                      {"SABSH2", 8},
                                      {"MEMDST", 8},
                                      {"MEM_S0", 8}}),
                        ncol - 10);
    values += g14(f.fkin);
    for (const double v : f.params) values += g14(v);
    values += g14(f.memdst) + g14(f.mem_s0) + zeros(ncol - 10);
  }
  out += head + "\n" + values + "\n";
}

/// Local friction coefficient of grid row iy: the V=3 row value or the single set. The
/// Solution has no per-element μ; the solvers that produce .mat files use Coulomb friction.
double row_friction(const Friction& f, int iy) {
  const auto row = static_cast<std::size_t>(iy);
  return row < f.rows.size() ? f.rows[row].fkin : f.fkin;
}

double at(const std::vector<double>& v, std::size_t i) {
  return i < v.size() ? v[i] : 0.0;
}

}  // namespace

std::string mat_file_text(const CaseRecord& problem, const Solution& solution,
                          const MatWheelRailContext* wheel_rail) {
  const MatWheelRailContext none;
  const MatWheelRailContext& wr = wheel_rail != nullptr ? *wheel_rail : none;
  const ControlDigits& d = problem.digits;
  const Grid& grid = solution.grid;
  const EffectiveKinematics ek = effective_kinematics(solution);
  const bool rolling = d.t == 2 || d.t == 3;
  const bool plastic = uses_plasticity(problem);
  const bool heat = d.h >= 1;
  const std::vector<std::string> columns = value_columns(rolling, plastic, heat);
  const int ncol = static_cast<int>(columns.size()) + 2;

  std::string out;
  // 1: metadata of the wheel/rail configuration (module 3: zeros) and the format version.
  out += comment_line(names({{"%  TIM", 11},
                             {"S_WS(FC)", 6},
                             {"TH_WS(FC)", 5},
                             {"Y_R(TR)", 7},
                             {"Z_R(TR)", 7},
                             {"ROLL_R(TR)", 4},
                             {"RNOM_ROL", 6}}),
                      ncol - 8, "FMT") +
         "\n";
  for (const double v : {0.0, wr.s_ws, wr.pitch_ws, wr.y_r, wr.z_r, wr.roll_r, wr.rnom_rol})
    out += g14(v);
  for (int j = 8; j <= ncol - 1; ++j) out += i6x8(0);
  out += fortran_i(kMatFormatVersion, 6) + "\n";
  out += comment_line(names({{"%  X_W(TR)", 7},
                             {"Y_W(TR)", 7},
                             {"Z_W(TR)", 7},
                             {"ROLL_W(TR)", 4},
                             {"YAW_W(TR)", 5},
                             {"RNOM_WHL", 6}}),
                      ncol - 7) +
         "\n";
  for (const double v : {wr.x_w, wr.y_w, wr.z_w, wr.roll_w, wr.yaw_w, wr.rnom_whl}) out += g14(v);
  out += zeros(ncol - 6) + "\n";
  // 2: contact reference position (module 3: zeros), patch numbers, spin centre.
  out += comment_line(names({{"%  X_CP(R)", 7},
                             {"Y_CP(R)", 7},
                             {"Z_CP(R)", 7},
                             {"DELT_CP(R)", 4},
                             {"X_CP(W)", 7},
                             {"Y_CP(W)", 7},
                             {"Z_CP(W)", 7},
                             {"NPATCH", 8},
                             {"IPATCH", 8},
                             {"SPINXO", 8},
                             {"SPINYO", 8}}),
                      ncol - 9) +
         "\n";
  for (const double v :
       {wr.x_cp_r, wr.y_cp_r, wr.z_cp_r, wr.delt_cp_r, wr.x_cp_w, wr.y_cp_w, wr.z_cp_w})
    out += g14(v);
  out += i6x8(wr.npatch) + i6x8(wr.ipatch) + g14(problem.kinematics.spinxo) +
         g14(problem.kinematics.spinyo) + zeros(ncol - 11) + "\n";
  // 3: grid. C1 is the (ignored) configuration digit of module 3, 0; the module-1 D digit keeps
  // CONTACT's initial value 2 in module 3.
  out += comment_line(names({{"%   MX", 4},
                             {"MY", 5},
                             {"XL", 12},
                             {"YL", 12},
                             {"DX", 12},
                             {"DY", 12},
                             {"CHI", 11},
                             {"DQ", 12},
                             {"C1", 12},
                             {"D", 13},
                             {"YNOM_WHL", 5}}),
                      ncol - 11) +
         "\n";
  const double yl = wr.left ? -(grid.yl + grid.my * grid.dy) : grid.yl;
  out += two_ints(grid.mx, grid.my) + g14(grid.xl) + g14(yl) + g14(grid.dx) + g14(grid.dy) +
         g14(ek.chi) + g14(ek.dq) + i6x8(wr.c1) + i6x8(wr.d) + g14(wr.ynom_whl) + zeros(ncol - 11) +
         "\n";
  // 4, 5: material and friction parameters.
  material_lines(out, problem, solution.simplified, ncol);
  friction_lines(out, problem, ek.veloc, ncol);
  // Column header and one row per element.
  std::string header = "%    I    IGS ";
  for (const std::string& c : columns) header += "   " + fmt::format("{:<11}", c);
  out += header + "\n";

  const bool all = d.a >= 2;
  const double lateral = wr.left ? -1.0 : 1.0;  // PY, UY of a left wheel's mirrored fields
  for (int iy = 0; iy < grid.my; ++iy) {
    const int source_iy = wr.left ? grid.my - 1 - iy : iy;
    for (int ix = 0; ix < grid.mx; ++ix) {
      const std::size_t i = grid.index(ix, source_iy);
      const auto state = i < solution.state.size() ? solution.state[i] : ElementState::Exterior;
      if (!all && state == ElementState::Exterior) continue;
      // Appended number by number: a .mat file of a long sequence holds millions of them.
      out += two_ints(static_cast<long long>(grid.index(ix, iy)) + 1, static_cast<int>(state));
      const double srel = std::hypot(at(solution.sx, i), at(solution.sy, i));
      // The local μ: the velocity-dependent value where the solver had one.
      const double mu =
          i < solution.mu.size() ? solution.mu[i] : row_friction(problem.friction, source_iy);
      for (const double v : {at(solution.h, i), mu, at(solution.pn, i), at(solution.px, i),
                             lateral * at(solution.py, i), at(solution.un, i), at(solution.ux, i),
                             lateral * at(solution.uy, i), srel})
        append_fortran_g(out, v, kWidth, 6);
      int filled = 11;
      if (plastic) {
        for (const double v : {at(solution.yield_limit, i), at(solution.plastic_x, i),
                               lateral * at(solution.plastic_y, i)})
          append_fortran_g(out, v, kWidth, 6);
        filled += 3;
      }
      if (heat) {  // surface temperatures [°C] (0 where a solution has none)
        append_fortran_g(out, at(solution.temp1, i), kWidth, 6);
        append_fortran_g(out, at(solution.temp2, i), kWidth, 6);
        filled += 2;
      }
      for (int k = filled; k < ncol; ++k)  // none left: the columns are the header's
        append_fortran_g(out, 0.0, kWidth, 6);
      out += '\n';
    }
  }
  return out;
}

std::filesystem::path mat_file_path(const std::filesystem::path& output_stem, int case_number) {
  std::filesystem::path p = output_stem;
  p += fmt::format(".{:04d}.mat", case_number);
  return p;
}

std::filesystem::path write_mat_file(const std::filesystem::path& output_stem,
                                     const CaseRecord& problem, const Solution& solution) {
  const std::filesystem::path path = mat_file_path(output_stem, problem.case_number);
  write_file_atomically(path, mat_file_text(problem, solution));
  return path;
}

}  // namespace rollcontact::format

namespace rollcontact::format {

std::vector<std::filesystem::path> write_wheelrail_mat_files(
    const std::filesystem::path& output_stem, const WheelRailRecord& record,
    const CaseRecord& identity, const WheelRailSolution& solution) {
  const CaseRecord patch = settings_record(record);
  MatWheelRailContext wr;
  const WheelsetMotion& m = record.motion;
  wr.s_ws = m.s;
  wr.pitch_ws = m.pitch;
  wr.y_r = solution.rail_marker_tr.position.y;
  wr.z_r = solution.rail_marker_tr.position.z;
  wr.roll_r = solution.rail_marker_tr.roll_rad;
  wr.x_w = solution.wheel_marker_tr.position.x;
  wr.y_w = solution.wheel_marker_tr.position.y;
  wr.z_w = solution.wheel_marker_tr.position.z;
  wr.roll_w = solution.wheel_marker_tr.roll_rad;
  wr.yaw_w = solution.wheel_marker_tr.yaw_rad;
  wr.rnom_whl = record.wheelset.nomradw;
  wr.npatch = static_cast<int>(solution.patches.size());
  wr.c1 = record.config;
  wr.d = record.discretisation.method;
  wr.ynom_whl = record.wheelset.ytape;
  wr.left = record.is_left();
  std::vector<std::filesystem::path> written;
  for (std::size_t k = 0; k < solution.patches.size(); ++k) {
    const WheelRailPatch& w = solution.patches[k];
    wr.ipatch = static_cast<int>(k) + 1;
    wr.x_cp_r = w.reference_tr.x;
    wr.y_cp_r = w.y_rail_mm;
    wr.z_cp_r = w.z_rail_mm;
    wr.delt_cp_r = w.delta_rail_rad;
    wr.x_cp_w = w.reference_wheel.x;
    wr.y_cp_w = w.reference_wheel.y;
    wr.z_cp_w = w.reference_wheel.z;
    std::filesystem::path path = output_stem;
    path += fmt::format(".{:04d}{}.mat", identity.case_number, static_cast<char>('a' + k % 26));
    write_file_atomically(path, mat_file_text(patch, w.solution, &wr));
    written.push_back(path);
  }
  return written;
}

}  // namespace rollcontact::format
