// The element-division picture of the report (spec/outputs.md §3.5).

#include <fmt/format.h>

#include <algorithm>
#include <numbers>
#include <ostream>
#include <string>

#include "format/report/number_format.hpp"
#include "format/report/report_internal.hpp"
#include "format/report/report_writer.hpp"

namespace rollcontact::format {
namespace {

// Windows up to this many columns get a blank before every character (CONTACT's HlfCol as in
// the revision of the reference reports: 44 columns are spaced, 55 are not).
constexpr int max_spaced_columns = 46;

char state_char(ElementState s) {
  switch (s) {
    case ElementState::Adhesion:
      return '*';
    case ElementState::Slip:
      return 'S';
    case ElementState::Plastic:
      return '|';
    default:
      return '.';
  }
}

// Displayed index range [lo, hi] (1-based) along one axis: one element of margin around the
// contact, the whole grid when the contact nearly touches both edges, the middle when empty.
std::pair<int, int> window(int n, int cmin, int cmax) {
  if (cmin > cmax) return {std::max(1, n / 2 - 5), std::min(n, n / 2 + 5)};
  if (cmin <= 5 && cmax >= n - 4) return {1, n};
  return {std::max(1, cmin - 1), std::min(n, cmax + 1)};
}

std::string rtrim(std::string s) {
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return s;
}

}  // namespace

void write_element_division(std::ostream& os, const Solution& solution, int tangential_digit,
                            double chi) {
  const Grid& g = solution.grid;
  const int nx = g.mx, ny = g.my;
  if (nx <= 0 || ny <= 0 || solution.state.size() != g.size()) return;

  int ixmin = nx + 1, ixmax = 0, iymin = ny + 1, iymax = 0;
  for (int iy = 1; iy <= ny; ++iy) {
    for (int ix = 1; ix <= nx; ++ix) {
      if (solution.state[g.index(ix - 1, iy - 1)] == ElementState::Exterior) continue;
      ixmin = std::min(ixmin, ix);
      ixmax = std::max(ixmax, ix);
      iymin = std::min(iymin, iy);
      iymax = std::max(iymax, iy);
    }
  }
  const auto [ix0, ix1] = window(nx, ixmin, ixmax);
  const auto [iy0, iy1] = window(ny, iymin, iymax);
  const int ncols = ix1 - ix0 + 1;
  const bool spaced = ncols <= max_spaced_columns;

  auto append = [spaced](std::string& s, char c) {
    if (spaced) s += ' ';
    s += c;
  };
  for (int iy = iy1; iy >= iy0; --iy) {
    std::string row = fmt::format("{:6d}  ", iy);
    for (int ix = ix0; ix <= ix1; ++ix) {
      const ElementState s = solution.state[g.index(ix - 1, iy - 1)];
      const bool corner = (ix == ix0 || ix == ix1) && (iy == iy0 || iy == iy1);
      append(row, s == ElementState::Exterior && corner ? 'o' : state_char(s));
    }
    report::line(os, row);
  }

  // Column numbers: hundreds and tens only at their multiples, units everywhere.
  auto digit_row = [&](int unit) {
    std::string row(8, ' ');
    for (int ix = ix0; ix <= ix1; ++ix) {
      const bool show = unit == 1 || ix % unit == 0;
      append(row, show ? static_cast<char>('0' + (ix / unit) % 10) : ' ');
    }
    report::line(os, rtrim(row));
  };
  if (ncols >= 200) digit_row(100);
  if (ncols >= 10) digit_row(10);
  digit_row(1);

  if (tangential_digit == 2 || tangential_digit == 3) {
    report::line(os, "     X  -->        Chi=" + fortran_f(chi * 180.0 / std::numbers::pi, 6, 2) +
                         " degrees");
  } else {
    report::line(os, "     X  -->");
  }
}

void write_element_division(std::ostream& os, const Solution& solution, int tangential_digit) {
  write_element_division(os, solution, tangential_digit, 0.0);
}

}  // namespace rollcontact::format
