// Eq 10 over penalty factors: the contact time step of one node against the calculation step of
// the mesh, and the penalty factor where they meet.

#include <cmath>

#include "fe_advice/value_checks.hpp"
#include "rollcontact/fe_advice.hpp"

namespace rollcontact::fe_advice {

void check_settings(const FeContactSettings& s) {
  check_material(s.material);
  detail::require_positive("element_size_mm", s.element_size_mm);
  detail::require_non_negative("smallest_element_mm", s.smallest_element_mm);
  detail::require_positive("time_step_scale", s.time_step_scale);
  detail::require_non_negative("calc_time_step_s", s.calc_time_step_s);
  detail::require_positive("nodal_mass_factor", s.nodal_mass_factor);
  detail::require_non_negative("vdc_percent", s.vdc_percent);
}

double calculation_time_step_s(const FeContactSettings& s) {
  check_settings(s);
  if (s.calc_time_step_s > 0.0) return s.calc_time_step_s;
  // LS-DYNA takes the smallest element step of the whole model, not the contact's elements.
  const double smallest = s.smallest_element_mm > 0.0 ? s.smallest_element_mm : s.element_size_mm;
  return courant_time_step_s(smallest, s.material, s.time_step_scale);
}

StabilityAdvice stability_advice(const FeContactSettings& s, double penalty_factor) {
  StabilityAdvice a;
  a.calc_time_step_s = calculation_time_step_s(s);
  a.penalty_factor = penalty_factor;
  a.stiffness_N_mm =
      penalty_stiffness_N_mm(penalty_factor, bulk_modulus_N_mm2(s.material), s.element_size_mm);
  a.mass_t = nodal_mass_t(s.element_size_mm, s.material.density_t_mm3, s.nodal_mass_factor);
  a.damping_ratio = damping_ratio_from_vdc(s.vdc_percent);
  a.contact_time_step_undamped_s = contact_time_step_undamped_s(a.mass_t, a.stiffness_N_mm);
  a.contact_time_step_s = contact_time_step_s(a.mass_t, a.stiffness_N_mm, a.damping_ratio);
  a.stable_undamped = contact_stable(a.calc_time_step_s, a.contact_time_step_undamped_s);
  a.stable = contact_stable(a.calc_time_step_s, a.contact_time_step_s);
  a.layer_compliance_mm3_N = interface_compliance_mm3_N(s.element_size_mm, a.stiffness_N_mm);
  return a;
}

double stability_boundary_penalty_factor(const FeContactSettings& s, bool damped) {
  // Δt_cont(α) = Δt_cont(1)·α^−½, so Δt_cont(α*) = Δt_calc at α* = (Δt_cont(1)/Δt_calc)².
  const StabilityAdvice one = stability_advice(s, 1.0);
  const double ratio =
      (damped ? one.contact_time_step_s : one.contact_time_step_undamped_s) / one.calc_time_step_s;
  return ratio * ratio;
}

std::vector<double> penalty_factor_sweep() {
  std::vector<double> alphas;
  for (int m = -1; m <= 12; ++m) alphas.push_back(std::ldexp(0.1, m));
  return alphas;
}

}  // namespace rollcontact::fe_advice
