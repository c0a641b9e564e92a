#include "contact/result_check.hpp"

#include <fmt/format.h>

#include <cmath>
#include <initializer_list>
#include <utility>
#include <vector>

namespace rollcontact {

namespace {

using Named = std::pair<const char*, double>;
using NamedField = std::pair<const char*, const std::vector<double>*>;

std::string first_in(std::initializer_list<Named> values) {
  for (const auto& [name, v] : values)
    if (!std::isfinite(v)) return fmt::format("{} = {}", name, v);
  return {};
}

std::string first_in(std::initializer_list<NamedField> fields) {
  for (const auto& [name, field] : fields)
    for (std::size_t i = 0; i < field->size(); ++i)
      if (!std::isfinite((*field)[i])) return fmt::format("{}[{}] = {}", name, i, (*field)[i]);
  return {};
}

}  // namespace

std::string first_non_finite(const Solution& s) {
  const Totals& t = s.totals;
  std::string found = first_in({Named{"FN", t.fn},
                                {"FX", t.fx},
                                {"FY", t.fy},
                                {"MZ", t.mz},
                                {"PEN", t.pen},
                                {"PMAX", t.pmax},
                                {"CREEP_X", t.creep_x},
                                {"CREEP_Y", t.creep_y},
                                {"SPIN", t.spin},
                                {"SHIFT_X", t.shift_x},
                                {"SHIFT_Y", t.shift_y},
                                {"ELEN", t.elastic_energy},
                                {"FRPOWER", t.frictional_power},
                                {"contact area", t.contact_area},
                                {"MAX(T1)", t.max_temp1},
                                {"MAX(T2)", t.max_temp2}});
  if (found.empty())
    found = first_in({NamedField{"pn", &s.pn},
                      {"px", &s.px},
                      {"py", &s.py},
                      {"un", &s.un},
                      {"ux", &s.ux},
                      {"uy", &s.uy},
                      {"sx", &s.sx},
                      {"sy", &s.sy},
                      {"h", &s.h},
                      {"temp1", &s.temp1},
                      {"temp2", &s.temp2}});
  for (const SubsurfaceResult& r : s.subsurface) {
    if (!found.empty()) break;
    found = first_in({NamedField{"subsurface ux", &r.ux},
                      {"subsurface uy", &r.uy},
                      {"subsurface uz", &r.uz},
                      {"subsurface sigvm", &r.sigvm},
                      {"subsurface sxx", &r.sxx},
                      {"subsurface syy", &r.syy},
                      {"subsurface szz", &r.szz},
                      {"subsurface sxy", &r.sxy},
                      {"subsurface sxz", &r.sxz},
                      {"subsurface syz", &r.syz}});
  }
  return found;
}

}  // namespace rollcontact
