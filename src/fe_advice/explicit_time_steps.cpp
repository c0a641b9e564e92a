// Eqs 4–10 of Ma et al. (2018): the Courant step of the mesh and the penalty spring, mass,
// damping and time step of one contact node.

#include <cmath>

#include "fe_advice/value_checks.hpp"
#include "rollcontact/fe_advice.hpp"

namespace rollcontact::fe_advice {

using detail::require_in_range;
using detail::require_non_negative;
using detail::require_positive;

void check_material(const FeMaterial& material) {
  require_positive("material.young_N_mm2", material.young_N_mm2);
  // ν → ½ makes K and c infinite: an incompressible solid has no explicit time step.
  require_in_range("material.poisson", material.poisson, 0.0, 0.5);
  require_positive("material.density_t_mm3", material.density_t_mm3);
}

double bulk_modulus_N_mm2(const FeMaterial& material) {
  check_material(material);
  return material.young_N_mm2 / (3.0 * (1.0 - 2.0 * material.poisson));
}

double dilatational_wave_speed_mm_s(const FeMaterial& material) {
  check_material(material);
  const double nu = material.poisson;
  // The P-wave modulus E(1−ν)/((1+ν)(1−2ν)) over ρ; N/mm² per t/mm³ is mm²/s².
  return std::sqrt(material.young_N_mm2 * (1.0 - nu) /
                   (material.density_t_mm3 * (1.0 + nu) * (1.0 - 2.0 * nu)));
}

double courant_time_step_s(double element_size_mm, const FeMaterial& material,
                           double time_step_scale) {
  require_positive("element_size_mm", element_size_mm);
  require_positive("time_step_scale", time_step_scale);
  return time_step_scale * element_size_mm / dilatational_wave_speed_mm_s(material);
}

double penalty_stiffness_N_mm(double penalty_factor, double bulk_modulus_N_mm2,
                              double element_size_mm) {
  require_positive("penalty_factor", penalty_factor);
  require_positive("bulk_modulus_N_mm2", bulk_modulus_N_mm2);
  require_positive("element_size_mm", element_size_mm);
  // A²/V of a cube of edge C_d is C_d.
  return penalty_factor * bulk_modulus_N_mm2 * element_size_mm;
}

double nodal_mass_t(double element_size_mm, double density_t_mm3, double mass_factor) {
  require_positive("element_size_mm", element_size_mm);
  require_positive("density_t_mm3", density_t_mm3);
  require_positive("nodal_mass_factor", mass_factor);
  return mass_factor * density_t_mm3 * element_size_mm * element_size_mm * element_size_mm;
}

double damping_ratio_from_vdc(double vdc_percent) {
  require_non_negative("vdc_percent", vdc_percent);
  return vdc_percent / 100.0;
}

double damping_reduction_factor(double damping_ratio) {
  require_non_negative("damping_ratio", damping_ratio);
  // 1/(√(1+ξ²) + ξ): the same value without the cancellation of √(1+ξ²) − ξ at large ξ.
  return 1.0 / (std::hypot(1.0, damping_ratio) + damping_ratio);
}

double contact_time_step_undamped_s(double mass_t, double stiffness_N_mm) {
  require_positive("mass_t", mass_t);
  require_positive("stiffness_N_mm", stiffness_N_mm);
  return 2.0 * std::sqrt(mass_t / stiffness_N_mm);
}

double contact_time_step_s(double mass_t, double stiffness_N_mm, double damping_ratio) {
  return contact_time_step_undamped_s(mass_t, stiffness_N_mm) *
         damping_reduction_factor(damping_ratio);
}

bool contact_stable(double calc_time_step_s, double contact_time_step_s) {
  return calc_time_step_s <= contact_time_step_s;
}

double interface_compliance_mm3_N(double element_size_mm, double stiffness_N_mm) {
  require_positive("element_size_mm", element_size_mm);
  require_positive("stiffness_N_mm", stiffness_N_mm);
  return element_size_mm * element_size_mm / stiffness_N_mm;
}

}  // namespace rollcontact::fe_advice
