// Combined elastic constants of two bodies (spec/physics.md §3.1).

#include "elastic/material.hpp"

#include <string>

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

}  // namespace rollcontact::elastic
