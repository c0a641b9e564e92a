#pragma once
// Influence kernels kept for reuse across grid sizes. A kernel depends on the component, the
// element size, the material and the rolling shift, but not on MX, MY: the kernel of a grid is
// the centre of the kernel of any larger grid with the same elements, value for value (the same
// corner abscissae, the same operations). Wheel/rail patches change their MX, MY from case to
// case and within the vertical-force iteration; cutting the kernel out of a kept larger one
// replaces the closed forms (logarithms in long double, most of the set-up time) by a copy.
// A kernel is tabulated at the grid's own size (one element more each way) first and with a
// margin once a grid outgrew it. A rolling shift of whole elements (steady rolling's step of
// one element) is no tabulation of its own: it is the unshifted kernel read that many offsets
// on, bit for bit.

#include <array>
#include <cstddef>
#include <list>
#include <optional>
#include <vector>

#include "elastic/influence.hpp"

namespace rollcontact::elastic {

class KernelLibrary {
 public:
  /// At most `budget_bytes` of kernels are kept (least recently used dropped first); a kernel
  /// larger than a quarter of it is made directly and not kept (large module-3 grids build their
  /// operators once, and their kernels would only double the memory).
  explicit KernelLibrary(std::size_t budget_bytes = std::size_t{64} << 20)
      : budget_bytes_(budget_bytes) {}

  /// Equal to make_kernel(c, grid, material, shift_x, shift_y).
  Kernel kernel(Component c, const Grid& grid, const CombinedMaterial& material,
                double shift_x = 0.0, double shift_y = 0.0);
  /// A kernel of component c for the grid's elements and material (no rolling shift) with at
  /// least the grid's MX, MY: at(dix, diy) for |dix| < MX, |diy| < MY equals make_kernel(c, grid,
  /// m)'s value for value, without the copy that kernel() cuts out. Valid until the next call.
  const Kernel& covering(Component c, const Grid& grid, const CombinedMaterial& m);
  /// Equal to make_kernels(cs, …): the components not kept are tabulated together (shared
  /// logarithms, elastic/influence.hpp).
  std::vector<Kernel> kernels(const std::vector<Component>& cs, const Grid& grid,
                              const CombinedMaterial& material, double shift_x = 0.0,
                              double shift_y = 0.0);

  std::size_t computed() const noexcept { return computed_; }  ///< closed-form tabulations

 private:
  /// A kept kernel: always a plain one (the inclination correction, C=4, turns kept plain
  /// kernels in kernels(), and a variant without curvature has the plain coefficients).
  struct Entry {
    Component c;
    double dx, dy, g, nu, k, layer, normal_layer, shift_x, shift_y;
    std::array<ViscousCompliance, 2> viscous;
    model::TractionElements elements;
    Kernel kernel;
  };
  static bool matches(const Entry& e, Component c, const Grid& grid, const CombinedMaterial& m,
                      double shift_x, double shift_y);
  /// The kept kernel cut to `grid`, or none; then `big` is the size to tabulate at (the grid's
  /// own, or with a margin when the grid outgrew a kept kernel, which is dropped).
  std::optional<Kernel> cut_kept(Component c, const Grid& grid, const CombinedMaterial& m,
                                 double shift_x, double shift_y, Grid& big);

  /// The kept kernel of (c, grid's elements, m, no shift) with at least the grid's size, if any
  /// (moved to the front of entries_).
  const Kernel* find_covering(Component c, const Grid& grid, const CombinedMaterial& m);

  std::size_t budget_bytes_, kept_bytes_ = 0;
  Kernel scratch_;            ///< covering()'s answer where no kept kernel covers the grid
  std::list<Entry> entries_;  ///< most recently used first
  std::size_t computed_ = 0;
};

/// The (2mx−1) × (2my−1) offsets of a kernel of at least (mx + |ox|) × (my + |oy|) elements
/// around its offset (ox, oy): its centre by default, the kernel seen (ox, oy) elements away
/// otherwise (a rolling shift of whole elements).
Kernel cut_kernel(const Kernel& big, int mx, int my, int ox = 0, int oy = 0);

}  // namespace rollcontact::elastic
