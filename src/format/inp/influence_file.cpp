// C=9 coefficient files (spec/inp-format.md §8.5). The four header groups follow the .inp rules
// (comments, continuation lines); after them the lines are consumed literally, with the exact
// number of comment lines, as CONTACT reads them.

#include "format/inp/influence_file.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include "format/text/inp_checks.hpp"
#include "format/text/inp_lexer.hpp"
#include "format/text/inp_stream.hpp"
#include "format/text/input_file.hpp"
#include "rollcontact/errors.hpp"

namespace rollcontact::format {

namespace {

using Table = model::InfluenceTable;

/// Values on a data line after IXOFS and XREL: Czz Czx Czy Cxz Cxx Cxy Cyz Cyx Cyy.
constexpr std::size_t kCoefficientsPerLine = Table::count;

/// Components odd in the x offset (inp-format.md §8.5: sign change for xz, zx, xy, yx).
constexpr std::array<bool, Table::count> kOddInX{false, true,  false, true, false,
                                                 true,  false, true,  false};

std::vector<std::string_view> split_lines(std::string_view text) {
  std::vector<std::string_view> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) {
      lines.push_back(text.substr(start));
      break;
    }
    lines.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  return lines;
}

/// The header as CONTACT's line buffer sees it: 256 characters a line. Data lines may be longer
/// (they are read whole), and the stream would refuse them.
std::string header_text(const std::vector<std::string_view>& lines) {
  std::string s;
  for (std::string_view l : lines) {
    s += l.substr(0, kInpLineLength);
    s += '\n';
  }
  return s;
}

/// Words of a data line: blanks, TABs, carriage returns and commas separate (list-directed).
std::vector<std::string_view> data_words(std::string_view line) {
  std::vector<std::string_view> words;
  std::size_t i = 0;
  const auto separator = [](char ch) { return ch == ' ' || ch == '\t' || ch == '\r' || ch == ','; };
  while (i < line.size()) {
    while (i < line.size() && separator(line[i])) ++i;
    const std::size_t start = i;
    while (i < line.size() && !separator(line[i])) ++i;
    if (i > start) words.push_back(line.substr(start, i - start));
  }
  return words;
}

struct Header {
  int mx = 0, my = 0;
  double dx = 0.0, dy = 0.0;
  int last_line = 0;  ///< 1-based line of the last header group
};

Header read_header(InpStream& in, std::optional<ElementSize> grid) {
  const GroupValues g1 = in.read_group(
      {{"NMATRIX", FieldKind::integer}, {"IACONVEX", FieldKind::integer}}, "NMATRIX IACONVEX");
  const GroupValues g2 = in.read_group(
      {{"LQUASID", FieldKind::integer}, {"XYZORDER", FieldKind::integer}}, "LQUASID XYZORDER");
  const GroupValues g3 = in.read_group(
      {{"LSYMMX", FieldKind::integer}, {"LSYMMY", FieldKind::integer}}, "LSYMMX LSYMMY");
  const GroupValues g4 = in.read_group({{"MXFILE", FieldKind::integer},
                                        {"MYFILE", FieldKind::integer},
                                        {"DXFILE", FieldKind::real},
                                        {"DYFILE", FieldKind::real}},
                                       "MXFILE MYFILE DXFILE DYFILE");
  if (g1.integer(0) != 1) {
    if (g1.integer(0) < 1)
      in.fail(g1.line(0), fmt::format("NMATRIX = {} must be 1 or MY", g1.integer(0)));
    throw NotSupportedError(fmt::format(
        "not supported yet: {}:{}: NMATRIX = {}, one coefficient matrix per grid row: the "
        "solver's products are convolutions, which need the same coefficients for every row "
        "(NMATRIX = 1)",
        in.file(), g1.line(0), g1.integer(0)));
  }
  if (g2.integer(0) != 0 || g2.integer(1) != 312)
    in.fail(g2.line(0), fmt::format("LQUASID, XYZORDER = {}, {} must be 0 and 312", g2.integer(0),
                                    g2.integer(1)));
  if (g3.integer(0) != 1 || g3.integer(1) != 0)
    in.fail(g3.line(0), fmt::format("LSYMMX, LSYMMY = {}, {} must be 1 and 0 (symmetric in x, "
                                    "not in y)",
                                    g3.integer(0), g3.integer(1)));
  Header h{g4.integer(0), g4.integer(1), g4.real(2), g4.real(3), g4.line(3)};
  // Bounds that keep (2·MXFILE − 1)(2·MYFILE − 1) far inside memory: a 2000×2000 grid at most.
  require_int_range(in, g4.line(0), "MXFILE", h.mx, 1, 2000);
  require_int_range(in, g4.line(1), "MYFILE", h.my, 1, 2000);
  require_positive(in, g4.line(2), "DXFILE", h.dx);
  require_positive(in, g4.line(3), "DYFILE", h.dy);
  // inp-format.md §8.5: the coefficients belong to the grid's elements, within 1e-5 mm.
  constexpr double tolerance_mm = 1e-5;
  if (grid &&
      (std::abs(grid->dx_mm - h.dx) > tolerance_mm || std::abs(grid->dy_mm - h.dy) > tolerance_mm))
    in.fail(g4.line(2), fmt::format("DXFILE, DYFILE = {}, {} mm differ from the grid's DX, DY = "
                                    "{}, {} mm (by more than {} mm)",
                                    h.dx, h.dy, grid->dx_mm, grid->dy_mm, tolerance_mm));
  return h;
}

/// One data line of row IYOFS: IXOFS (must be `ixofs`), XREL and the nine coefficients.
void read_data_line(std::string_view line, int line_number, const std::string& file, int ixofs,
                    int iyofs, Table& t) {
  const auto fail = [&](const std::string& message, std::string_view offending = {}) {
    throw InputError(file, line_number,
                     fmt::format("IYOFS = {}, IXOFS = {}: {}", iyofs, ixofs, message),
                     std::string(offending));
  };
  const std::vector<std::string_view> words = data_words(line);
  if (words.size() < 2 + kCoefficientsPerLine)
    fail(fmt::format("expected IXOFS XREL and 9 coefficients (11 values), found {}", words.size()));
  const std::optional<int> read_ix = parse_integer_field(words[0]);
  if (!read_ix || *read_ix != ixofs)
    fail(fmt::format("expected IXOFS = {} (lines are read in order, with exactly two comment "
                     "lines before each IYOFS)",
                     ixofs),
         words[0]);
  if (!parse_fortran_real(words[1])) fail("XREL is not a number", words[1]);
  for (std::size_t c = 0; c < kCoefficientsPerLine; ++c) {
    const std::optional<double> v = parse_fortran_real(words[2 + c]);
    if (!v) fail(fmt::format("coefficient {} of 9 is not a number", c + 1), words[2 + c]);
    auto& values = t.values[c];
    values[t.index(ixofs, iyofs)] = *v;
    if (ixofs > 0) values[t.index(-ixofs, iyofs)] = kOddInX[c] ? -*v : *v;
    if (*v != 0.0 && (c == Table::zx || c == Table::zy || c == Table::xz || c == Table::yz))
      t.coupled = true;
  }
}

}  // namespace

