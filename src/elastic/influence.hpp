#pragma once
// Closed-form influence coefficients of piecewise-constant tractions on a half-space
// (Boussinesq–Cerruti, spec/physics.md §3.2) and their tabulation on a grid (kernels).

#include <vector>

#include "rollcontact/grid.hpp"
#include "rollcontact/solution.hpp"

namespace rollcontact::elastic {

/// Displacement component i due to traction component j. C_nx = −C_xn, C_ny = −C_yn, C_yx = C_xy.
enum class Component { nn, xx, yy, xy, xn, yn, nx, ny, yx };

/// C_ij for an observation-minus-source offset (ox, oy) [mm] on elements of size dx × dy [mm],
/// WITHOUT the factor 1/G: u_i = (1/G) Σ C_ij p_j. Returns mm (displacement per N/mm² times G).
double influence_coefficient(Component c, double ox, double oy, double dx, double dy, double nu,
                             double k);

/// Coefficients of one component for every grid offset (dix, diy), dix ∈ [−(mx−1), mx−1],
/// diy ∈ [−(my−1), my−1], already divided by G: u_I = Σ_J kernel(ix_I−ix_J, iy_I−iy_J) p_J.
/// shift_x/shift_y move the observation point (rolling: previous-time displacement, §3.2).
class Kernel {
 public:
  Kernel() = default;
  Kernel(int mx, int my);
  int mx() const noexcept { return mx_; }
  int my() const noexcept { return my_; }
  double& at(int dix, int diy) noexcept { return data_[index(dix, diy)]; }
  double at(int dix, int diy) const noexcept { return data_[index(dix, diy)]; }
  const std::vector<double>& data() const noexcept { return data_; }
  /// this += w·other, offset by offset (same mx, my).
  void add_scaled(const Kernel& other, double w) noexcept {
    for (std::size_t i = 0; i < data_.size(); ++i) data_[i] += w * other.data_[i];
  }

 private:
  std::size_t index(int dix, int diy) const noexcept {
    return static_cast<std::size_t>(dix + mx_ - 1) +
           static_cast<std::size_t>(2 * mx_ - 1) * static_cast<std::size_t>(diy + my_ - 1);
  }
  int mx_ = 0, my_ = 0;
  std::vector<double> data_;
};

/// |K| below this: the coupling terms are dropped and the normal and tangential problems are
/// solved apart (spec §3.2; K = 0 within rounding for equal materials).
inline constexpr double kCouplingThreshold = 1e-6;

/// True when the material couples the normal and tangential problems (|K| ≥ threshold, or a
/// viscous part with a coupling of that size: dissimilar viscoelastic bodies). Coefficients from
/// a file couple when the file has coupling terms, whatever K the material lines give; turned
/// coefficients (C=4 with a curvature) always couple.
inline bool is_coupled(const CombinedMaterial& material) noexcept {
  if (material.table) return material.table->coupled;
  // Turned coefficients (C=4) carry part of a normal load into tangential displacements and
  // back even for quasi-identical bodies (wheelrail-advanced.md §1.7).
  if (material.inclination_corrected()) return true;
  const auto large = [](double k) { return k >= kCouplingThreshold || k <= -kCouplingThreshold; };
  return large(material.k) || large(material.viscous[0].weight * material.viscous[0].k) ||
         large(material.viscous[1].weight * material.viscous[1].k);
}

/// Tabulates component c of the influence matrix for the grid and material (divided by G),
/// including an interfacial layer's compliance and the viscous parts of viscoelastic bodies
/// (elastic/viscous_kernel.hpp). With material.table (C=9) the coefficients come from the table
/// (elastic/table_kernel.hpp) instead of the closed forms; with material.elements bilinear (C=3)
/// from the bilinear elements' closed forms (elastic/bilinear_kernel.hpp).
Kernel make_kernel(Component c, const Grid& grid, const CombinedMaterial& material,
                   double shift_x = 0.0, double shift_y = 0.0);

/// make_kernel for several components on the same grid, bit for bit: nn, xx, yy and xy are
/// tabulated together on one corner lattice (their logarithms shared).
std::vector<Kernel> make_kernels(const std::vector<Component>& cs, const Grid& grid,
                                 const CombinedMaterial& material, double shift_x = 0.0,
                                 double shift_y = 0.0);

/// The elastic corner sums of make_kernel (no layer, no viscous part) without CONTACT's guard
/// that drops a log term below δx·1e−10 (physics.md §3.2): that guard, harmless at the fixed
/// offsets of make_kernel, makes the coefficients jump by ~1e-3 where a corner passes within
/// ~1e-4 mm of an axis (2-D strips), which an integral over the shift must not see. Continuous
/// in the shift; x·log x = 0 at x = 0 only.
Kernel make_continuous_kernel(Component c, const Grid& grid, const CombinedMaterial& material,
                              double shift_x = 0.0, double shift_y = 0.0);

/// A linear rule along x that replaces the corner function F at each corner abscissa X_i of a
/// kernel's corner lattice, X_i = (i − mx + ½)·dx + shift_x, i = 0 … 2mx−1, by
///   G_i = Σ_{k ∈ [begin[i], begin[i+1])} weight[k]·F(x_mm[k], Y) + carry[i]·G_{i+1},
/// evaluated from the last corner backwards (its carry is 0). For an integral over the
/// observation point's history this is a recursion: G_i = ∫ over [X_i, X_{i+1}] + decay·G_{i+1}.
struct CornerXRule {
  std::vector<long double> x_mm;    ///< abscissae where F is evaluated [mm]
  std::vector<long double> weight;  ///< one per abscissa [-]
  std::vector<std::size_t> begin;   ///< 2mx + 1 offsets into x_mm
  std::vector<long double> carry;   ///< 2mx factors [-]
};

/// make_continuous_kernel with every corner's F replaced by the rule's G (rows at the corner
/// ordinates (j − my + ½)·dy + shift_y): the kernel of Σ_k weight_k·C at the shifted observation
/// points the rule stands for, with F evaluated once per abscissa and row instead of once per
/// abscissa and corner; nn, xx, yy and xy of one call share their logarithms.
std::vector<Kernel> make_integrated_kernels(const std::vector<Component>& cs, const Grid& grid,
                                            const CombinedMaterial& material, double shift_y,
                                            const CornerXRule& rule);

/// make_kernel's elastic corner sums with the corner function evaluated at every corner, nothing
/// shared between mirrored corners: the reference that tests compare make_kernel with, bit for
/// bit.
Kernel make_unshared_kernel(Component c, const Grid& grid, const CombinedMaterial& material,
                            double shift_x = 0.0, double shift_y = 0.0);

}  // namespace rollcontact::elastic
