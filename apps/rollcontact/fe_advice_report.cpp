// The text table and JSON of `rollcontact fe-advice` (docs/fe-advice.md shows both).

#include "fe_advice_report.hpp"

#include <fmt/format.h>

#include <nlohmann/json.hpp>
#include <string>

namespace rollcontact::cli {

namespace {

constexpr double kUs = 1e6;              // s → µs
constexpr double kNPerMPerNPerMm = 1e3;  // N/mm → N/m
constexpr double kKgM3PerTMm3 = 1e12;    // t/mm³ → kg/m³
constexpr double kKgPerT = 1e3;          // t → kg

const char* verdict(bool stable) {
  return stable ? "stable" : "UNSTABLE";
}

std::string time_step_origin(const fe_advice::FeContactSettings& s) {
  if (s.calc_time_step_s > 0.0) return "given";
  const double smallest = s.smallest_element_mm > 0.0 ? s.smallest_element_mm : s.element_size_mm;
  return fmt::format("{:g} x Courant step of a {:g} mm element", s.time_step_scale, smallest);
}

std::string header(const FeAdviceReport& r) {
  const auto& s = r.settings;
  const auto& m = s.material;
  const fe_advice::StabilityAdvice& a = r.rows.front().advice;
  std::string out = "fe-advice: explicit-FE penalty contact (Ma et al. 2018, eqs 4-10)\n";
  out += fmt::format(
      "  material       E {:g} N/mm2, nu {:g}, rho {:g} kg/m3: K {:g} N/mm2, c {:.1f} m/s\n",
      m.young_N_mm2, m.poisson, m.density_t_mm3 * kKgM3PerTMm3, fe_advice::bulk_modulus_N_mm2(m),
      fe_advice::dilatational_wave_speed_mm_s(m) / 1e3);
  out += fmt::format(
      "  contact node   C_d {:g} mm, mass {:g} rho C_d^3 = {:.4g} kg, VDC {:g} % "
      "(xi {:g}, eq 9 factor {:.4f})\n",
      s.element_size_mm, s.nodal_mass_factor, a.mass_t * kKgPerT, s.vdc_percent, a.damping_ratio,
      fe_advice::damping_reduction_factor(a.damping_ratio));
  out += fmt::format("  time step      dt_calc {:.4g} us ({})\n", a.calc_time_step_s * kUs,
                     time_step_origin(s));
  out += fmt::format(
      "  boundary       dt_calc = dt_cont at alpha = {:.4g} (eq 8, undamped), "
      "{:.4g} (eq 9, VDC {:g} %)\n",
      r.boundary_undamped, r.boundary_damped, s.vdc_percent);
  if (r.with_pressure) {
    const auto& c = r.contact;
    out += fmt::format(
        "  contact        FN {:g} N, h = {:.6g} x^2 + {:.6g} y^2 [1/mm], grid {:g} mm: "
        "exact pmax {:.1f} N/mm2, area {:.1f} mm2, approach {:.4f} mm\n",
        c.normal_force_N, c.curvature_x_1_mm, c.curvature_y_1_mm, c.grid_step_mm,
        r.exact.pmax_N_mm2, r.exact.area_mm2, r.exact.approach_mm);
  }
  return out;
}

std::string row_line(const FeAdviceReport& r, const FeAdviceRow& row) {
  const fe_advice::StabilityAdvice& a = row.advice;
  std::string line = fmt::format(
      "{:>8g} {:>10.4g} {:>8.4f} {:>8.4f} {:>8.4f}  {:<8} {:<8} {:>9.4g} {:>10.3g}",
      a.penalty_factor, a.stiffness_N_mm * kNPerMPerNPerMm, a.contact_time_step_undamped_s * kUs,
      a.contact_time_step_s * kUs, a.calc_time_step_s * kUs, verdict(a.stable_undamped),
      verdict(a.stable), row.oscillator.growth_per_step, a.layer_compliance_mm3_N);
  if (r.with_pressure) {
    const auto& l = row.layered;
    line +=
        fmt::format(" {:>7.1f} {:>6.3f} {:>7.1f} {:>6.3f}", l.pmax_N_mm2,
                    l.pmax_N_mm2 / r.exact.pmax_N_mm2, l.area_mm2, l.area_mm2 / r.exact.area_mm2);
  }
  return line + "\n";
}

}  // namespace

std::string format_fe_advice_text(const FeAdviceReport& r) {
  std::string out = header(r) + "\n";
  out += "                       dt_cont [us]     dt_calc  verdict (eq 10)  amplitude L=C_d^2/k";
  out += r.with_pressure ? "   with layer L: pmax, area\n" : "\n";
  out += "   alpha    k [N/m]     eq 8     eq 9     [us]  eq 8     eq 9      per step  [mm3/N]";
  out += r.with_pressure ? "  [N/mm2] /exact   [mm2] /exact\n" : "\n";
  for (const FeAdviceRow& row : r.rows) out += row_line(r, row);
  return out;
}

std::string format_fe_advice_json(const FeAdviceReport& r) {
  using nlohmann::json;
  const auto& s = r.settings;
  json j;
  j["units"] = "mm, N, s, t (masses also in kg)";
  j["material"] = {{"young_N_mm2", s.material.young_N_mm2},
                   {"poisson", s.material.poisson},
                   {"density_kg_m3", s.material.density_t_mm3 * kKgM3PerTMm3},
                   {"bulk_modulus_N_mm2", fe_advice::bulk_modulus_N_mm2(s.material)},
                   {"wave_speed_m_s", fe_advice::dilatational_wave_speed_mm_s(s.material) / 1e3}};
  j["mesh"] = {
      {"element_size_mm", s.element_size_mm}, {"smallest_element_mm", s.smallest_element_mm},
      {"time_step_scale", s.time_step_scale}, {"nodal_mass_factor", s.nodal_mass_factor},
      {"vdc_percent", s.vdc_percent},         {"calc_time_step_given", s.calc_time_step_s > 0.0}};
  j["stability_boundary"] = {{"penalty_factor_eq8", r.boundary_undamped},
                             {"penalty_factor_eq9", r.boundary_damped}};
  if (r.with_pressure)
    j["contact"] = {{"normal_force_N", r.contact.normal_force_N},
                    {"curvature_x_1_mm", r.contact.curvature_x_1_mm},
                    {"curvature_y_1_mm", r.contact.curvature_y_1_mm},
                    {"grid_step_mm", r.contact.grid_step_mm},
                    {"exact_pmax_N_mm2", r.exact.pmax_N_mm2},
                    {"exact_area_mm2", r.exact.area_mm2},
                    {"exact_approach_mm", r.exact.approach_mm}};
  json rows = json::array();
  for (const FeAdviceRow& row : r.rows) {
    const auto& a = row.advice;
    json o = {{"penalty_factor", a.penalty_factor},
              {"stiffness_N_m", a.stiffness_N_mm * kNPerMPerNPerMm},
              {"nodal_mass_kg", a.mass_t * kKgPerT},
              {"damping_ratio", a.damping_ratio},
              {"contact_time_step_eq8_s", a.contact_time_step_undamped_s},
              {"contact_time_step_eq9_s", a.contact_time_step_s},
              {"calc_time_step_s", a.calc_time_step_s},
              {"stable_eq8", a.stable_undamped},
              {"stable_eq9", a.stable},
              {"oscillator_growth_per_step", row.oscillator.growth_per_step},
              {"oscillator_growth_per_cycle", row.oscillator.growth_per_period},
              {"layer_compliance_mm3_N", a.layer_compliance_mm3_N}};
    if (r.with_pressure) {
      o["pmax_layer_N_mm2"] = row.layered.pmax_N_mm2;
      o["pmax_ratio"] = row.layered.pmax_N_mm2 / r.exact.pmax_N_mm2;
      o["area_layer_mm2"] = row.layered.area_mm2;
      o["area_ratio"] = row.layered.area_mm2 / r.exact.area_mm2;
    }
    rows.push_back(std::move(o));
  }
  j["rows"] = std::move(rows);
  return j.dump(2) + "\n";
}

}  // namespace rollcontact::cli