model::InfluenceTable parse_influence_file(std::string_view text, const std::string& file_name,
                                           std::optional<ElementSize> grid) {
  const std::vector<std::string_view> lines = split_lines(text);
  const std::string header = header_text(lines);
  InpStream in(header, file_name);
  const Header h = read_header(in, grid);
  // After the header: two comment lines, then per IYOFS two comment lines and MXFILE data lines.
  const std::int64_t rows = 2 * static_cast<std::int64_t>(h.my) - 1;
  const std::int64_t needed = 2 + rows * (2 + h.mx);
  const std::int64_t available = static_cast<std::int64_t>(lines.size()) - h.last_line;
  if (available < needed)
    throw InputError(file_name, static_cast<int>(lines.size()),
                     fmt::format("the file ends after line {}: MXFILE = {}, MYFILE = {} need {} "
                                 "lines after the header (line {}), found {}",
                                 lines.size(), h.mx, h.my, needed, h.last_line, available));
  Table t;
  t.mx = h.mx;
  t.my = h.my;
  t.dx_mm = h.dx;
  t.dy_mm = h.dy;
  t.source = file_name;
  for (auto& v : t.values) v.assign(static_cast<std::size_t>((2 * h.mx - 1) * rows), 0.0);
  std::size_t next = static_cast<std::size_t>(h.last_line) + 2;  // 0-based index of the line
  for (int iyofs = -(h.my - 1); iyofs <= h.my - 1; ++iyofs) {
    next += 2;
    for (int ixofs = 0; ixofs < h.mx; ++ixofs, ++next)
      read_data_line(lines[next], static_cast<int>(next) + 1, file_name, ixofs, iyofs, t);
  }
  return t;
}

std::shared_ptr<const model::InfluenceTable> read_influence_file(const std::filesystem::path& path,
                                                                 std::optional<ElementSize> grid) {
  const std::string text = read_input_file(path, "influence coefficient file");
  return std::make_shared<const model::InfluenceTable>(
      parse_influence_file(text, path.string(), grid));
}

std::string format_influence_file(const model::InfluenceTable& t) {
  std::string s;
  s += fmt::format("{:6d} {:6d}          NMATRIX, IACONVEX\n", 1, 0);
  s += fmt::format("{:6d} {:6d}          LQUASID, XYZORDER\n", 0, 312);
  s += fmt::format("{:6d} {:6d}          LSYMMX, LSYMMY\n", 1, 0);
  s += fmt::format("{:6d} {:6d} {} {}   MXFILE, MYFILE, DXFILE, DYFILE\n", t.mx, t.my, t.dx_mm,
                   t.dy_mm);
  s += "% influence coefficients, combined for both bodies, without the factor 1/G\n";
  s += "% C_ij: displacement i due to a unit load in j (z normal)\n";
  for (int iyofs = -(t.my - 1); iyofs <= t.my - 1; ++iyofs) {
    s += fmt::format("% IYOFS = {}, YREL = {}\n", iyofs, iyofs * t.dy_mm);
    s += "% IXOFS XREL Czz Czx Czy Cxz Cxx Cxy Cyz Cyx Cyy\n";
    for (int ixofs = 0; ixofs < t.mx; ++ixofs) {
      s += fmt::format("{} {}", ixofs, ixofs * t.dx_mm);
      for (std::size_t c = 0; c < Table::count; ++c)
        s += fmt::format(" {}", t.values[c][t.index(ixofs, iyofs)]);
      s += '\n';
    }
  }
  return s;
}

}  // namespace rollcontact::format
