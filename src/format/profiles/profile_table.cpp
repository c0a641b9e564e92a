#include "format/profiles/profile_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cstddef>

#include "format/profiles/profile_text.hpp"
#include "format/text/inp_lexer.hpp"
#include "rollcontact/errors.hpp"

namespace rollcontact::format {

namespace {

std::string lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

/// Column layout from ColumnDef: positions of the X (profile y), Y (profile z) and K columns.
struct Columns {
  std::size_t count = 0;  ///< 0: no ColumnDef, use the first two numbers of each line
  std::size_t x = 0, y = 1;
  std::ptrdiff_t k = -1;
};

Columns parse_column_def(std::string_view value, const std::string& file, int line) {
  Columns c;
  bool has_x = false;
  bool has_y = false;
  std::size_t index = 0;
  std::size_t start = 0;
  for (;;) {
    std::size_t end = value.find(',', start);
    if (end == std::string_view::npos) end = value.size();
    const std::string letter = lower(trim(value.substr(start, end - start)));
    if (letter == "x") {
      c.x = index;
      has_x = true;
    } else if (letter == "y") {
      c.y = index;
      has_y = true;
    } else if (letter == "k") {
      c.k = static_cast<std::ptrdiff_t>(index);
    } else if (letter != "a" && letter != "c" && letter != "n") {
      throw InputError(file, line, "unknown column letter in ColumnDef (expected X, Y, A, C, N, K)",
                       letter);
    }
    ++index;
    if (end == value.size()) break;
    start = end + 1;
  }
  if (!has_x || !has_y) {
    throw InputError(file, line, "ColumnDef must name the columns X and Y", std::string(value));
  }
  c.count = index;
  return c;
}

}  // namespace

RawProfile parse_table_profile(std::string_view text, const std::string& file, bool miniprof,
                               std::vector<std::string>& warnings) {
  RawProfile raw;
  raw.file = file;
  raw.format = miniprof ? ProfileFormat::Miniprof : ProfileFormat::Plain;
  const std::vector<std::string> lines = split_lines(text);
  Columns columns;
  bool in_header = miniprof;
  std::size_t skipped = 0;
  int first_skipped = 0;
  int last_line = 0;
  std::vector<double> row;
  std::string bad;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const int line_no = static_cast<int>(i + 1);
    const std::string_view line = trim(strip_comment(lines[i], "!\"%#"));
    if (in_header) {
      // The header ends at the first blank or purely numeric line.
      if (trim(lines[i]).empty()) {
        in_header = false;
        continue;
      }
      if (line.empty()) continue;  // comment-only line inside the header
      const bool numeric = parse_number_row(line, row, bad) && !row.empty();
      if (!numeric) {
        const std::size_t eq = line.find('=');
        if (eq == std::string_view::npos) {
          // Old-style headers: a keyword line such as 'MINIPROF 101 148 1994 3 24' or
          // 'MINIWHEELPROF' (with or without a leading '#'), read and ignored as CONTACT does.
          if (std::isalpha(static_cast<unsigned char>(line.front()))) continue;
          throw InputError(file, line_no, "expected 'Key=Value' in the Miniprof header",
                           std::string(line));
        }
        const std::string key = lower(trim(line.substr(0, eq)));
        const std::string_view value = trim(line.substr(eq + 1));
        if (key == "columndef") {
          columns = parse_column_def(value, file, line_no);
        } else if ((key == "xoffset" || key == "yoffset") && !value.empty()) {
          // An empty value ('XOffset=') leaves the offset at 0.
          const auto v = parse_fortran_real(value);
          if (!v) {
            throw InputError(file, line_no, fmt::format("expected a number for {}", key),
                             std::string(value));
          }
          (key == "xoffset" ? raw.shift_y : raw.shift_z) = *v;
        }
        continue;
      }
      in_header = false;
    }
    if (line.empty()) continue;
    last_line = line_no;
    if (!parse_number_row(line, row, bad)) {
      throw InputError(file, line_no, "expected numbers in a profile data line", bad);
    }
    const std::size_t need = columns.count > 0 ? columns.count : 2;
    if (row.size() < need) {
      if (skipped++ == 0) first_skipped = line_no;
      continue;
    }
    raw.y.push_back(row[columns.x]);
    raw.z.push_back(row[columns.y]);
    if (columns.k >= 0) raw.k_yield.push_back(row[static_cast<std::size_t>(columns.k)]);
  }
  if (skipped > 0) {
    warnings.push_back(fmt::format("{}:{}: {} line(s) with too few columns skipped", file,
                                   first_skipped, skipped));
  }
  if (raw.y.size() < 2) {
    throw InputError(file, last_line,
                     fmt::format("a profile needs at least 2 points, found {}", raw.y.size()));
  }
  return raw;
}

}  // namespace rollcontact::format
