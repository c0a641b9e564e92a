#pragma once
// Prescribed tangential forces (F = 1, 2; spec/physics.md §9.6): find the creepages (shifts for
// T=1) at which the tangential problem yields FX/(μ FN) (and FY/(μ FN)).

#include <array>
#include <functional>
#include <string>

namespace rollcontact {

struct ForceIterationInput {
  int unknowns = 1;        ///< 1: ξ (η fixed); 2: ξ and η
  double target_x = 0.0;   ///< FX/(μ FN)
  double target_y = 0.0;   ///< FY/(μ FN) (unknowns = 2)
  double fixed_eta = 0.0;  ///< η when unknowns = 1
  double start_ksi = 1e-6, start_eta = 0.0;
  /// d(FX, FY)/(μFN) by d(ξ, η) of the previous case of a sequence (row-major), or zeros. A usable
  /// one replaces the finite-difference start: the first step is a Newton step with it, which
  /// saves one tangential solve (two for F=2) per case of a force-prescribed sequence.
  std::array<double, 4> start_jacobian{};
  double eps = 1e-5;        ///< stop when |ΔFX| (+ |ΔFY|) ≤ eps
  int max_iterations = 30;  ///< MAXNR
};

struct ForceIterationResult {
  double ksi = 0.0, eta = 0.0;
  int iterations = 0;
  bool converged = false;
  std::string message;
  std::array<double, 4> jacobian{};  ///< d(FX, FY)/(μFN) by d(ξ, η), row-major
};

/// `evaluate(ξ, η)` solves the tangential problem and returns (FX, FY)/(μ FN). Newton steps with
/// a start Jacobian (the previous case's, else finite differences) and secant/Broyden updates; for
/// one unknown the root is bracketed as soon as possible and bisection guards the secant steps (the
/// creep curve is monotone).
ForceIterationResult force_iteration(
    const ForceIterationInput& in,
    const std::function<std::array<double, 2>(double, double)>& evaluate);

}  // namespace rollcontact
