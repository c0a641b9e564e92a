// `rollcontact fe-advice`: advice for explicit-FE penalty contact (Ma et al. 2018, eqs 4–10) —
// the contact time step per penalty factor against the calculation step, the penalty oscillator
// at that step, and the pressure error of the penalty compliance (docs/fe-advice.md).

#include <fmt/format.h>

#include <memory>
#include <string>
#include <vector>

#include "commands.hpp"
#include "fe_advice_report.hpp"
#include "rollcontact/errors.hpp"
#include "rollcontact/fe_advice.hpp"

namespace rollcontact::cli {

namespace {

constexpr double kTMm3PerKgM3 = 1e-12;  // kg/m³ → t/mm³
constexpr double kSPerUs = 1e-6;

struct FeAdviceOptions {
  double element_size_mm = 1.0;
  double smallest_element_mm = 0.0;
  std::vector<double> penalty_factors{0.1};
  bool sweep = false;
  double vdc_percent = 80.0;
  double dt_calc_us = 0.0;
  double time_step_scale = fe_advice::default_time_step_scale;
  double nodal_mass_factor = fe_advice::default_nodal_mass_factor;
  double young_N_mm2 = 210000.0;
  double poisson = 0.3;
  double density_kg_m3 = 7900.0;
  double force_N = 1.0e5;
  std::vector<double> curvatures_1_mm{1.0 / 920.0, 4.0e-4};
  double grid_step_mm = 0.25;
  bool no_pressure = false;
  bool json = false;
};

FeAdviceReport make_report(const FeAdviceOptions& o) {
  FeAdviceReport r;
  r.settings.material = {o.young_N_mm2, o.poisson, o.density_kg_m3 * kTMm3PerKgM3};
  r.settings.element_size_mm = o.element_size_mm;
  r.settings.smallest_element_mm = o.smallest_element_mm;
  r.settings.time_step_scale = o.time_step_scale;
  r.settings.calc_time_step_s = o.dt_calc_us * kSPerUs;
  r.settings.nodal_mass_factor = o.nodal_mass_factor;
  r.settings.vdc_percent = o.vdc_percent;
  fe_advice::check_settings(r.settings);
  r.contact.normal_force_N = o.force_N;
  r.contact.curvature_x_1_mm = o.curvatures_1_mm.at(0);
  r.contact.curvature_y_1_mm = o.curvatures_1_mm.at(1);
  r.contact.material = r.settings.material;
  r.contact.grid_step_mm = o.grid_step_mm;
  r.with_pressure = !o.no_pressure;
  if (r.with_pressure) fe_advice::check_contact_case(r.contact);
  return r;
}

void compute(FeAdviceReport& r, const std::vector<double>& alphas) {
  std::vector<double> compliances{0.0};  // first the exact contact, without layer
  for (const double alpha : alphas) {
    FeAdviceRow row;
    row.advice = fe_advice::stability_advice(r.settings, alpha);
    const auto& a = row.advice;
    row.oscillator = fe_advice::run_penalty_oscillator(
        {a.mass_t, a.stiffness_N_mm, a.damping_ratio}, a.calc_time_step_s);
    compliances.push_back(a.layer_compliance_mm3_N);
    r.rows.push_back(row);
  }
  r.boundary_undamped = fe_advice::stability_boundary_penalty_factor(r.settings, false);
  r.boundary_damped = fe_advice::stability_boundary_penalty_factor(r.settings, true);
  if (!r.with_pressure) return;
  const auto results = fe_advice::solve_normal_contacts(r.contact, compliances);
  r.exact = results.front();
  for (std::size_t i = 0; i < r.rows.size(); ++i) r.rows[i].layered = results[i + 1];
}

int run_fe_advice(const FeAdviceOptions& o) {
  try {
    FeAdviceReport r = make_report(o);
    compute(r, o.sweep ? fe_advice::penalty_factor_sweep() : o.penalty_factors);
    fmt::print("{}", o.json ? format_fe_advice_json(r) : format_fe_advice_text(r));
  } catch (const InvalidValueError& e) {
    // A bad value on the command line: the documented status of a bad command line.
    fmt::print(stderr, "rollcontact fe-advice: error: {}\n", e.what());
    return exit_input_error;
  }
  return exit_ok;
}

}  // namespace

CommandRunner add_fe_advice_command(CLI::App& app) {
  auto o = std::make_shared<FeAdviceOptions>();
  CLI::App* cmd = app.add_subcommand(
      "fe-advice",
      "Advice for explicit-FE penalty contact (Ma et al. 2018): contact time step per penalty "
      "factor against the calculation step (stable/UNSTABLE), and the pmax and area error the "
      "penalty compliance causes (docs/fe-advice.md). Units mm, N, s");
  cmd->add_option("--element-size", o->element_size_mm,
                  "edge C_d of the contact surface elements [mm]")
      ->capture_default_str();
  cmd->add_option("--smallest-element", o->smallest_element_mm,
                  "edge of the model's smallest element, which sets the Courant step [mm] "
                  "(default: --element-size)");
  CLI::Option* alphas =
      cmd->add_option("-a,--penalty-factor", o->penalty_factors, "penalty scale factor(s) alpha")
          ->capture_default_str();
  cmd->add_flag("--sweep", o->sweep, "the paper's alpha = 0.1*2^m, m = -1..12 (0.05 .. 409.6)")
      ->excludes(alphas);
  cmd->add_option("--vdc", o->vdc_percent, "contact damping VDC [% of critical]")
      ->capture_default_str();
  cmd->add_option("--dt-calc", o->dt_calc_us,
                  "calculation time step [us] (default: --tssfac x Courant step of the smallest "
                  "element)");
  cmd->add_option("--tssfac", o->time_step_scale, "time-step scale factor on the Courant step")
      ->capture_default_str();
  cmd->add_option("--nodal-mass-factor", o->nodal_mass_factor,
                  "oscillating mass of a contact node as a fraction of rho*C_d^3")
      ->capture_default_str();
  cmd->add_option("--young", o->young_N_mm2, "Young's modulus E [N/mm2]")->capture_default_str();
  cmd->add_option("--poisson", o->poisson, "Poisson's ratio")->capture_default_str();
  cmd->add_option("--density", o->density_kg_m3, "density [kg/m3]")->capture_default_str();
  cmd->add_option("--force", o->force_N, "normal force of the pressure-error contact [N]")
      ->capture_default_str();
  cmd->add_option("--curvatures", o->curvatures_1_mm,
                  "A B [1/mm] of the gap h = A x^2 + B y^2 (x rolling); default: 100 kN S1002 on "
                  "54E1 stand-in, a Hertzian 191 mm2 patch")
      ->expected(2);
  cmd->add_option("--grid-step", o->grid_step_mm, "element size of the contact grid [mm]")
      ->capture_default_str();
  cmd->add_flag("--no-pressure", o->no_pressure, "skip the pressure-error contact solves");
  cmd->add_flag("--json", o->json, "write JSON instead of the table");
  return [o] { return run_fe_advice(*o); };
}

}  // namespace rollcontact::cli
