#pragma once
// The normal contact problem for a non-symmetric influence operator: viscoelastic rolling (M=1),
// where the displacement at x depends on the pressure upstream more than downstream.
//
// NormCG (normal_solver.hpp) minimises ½pᵀAp + pᵀ(h − PEN) and needs A symmetric; with M=1 it is
// not, and the problem is the linear complementarity problem itself: p ≥ 0, e = h − PEN + A·p ≥ 0,
// p·e = 0 (plus δxδy·Σp = FN for a prescribed force). A is positive definite in the sense
// pᵀAp > 0 (elastic energy plus the dissipation of the dashpots), so the solution is unique.
// It is found by the classic active-set iteration (Kalker's NORM): solve the equalities e = 0 on
// a contact set C exactly, drop the elements that came out in tension, else add the exterior
// ones that penetrate, until neither happens. The equalities A_CC·p = PEN − h_C are solved by
// GMRES with the FFT product restricted to C; no preconditioner (spec-additions §B5: the
// circulant preconditioner of NormCG is not used with M=1). A prescribed force is met by
// superposition: p = r + PEN·q with A_CC·r = −h_C, A_CC·q = 1 and PEN from the force.

#include <vector>

#include "elastic/convolution.hpp"
#include "normal/normal_solver.hpp"
#include "rollcontact/grid.hpp"

namespace rollcontact::normal {

class ActiveSetNormalSolver {
 public:
  /// `a` applies the influence operator (C_nn/G) on the whole grid.
  ActiveSetNormalSolver(const Grid& grid, elastic::LinearOperator& a) : grid_(grid), a_(a) {}

  /// As NormalSolver::solve: h [mm] (≥ 1e29: excluded), `value` PEN [mm] or FN [N], `initial`
  /// an optional starting pressure (its support is the first contact set). NormalResult's
  /// `iterations` counts GMRES steps, `set_changes` the active-set passes (at most
  /// settings.max_iterations).
  NormalResult solve(const std::vector<double>& h, NormalLoad load, double value,
                     const NormalSettings& settings, const std::vector<double>* initial = nullptr,
                     double poisson = 0.3, double modulus = 1.0);

 private:
  /// p on the contact set (zero elsewhere) with zero gap there; returns false if GMRES failed.
  bool solve_on_set(const std::vector<double>& h, const std::vector<int>& set, bool force_given,
                    double value, std::vector<double>& p, double& pen, NormalResult& res);

  Grid grid_;
  elastic::LinearOperator& a_;
};

}  // namespace rollcontact::normal
