// Re-formats numbers read from CONTACT's reference reports and compares them with the printed
// text, field by field, for the module-3 blocks the report writer produces.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "format/report/number_format.hpp"
#include "support/examples.hpp"

namespace rollcontact::format {
namespace {

using Formatter = std::function<std::string(double)>;

struct Checker {
  int checked = 0;
  std::vector<std::string> failures;

  // A printed token stands for every value in its rounding interval; the value read back lies at
  // the edge when rounding crossed a power of ten ("10000.", "1.0000"), so nearby values count.
  void field(const std::string& file, int lineno, const std::string& token, const Formatter& f) {
    std::string trimmed = token;
    trimmed.erase(0, trimmed.find_first_not_of(' '));
    if (trimmed.empty() || trimmed.find('*') != std::string::npos) return;
    const double v = std::strtod(trimmed.c_str(), nullptr);
    ++checked;
    for (double factor : {1.0, 1.0 - 1e-6, 1.0 + 1e-6}) {
      if (f(v * factor) == token) return;
    }
    if (failures.size() < 30)
      failures.push_back(file + ":" + std::to_string(lineno) + ": '" + token + "' -> '" + f(v) +
                         "'");
  }

  void fields(const std::string& file, int lineno, std::string text, std::size_t start,
              const std::vector<std::pair<int, Formatter>>& layout) {
    std::size_t total = start;
    for (const auto& [w, f] : layout) total += static_cast<std::size_t>(w);
    if (text.size() < total) text.resize(total, ' ');
    std::size_t pos = start;
    for (const auto& [w, f] : layout) {
      field(file, lineno, text.substr(pos, static_cast<std::size_t>(w)), f);
      pos += static_cast<std::size_t>(w);
    }
  }
};

bool starts(const std::string& s, const char* prefix) {
  return s.rfind(prefix, 0) == 0;
}

// True when s[pos, pos+n) holds exactly one real number (blanks around it allowed).
bool numeric(const std::string& s, std::size_t pos, std::size_t n) {
  if (s.size() < pos + n) return false;
  const std::string t = s.substr(pos, n);
  char* end = nullptr;
  std::strtod(t.c_str(), &end);
  if (end == t.c_str()) return false;
  for (const char* p = end; *p != 0; ++p)
    if (*p != ' ') return false;
  return true;
}

TEST(NumberFormatReference, ModuleThreeReportsRoundTrip) {
  REQUIRE_EXAMPLES();
  const Formatter sig = [](double v) { return fmt_sig(12, 4, 4, v); };
  const Formatter sig6 = [](double v) { return fmt_sig(12, 6, 4, v); };
  const Formatter sig3 = [](double v) { return fmt_sig(12, 3, 3, v); };
  const Formatter g12 = [](double v) { return fortran_g(v, 12, 4); };
  const Formatter g11 = [](double v) { return fortran_g(v, 11, 3); };
  const Formatter f83 = [](double v) { return fortran_f(v, 8, 3) + "    "; };
  const Formatter f101 = [](double v) { return fortran_f(v, 10, 1); };
  const Formatter i7 = [](double v) { return fortran_i(std::llround(v), 7); };
  const Formatter i6 = [](double v) { return fortran_i(std::llround(v), 6); };
  const Formatter i3 = [](double v) { return fortran_i(std::llround(v), 3); };

  Checker c;
  const std::vector<std::string> files = {
      "cattaneo",    "carter2d",    "bentall",     "visc_cylindr", "subsurf",
      "conformal",   "fastsim",     "tractcurv",   "spence35",     "ertz_temperature",
      "veldep_fric", "plastic_3bl", "catt_to_cart"};
  for (const auto& name : files) {
    const std::filesystem::path path =
        std::filesystem::path(ROLLCONTACT_EXAMPLES_DIR) / (name + ".ref_out");
    std::ifstream in(path);
    ASSERT_TRUE(in) << path;
    std::string prev, l;
    int lineno = 0;
    bool in_table = false;
    int table_t = 0;
    while (std::getline(in, l)) {
      ++lineno;
      if (!l.empty() && l.back() == '\r') l.pop_back();
      if (starts(l, " Case") || starts(l, " SUBSURFACE")) in_table = false;
      if (starts(l, "     X         H-PEN")) {
        in_table = true;
        table_t = 1;
      }
      if (starts(prev, "     FN          FX          FY          MZ")) {
        c.fields(name, lineno, l, 2,
                 {{12, sig}, {12, sig}, {12, sig}, {12, sig}, {12, sig}, {12, sig}});
      } else if (starts(prev, "     FN/G")) {
        std::vector<std::pair<int, Formatter>> lay = {
            {12, sig}, {12, sig}, {12, sig}, {12, sig6}, {12, sig}};
        if (prev.find("MAX(T1,T2)") != std::string::npos) lay.emplace_back(12, sig);
        c.fields(name, lineno, l, 2, lay);
      } else if (starts(prev, "     CHI         DQ")) {
        c.fields(name, lineno, l, 2,
                 {{12, g12}, {12, g12}, {12, sig}, {12, sig}, {12, sig}, {12, sig}});
      } else if (starts(prev, "     DT ")) {
        c.fields(name, lineno, l, 2, {{12, f83}, {12, sig}, {12, sig}, {12, sig}, {12, sig}});
      } else if (starts(prev, "     NU ") || starts(prev, "    POISS(1)") ||
                 starts(prev, "     GG3") || starts(prev, "     K0_MF") ||
                 starts(prev, "     FLX1") || starts(prev, "     NUV")) {
        const int n = starts(prev, "     FLX1") || starts(prev, "     NUV") ? 3 : 4;
        c.fields(name, lineno, l, 2,
                 std::vector<std::pair<int, Formatter>>(static_cast<std::size_t>(n), {12, g12}));
      } else if (starts(prev, "     FSTAT       FKIN")) {
        c.fields(name, lineno, l, 2, {{12, g12}, {12, g12}});
      } else if (starts(prev, "     FKIN        F")) {
        c.fields(name, lineno, l, 2, {{12, g12}, {12, g12}, {12, g12}, {12, g12}, {12, g12}});
      } else if (starts(prev, "     FG(1)")) {
        c.fields(name, lineno, l, 2,
                 {{12, g12}, {12, g12}, {12, sig}, {12, sig}, {12, sig}, {12, sig}});
      } else if (starts(prev, "  DFN/DPEN")) {
        c.fields(name, lineno, l, 0, {{12, sig3}});
      } else if (starts(l, "   FN  ") || starts(l, "   FX  ") || starts(l, "   FY  ")) {
        c.fields(name, lineno, l, 6, {{12, sig3}, {12, sig3}, {12, sig3}, {12, sig3}});
      } else if (starts(prev, "    NPOT   NCON")) {
        const int n = prev.find("NPLAST") != std::string::npos ? 7 : 6;
        c.fields(name, lineno, l, 1,
                 std::vector<std::pair<int, Formatter>>(static_cast<std::size_t>(n), {7, i7}));
      } else if (starts(l, " SEMIAXES PRESCRIBED, AA,BB:") ||
                 starts(l, " THE CURVATURES A1,B1 ARE:") || starts(l, " EFFECTIVE RAD.CURV") ||
                 starts(l, " CURVATURE AND ELLIPTIC")) {
        c.fields(name, lineno, l, 43, {{12, g12}, {12, g12}});
      } else if (starts(l, " BASIC SEMIAXES") || starts(l, " POTENTIAL CONTACT, SCALE:")) {
        c.fields(name, lineno, l, 43, {{12, g12}, {12, g12}, {12, g12}});
      } else if (starts(l, " DISCRETISATION MX,MY")) {
        c.fields(name, lineno, l, 43, {{6, i6}, {6, i6}, {12, g12}, {12, g12}});
      } else if (in_table && starts(l, " Y = ")) {
        c.fields(name, lineno, l, 5, {{12, g12}});
        c.fields(name, lineno, l, 21, {{3, i3}});
      } else if (in_table && table_t == 1 && l.size() > 67 && numeric(l, 1, 12)) {
        c.fields(name, lineno, l, 1,
                 {{12, g12}, {11, g11}, {11, g11}, {11, g11}, {11, g11}, {10, f101}});
        c.fields(name, lineno, l, 69, {{11, g11}, {11, g11}, {11, g11}});
      }
      prev = l;
    }
  }
  EXPECT_GT(c.checked, 10000);
  for (const auto& f : c.failures) ADD_FAILURE() << f;
  EXPECT_TRUE(c.failures.empty()) << c.failures.size() << " of " << c.checked << " fields differ";
}

}  // namespace
}  // namespace rollcontact::format
