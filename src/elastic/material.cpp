// Combined elastic constants of two bodies (spec/physics.md §3.1).

#include "elastic/material.hpp"

#include <string>
#include <utility>

#include "elastic/inclination_correction.hpp"
#include "rollcontact/errors.hpp"

namespace rollcontact::elastic {

namespace {

void check_body(int body, double nu, double g) {
  // The negated comparisons also reject NaN.
  if (!(g > 0.0)) {
    throw ProblemError("body " + std::to_string(body) + ": shear modulus G must be positive, got " +
                       std::to_string(g) + " N/mm^2");
  }
  if (!(nu >= 0.0 && nu <= 0.5)) {
    throw ProblemError("body " + std::to_string(body) +
                       ": Poisson ratio must lie in [0, 0.5], got " + std::to_string(nu));
  }
}

}  // namespace

CombinedMaterial combine_materials(double nu1, double nu2, double g1, double g2) {
  check_body(1, nu1, g1);
  check_body(2, nu2, g2);
  CombinedMaterial m;
  m.g = 2.0 / (1.0 / g1 + 1.0 / g2);
  m.nu = 0.5 * m.g * (nu1 / g1 + nu2 / g2);
  // Minus sign: K > 0 when body 1 is the more compressible one (bentall: aluminium on steel,
  // K = +0.100; spence35: soft body 1 on rigid body 2, K = +0.5).
  m.k = material_difference_k(nu1, nu2, g1, g2);
  return m;
}

namespace {

ViscousCompliance viscous_part(const CombinedMaterial& glassy, const model::ElasticBody& body,
                               const model::ViscoelasticBody& visco, double sign,
                               double velocity_mm_s) {
  ViscousCompliance v;
  v.weight = 0.5 * glassy.g * visco.creep_ratio / body.shear_modulus_N_mm2;
  v.nu = body.poisson_ratio;
  v.k = sign * 0.5 * (1.0 - 2.0 * body.poisson_ratio);
  v.relaxation_length_mm = visco.relaxation_length_mm(velocity_mm_s);
  return v;
}

}  // namespace

CombinedMaterial combine_bodies(const model::Bodies& b, double velocity_mm_s) {
  CombinedMaterial m = combine_materials(b.body1.poisson_ratio, b.body2.poisson_ratio,
                                         b.body1.shear_modulus_N_mm2, b.body2.shear_modulus_N_mm2);
  if (b.has_layer) m.layer_compliance = b.layer.compliance_mm3_N();
  m.normal_layer_compliance = b.normal_layer_flexibility_mm3_N;
  m.table = b.influence_table;
  m.elements = b.traction_elements;
  if (b.inclination.active()) {
    if (b.inclination.varying_curvature)
      throw NotSupportedError(
          "not supported yet: the inclination correction (C=4) with varying curvature "
          "(IF_METH=1); IF_METH=0 fits the table with a constant curvature");
    m.inclination_variant = b.inclination.variant;
    m.inclination_curvature_per_mm = inclination_curvature(b.inclination);
  }
  if (!b.viscoelastic) return m;
  for (const model::ViscoelasticBody* v : {&b.viscous1, &b.viscous2})
    if (!(v->creep_ratio >= 0.0 && v->relaxation_time_s >= 0.0))
      throw ProblemError("viscoelastic bodies need FG >= 0 and TC >= 0");
  ViscousCompliance v1 = viscous_part(m, b.body1, b.viscous1, 1.0, velocity_mm_s);
  ViscousCompliance v2 = viscous_part(m, b.body2, b.viscous2, -1.0, velocity_mm_s);
  if (v1.nu == v2.nu && v1.relaxation_length_mm == v2.relaxation_length_mm) {
    const double w = v1.weight + v2.weight;
    v1.k = w > 0.0 ? (v1.weight * v1.k + v2.weight * v2.k) / w : 0.0;
    v1.weight = w;
    v2 = {};
  }
  if (v1.weight == 0.0) std::swap(v1, v2);
  m.viscous = {v1, v2};
  return m;
}

CombinedMaterial effective_viscoelastic_constants(const model::Bodies& b) {
  const auto compliance = [](const model::ElasticBody& e, const model::ViscoelasticBody& v) {
    const double relaxed = v.relaxation_time_s > 0.0 ? 1.0 : 1.0 + v.creep_ratio;
    return relaxed / e.shear_modulus_N_mm2;
  };
  const double c1 = compliance(b.body1, b.viscous1), c2 = compliance(b.body2, b.viscous2);
  const double nu1 = b.body1.poisson_ratio, nu2 = b.body2.poisson_ratio;
  CombinedMaterial m;
  m.g = 2.0 / (c1 + c2);
  m.nu = 0.5 * m.g * (c1 * nu1 + c2 * nu2);
  m.k = 0.25 * m.g * ((1.0 - 2.0 * nu1) * c1 - (1.0 - 2.0 * nu2) * c2);
  return m;
}

}  // namespace rollcontact::elastic
