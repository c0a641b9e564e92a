#pragma once
// The frictional tangential problem for a fixed pressure (spec/physics.md §5–6, §9):
//
//   S = b + A·p_t  on the contact elements,
//   adhesion: S = 0, |p_t| ≤ g;   slip: |p_t| = g, p_t = −g·S/|S|,
//
// with g = μ·p_n the traction bound, b the slip for p_t = 0 (rigid shift, normal coupling and
// the previous-time displacement) and A the tangential influence operator per step: C_tt/G for
// shifts and transient rolling (symmetric), (C − C′)_tt/G for steady rolling.

#include <functional>
#include <string>
#include <vector>

#include "elastic/block_convolution.hpp"
#include "elastic/influence.hpp"
#include "elastic/interaction.hpp"
#include "rollcontact/grid.hpp"
#include "rollcontact/solution.hpp"
#include "tangential/tangential_preconditioner.hpp"

namespace rollcontact::tangential {

/// The operator A as kernels (for element-wise access) and as an FFT product (2 in, 2 out).
struct TangentialOperator {
  const elastic::Kernel* xx = nullptr;
  const elastic::Kernel* xy = nullptr;
  const elastic::Kernel* yx = nullptr;
  const elastic::Kernel* yy = nullptr;
  elastic::BlockConvolution* product = nullptr;
  /// Approximate C_tt⁻¹·G (block circulant). For steady rolling A = (I − T)·C_tt/G with T the
  /// shift by one element towards the trailing edge, so A⁻¹ ≈ C⁻¹·(I − T)⁻¹ where (I − T)⁻¹ is
  /// a cumulative sum along each row from the leading edge.
  TangentialPreconditioner* preconditioner = nullptr;
  bool symmetric = true;  ///< A = Aᵀ (shift and transient rolling); false: steady rolling
  /// Steady rolling: A = (I − T)·C_tt/G (the preconditioner takes (I − T)⁻¹ as well). Apart
  /// from `symmetric` because turned coefficients (C=4) make A of a shift non-symmetric too.
  bool steady = false;
  /// Attenuation between parts of the grid, already inside `product`; solvers that use kernel
  /// entries directly (Gauss–Seidel) apply f(part I, part J) themselves. nullptr: none.
  const elastic::Interaction* interaction = nullptr;

  /// (u_x, u_y) = A·(p_x, p_y) over the whole grid.
  void apply(const std::vector<double>& px, const std::vector<double>& py, std::vector<double>& ux,
             std::vector<double>& uy) const;
};

struct TangentialSystem {
  Grid grid;
  std::vector<char> contact;   ///< 1 for elements in contact
  std::vector<double> bound;   ///< g = μ p_n [N/mm²]
  std::vector<double> bx, by;  ///< slip at zero tangential traction [mm per step]
  TangentialOperator a;
  double chi = 0.0;  ///< rolling direction (sweep order of SteadyGS)
};

struct TangentialSettings {
  double eps = 1e-5;  ///< relative change of p_t at which iterations stop
  int max_iterations = 999;
  double omega_h = 1.0, omega_s = 1.0;  ///< Gauss–Seidel relaxation in adhesion / slip
  int anderson_depth = 8;               ///< Anderson acceleration of the sweeps (0: off)
  /// Semismooth Newton: the slip the iteration carries (b + A·p of the last iterate, before the
  /// final projection onto the bounds) instead of one more product. For iterates whose slip
  /// nobody reads (the vertical-force iteration's rough solves).
  bool slip_of_last_iterate = false;
};

struct TangentialResult {
  std::vector<double> px, py;  ///< tangential tractions [N/mm²]
  std::vector<double> sx, sy;  ///< slip per step S [mm] (0 outside the contact)
  std::vector<ElementState> state;
  int iterations = 0;
  double residual = 0.0;
  bool converged = false;
  std::string message;
};

/// A result of `n` elements without tractions or slip, every element exterior (not converged:
/// the caller says whether it is an answer or a start).
inline TangentialResult no_tractions(std::size_t n) {
  TangentialResult r;
  r.px.assign(n, 0.0);
  r.py.assign(n, 0.0);
  r.sx.assign(n, 0.0);
  r.sy.assign(n, 0.0);
  r.state.assign(n, ElementState::Exterior);
  return r;
}

/// Classifies and finalises a traction field: S = b + A p, states from |p| vs g. With `sx`, `sy`
/// (full-grid slip known already) they are taken for S instead of a product.
void finalise(const TangentialSystem& sys, TangentialResult& res,
              const std::vector<double>* sx = nullptr, const std::vector<double>* sy = nullptr);

/// One Gauss–Seidel sweep (or other fixed-point map) applied to the tractions in place.
using SweepFunction = std::function<void(std::vector<double>& px, std::vector<double>& py)>;

/// Iterates `sweep` with Anderson acceleration until the relative change of a sweep is below
/// settings.eps; tractions are kept within the traction bound. Sets iterations, residual,
/// converged and message of `res` (whose px, py hold the start and then the result).
void iterate_with_acceleration(const TangentialSystem& sys, const TangentialSettings& settings,
                               TangentialResult& res, const SweepFunction& sweep, const char* name);

/// Preconditioned block-Jacobi with Anderson acceleration: each iteration takes a global step
/// δ = −M·S on the adhesion elements (M ≈ A⁻¹ by FFT) and then solves every element's local
/// problem exactly against the updated slip. The local solves make the fixed points exactly the
/// Coulomb solutions; the global step carries the long-range elastic coupling that limits
/// Gauss–Seidel. Two products with A per iteration. Needs sys.a.preconditioner.
TangentialResult solve_preconditioned_jacobi(const TangentialSystem& sys,
                                             const TangentialSettings& settings,
                                             const std::vector<double>* px0 = nullptr,
                                             const std::vector<double>* py0 = nullptr);

/// Semismooth Newton iteration on F(p) = p − P_g(p − r·S) with Krylov inner solves (PCG for
/// symmetric A, GMRES for steady rolling) and a line search on ‖F‖; see semismooth_newton.cpp.
/// `iterations` counts the products with A. Needs sys.a.preconditioner.
TangentialResult solve_semismooth_newton(const TangentialSystem& sys,
                                         const TangentialSettings& settings,
                                         const std::vector<double>* px0 = nullptr,
                                         const std::vector<double>* py0 = nullptr);

/// Gauss–Seidel over all contact elements with the exact local element solution (physics.md
/// §9.3 "ConvexGS"), accelerated by Anderson mixing. Up to 4000 contact elements the slip of
/// all others is updated after each element (exact, O(N²) per sweep); above, only within two
/// rows, the rest being refreshed by an FFT product per sweep.
TangentialResult solve_convex_gs(const TangentialSystem& sys, const TangentialSettings& settings,
                                 const std::vector<double>* px0 = nullptr,
                                 const std::vector<double>* py0 = nullptr);

}  // namespace rollcontact::tangential
