#pragma once
// Effective kinematics (CONTACT's silent adjustments, spec/physics.md §14) and the rigid slip of
// each element (§5).

#include <vector>

#include "rollcontact/grid.hpp"
#include "rollcontact/model/patch_problem.hpp"
#include "rollcontact/solution.hpp"

namespace rollcontact::tangential {

/// Which tangential solver a case uses (physics.md §9.1).
enum class TangentialSolverKind { None, TangCG, ConvexGS, SteadyGS };

/// The solver selected by the tangential problem and the solver options before the
/// trailing-edge check (CONTACT's T and G digits).
TangentialSolverKind select_solver(const model::PatchProblem& problem);

/// χ, δq, V and δt after the adjustments of physics.md §14 (T=0,1: χ=0, δq=1, V=1; T=3: δq = δx
/// with every solver, and χ → 0 or π with SteadyGS and the simplified theories, χ := 0 for
/// viscoelastic bodies). `warnings` receives a message when a value is changed by more than
/// CONTACT's 1 % threshold.
EffectiveKinematics effective_kinematics(const model::PatchProblem& problem, const Grid& grid,
                                         std::vector<std::string>* warnings = nullptr);

/// Rigid shift per step W = δq·w [mm] (T=2,3) or the rigid shift [mm] (T=1) of every element,
/// for creepages (ξ, η, φ) [-, -, rad/mm] (T=1: shifts [mm, mm, rad]).
struct RigidShift {
  std::vector<double> wx, wy;
};
RigidShift rigid_shift(const Grid& grid, const model::PatchProblem& problem,
                       const EffectiveKinematics& kin, double cksi, double ceta, double cphi);

}  // namespace rollcontact::tangential
