#pragma once
// NormCG: the elastic normal contact problem solved by a preconditioned, bound-constrained
// conjugate-gradient method with FFT-based products (spec/physics.md §7.1).
//
// Find p ≥ 0 with gap e = h − PEN + A·p ≥ 0 and p·e = 0 per element, where A is the normal
// influence operator (C_nn/G). Either PEN is given, or the total force dx·dy·Σp = FN and PEN is
// an unknown. The iteration follows Polonsky & Keer (1999): CG steps on the current contact set,
// negative pressures truncated, penetrating exterior elements added with a conjugacy restart;
// for prescribed force the mean gap over the contact set plays the role of PEN. Products are
// preconditioned by an approximate inverse of A (Vollebregt 2014), and the displacement A·p is
// updated incrementally so that one iteration costs one product A·d plus one preconditioner
// application.

#include <string>
#include <vector>

#include "elastic/convolution.hpp"
#include "elastic/influence.hpp"
#include "elastic/interaction.hpp"
#include "normal/preconditioner.hpp"
#include "rollcontact/grid.hpp"

namespace rollcontact::normal {

enum class NormalLoad { Approach, Force };

struct NormalSettings {
  double eps = 1e-5;  ///< stop when ||Δp||_rms ≤ eps·||p||_rms with an unchanged contact set
  int max_iterations = 999;  ///< MAXGS: total CG iterations allowed
};

struct NormalResult {
  std::vector<double> pn;  ///< pressure [N/mm²]
  std::vector<double> un;  ///< normal displacement difference A·p [mm]
  double pen = 0.0;        ///< approach [mm] (given or solved)
  double fn = 0.0;         ///< total force [N] (given or resulting)
  int contact_elements = 0;
  int iterations = 0;              ///< CG iterations
  int set_changes = 0;             ///< iterations in which the contact set changed
  int products = 0;                ///< applications of A (FFT products) in total
  double iteration_seconds = 0.0;  ///< wall time spent in the CG iterations (benchmarks)
  double residual = 0.0;           ///< final ||Δp||_rms / ||p||_rms
  bool converged = false;
  std::string message;
};

class NormalSolver {
 public:
  /// `a` applies C_nn/G on the grid; `kernel` is the same operator tabulated (used for sparse
  /// corrections of A·p when few elements change); `m` is the preconditioner.
  /// `interaction` (optional): the attenuation between parts that `a` applies, needed here for
  /// the sparse corrections.
  NormalSolver(const Grid& grid, elastic::LinearOperator& a, const elastic::Kernel& kernel,
               Preconditioner& m, const elastic::Interaction* interaction = nullptr);

  /// Solves for the undeformed distance h (grid.size() values [mm]; values ≥ 1e29 mark excluded
  /// elements). `value` is PEN [mm] or FN [N]. `initial` (optional, grid.size() values) is a
  /// starting pressure; otherwise an estimate from the geometry is used.
  /// `initial_un`, if given, is A·initial made before (the previous solve's pressure on the
  /// same grid): the start takes it instead of a product of its own.
  NormalResult solve(const std::vector<double>& h, NormalLoad load, double value,
                     const NormalSettings& settings, const std::vector<double>* initial = nullptr,
                     double poisson = 0.3, double modulus = 1.0,
                     const std::vector<double>* initial_un = nullptr);

 private:
  /// Initial pressure (estimate or `initial`, clipped to p ≥ 0, scaled to the force) and its
  /// displacement in res.pn, res.un. Returns false when the start is already the answer (no
  /// element penetrates under a prescribed approach).
  bool start(const std::vector<double>& h, NormalLoad load, double value,
             const std::vector<double>* initial, const std::vector<double>* initial_un,
             double poisson, double modulus, NormalResult& res);
  /// Final consistent displacement, force, approach and contact count, and the independent check
  /// of the contact conditions that may revoke res.converged.
  void finish(const std::vector<double>& h, bool force_given, double value,
              const NormalSettings& settings, NormalResult& res);
  void apply_sparse_correction(const std::vector<int>& changed, const std::vector<double>& delta,
                               std::vector<double>& u);

  Grid grid_;
  elastic::LinearOperator& a_;
  const elastic::Kernel& kernel_;
  Preconditioner& m_;
  const elastic::Interaction* interaction_;
  std::vector<const double*> first_;  // scratch of apply_sparse_correction
};

/// Starting pressure from the geometry alone (physics.md §7.1): a Hertz-like square-root profile
/// on {h − h_min < 0.6·pen_est}, scaled to FN (or to the force estimated from PEN).
/// `poisson`, `modulus` = combined ν and G. Returns zeros when there is no contact.
std::vector<double> initial_pressure(const Grid& grid, const std::vector<double>& h,
                                     NormalLoad load, double value, double poisson, double modulus);

}  // namespace rollcontact::normal
