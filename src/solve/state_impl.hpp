#pragma once
// What a PatchSolver holds: cached operators per grid and material, and the previous solution.

#include <memory>
#include <optional>
#include <vector>

#include "elastic/block_convolution.hpp"
#include "elastic/convolution.hpp"
#include "elastic/influence.hpp"
#include "normal/preconditioner.hpp"
#include "rollcontact/solve.hpp"
#include "tangential/tangential_system.hpp"

namespace rollcontact {

inline bool same_grid_and_material(const Grid& a, const Grid& b, const CombinedMaterial& m,
                                   const CombinedMaterial& n) noexcept {
  return a.mx == b.mx && a.my == b.my && a.dx == b.dx && a.dy == b.dy && m.g == n.g &&
         m.nu == n.nu && m.k == n.k;
}

/// The normal influence operator of one grid/material, with its FFT plans and preconditioner.
struct NormalOperators {
  Grid grid;
  CombinedMaterial material;
  elastic::Kernel kernel;
  std::unique_ptr<elastic::FftConvolution> product;
  std::unique_ptr<normal::CirculantPreconditioner> preconditioner;
};

/// Tangential operators of one grid/material/rolling step:
///  a     — A = C_tt/G (T=1,2) or (C − C′)_tt/G (T=3) as kernels and FFT product;
///  prev  — (u′_x, u′_y) from (p_x, p_y, p_n) of the previous time with C′ (T=2) or C (T=1);
///  tn    — tangential displacement per step due to p_n (K ≠ 0), with C or C − C′;
///  nt    — normal displacement due to (p_x, p_y) with C (K ≠ 0).
struct TangentialOperators {
  Grid grid;
  CombinedMaterial material;
  int t = 0;
  double shift_x = 0.0, shift_y = 0.0;
  elastic::Kernel xx, xy, yy;
  std::unique_ptr<elastic::BlockConvolution> a;
  elastic::Kernel prev_xx, prev_xy, prev_yy, prev_xn, prev_yn;
  std::unique_ptr<elastic::BlockConvolution> prev;
  elastic::Kernel tn_x, tn_y, nt_x, nt_y;
  std::unique_ptr<elastic::BlockConvolution> tn, nt;
  /// Plain C (3×3 with couplings when K ≠ 0) for the displacement fields and elastic energy.
  elastic::Kernel c_xx, c_xy, c_yy, c_xn, c_yn, c_nn;
  std::unique_ptr<elastic::BlockConvolution> full;

  std::unique_ptr<tangential::TangentialPreconditioner> preconditioner;  ///< T=1,2 only

  tangential::TangentialOperator view() const {
    return {&xx, &xy, &xy, &yy, a.get(), preconditioner.get(), t != 3};
  }
};

/// The steady-rolling operator of a coarse level of the nested-iteration start: A = (C − C′)_tt
/// with C′ one (coarse) step downstream, its FFT product and the preconditioner from C_tt.
struct CoarseSteadyOperators {
  Grid grid;
  CombinedMaterial material;
  double shift_x = 0.0, shift_y = 0.0;
  elastic::Kernel xx, xy, yy;
  std::unique_ptr<elastic::BlockConvolution> a;
  std::unique_ptr<tangential::TangentialPreconditioner> preconditioner;

  tangential::TangentialOperator view() const {
    return {&xx, &xy, &xy, &yy, a.get(), preconditioner.get(), false};
  }
};

struct PatchSolver::Impl {
  SolveOptions options;
  std::unique_ptr<NormalOperators> normal;  ///< rebuilt when grid or material change
  /// Operators of the coarser grids of the nested-iteration start, per level (1 = twice as
  /// coarse as `normal`).
  std::vector<std::unique_ptr<NormalOperators>> coarse_normal;
  std::unique_ptr<TangentialOperators> tangential;  ///< rebuilt when grid, material or step change
  /// Steady-rolling operators of the coarser grids (level 1 = twice as coarse as `tangential`).
  std::vector<std::unique_ptr<CoarseSteadyOperators>> coarse_steady;
  std::optional<Solution> previous;  ///< last solved case (P=0 continuation, warm starts)

  /// The normal operators for this grid and material, built on first use and kept.
  NormalOperators& normal_operators(const Grid& grid, const CombinedMaterial& material);
  /// The same for coarse level `level` ≥ 1.
  NormalOperators& coarse_normal_operators(int level, const Grid& grid,
                                           const CombinedMaterial& material);
  /// Coarse steady-rolling operators for level `level` ≥ 1 with the rolling step (shift_x,
  /// shift_y).
  CoarseSteadyOperators& coarse_steady_operators(int level, const Grid& grid,
                                                 const CombinedMaterial& material, double shift_x,
                                                 double shift_y);
  /// The tangential operators for T = 1, 2, 3 with the rolling step (shift_x, shift_y) [mm].
  TangentialOperators& tangential_operators(const Grid& grid, const CombinedMaterial& material,
                                            int t, double shift_x, double shift_y);
};

}  // namespace rollcontact
