// KernelLibrary: kernels cut from a kept larger one are the kernels make_kernel tabulates, value
// for value, and the closed forms run only when a grid outgrows what is kept.

#include <gtest/gtest.h>

#include "elastic/kernel_library.hpp"

namespace rollcontact::elastic {
namespace {

Grid grid(int mx, int my) {
  return {.mx = mx, .my = my, .xl = 0, .yl = 0, .dx = 0.2, .dy = 0.25};
}

TEST(KernelLibrary, CutKernelsEqualTabulatedOnesExactly) {
  const CombinedMaterial m{.g = 82000.0, .nu = 0.28, .k = 0.03};
  KernelLibrary lib;
  for (Component c : {Component::nn, Component::xx, Component::xy, Component::xn}) {
    for (auto [mx, my] :
         {std::pair{16, 12}, std::pair{9, 20}, std::pair{18, 14}, std::pair{3, 2}}) {
      for (double shift : {0.0, 0.2}) {
        const Kernel a = lib.kernel(c, grid(mx, my), m, shift, 0.0);
        const Kernel b = make_kernel(c, grid(mx, my), m, shift, 0.0);
        ASSERT_EQ(a.mx(), mx);
        ASSERT_EQ(a.my(), my);
        EXPECT_EQ(a.data(), b.data()) << static_cast<int>(c) << " " << mx << "x" << my;
      }
    }
  }
}

TEST(KernelLibrary, SeveralComponentsAtOnceEqualTheirKernels) {
  const CombinedMaterial m{.g = 82000.0, .nu = 0.28, .k = 0.03};
  KernelLibrary lib;
  lib.kernel(Component::nn, grid(12, 10), m);  // kept: cut, the others tabulated together
  const std::vector<Component> cs{Component::xx, Component::nn, Component::xn, Component::yy};
  for (auto [mx, my] : {std::pair{12, 10}, std::pair{14, 9}, std::pair{5, 5}}) {
    const std::vector<Kernel> k = lib.kernels(cs, grid(mx, my), m, 0.2, 0.0);
    for (std::size_t q = 0; q < cs.size(); ++q)
      EXPECT_EQ(k[q].data(), make_kernel(cs[q], grid(mx, my), m, 0.2, 0.0).data())
          << static_cast<int>(cs[q]) << " " << mx << "x" << my;
  }
}

TEST(KernelLibrary, TabulatesOnlyWhenAGridOutgrowsTheKeptKernel) {
  const CombinedMaterial m{.g = 1.0, .nu = 0.3, .k = 0.0};
  KernelLibrary lib;
  lib.kernel(Component::nn, grid(16, 16), m);  // keeps 17 × 17: its own size and one more
  EXPECT_EQ(lib.computed(), 1u);
  lib.kernel(Component::nn, grid(16, 8), m);  // inside: cut
  lib.kernel(Component::nn, grid(4, 4), m);
  lib.kernel(Component::nn, grid(17, 17), m);  // a rolling step's one element more
  EXPECT_EQ(lib.computed(), 1u);
  lib.kernel(Component::nn, grid(18, 8), m);  // outgrows in x: keeps 25 × 17 (1.5 × 17)
  EXPECT_EQ(lib.computed(), 2u);
  lib.kernel(Component::nn, grid(25, 17), m);  // inside the margin: cut
  EXPECT_EQ(lib.computed(), 2u);
  lib.kernel(Component::nn, grid(26, 8), m);  // outgrows again: 37 × 17
  EXPECT_EQ(lib.computed(), 3u);
  lib.kernel(Component::nn, grid(37, 17), m);
  EXPECT_EQ(lib.computed(), 3u);
  lib.kernel(Component::nn, grid(30, 18), m);  // outgrows in y: 38 (30 + ¼) × 25 (1.5 × 17)
  EXPECT_EQ(lib.computed(), 4u);
  lib.kernel(Component::nn, grid(38, 25), m);
  EXPECT_EQ(lib.computed(), 4u);
  lib.kernel(Component::yy, grid(4, 4), m);  // another component, element size or material
  lib.kernel(Component::nn, {.mx = 4, .my = 4, .xl = 0, .yl = 0, .dx = 0.1, .dy = 0.25}, m);
  lib.kernel(Component::nn, grid(4, 4), {.g = 2.0, .nu = 0.3, .k = 0.0});
  EXPECT_EQ(lib.computed(), 7u);
  // A budget too small to keep anything: every request tabulates, results unchanged.
  KernelLibrary none(16);
  none.kernel(Component::nn, grid(8, 8), m);
  EXPECT_EQ(none.kernel(Component::nn, grid(8, 8), m).data(),
            make_kernel(Component::nn, grid(8, 8), m).data());
  EXPECT_EQ(none.computed(), 2u);
}

TEST(KernelLibrary, ShiftsOfWholeElementsAreTheUnshiftedKernelReadOffsetsOn) {
  // Steady rolling shifts by one element: the kernels come from the unshifted ones, bit for
  // bit equal to a tabulation on the shifted lattice, with an interfacial layer's compliance
  // at the element the shifted point lands in; a shift of part of an element is tabulated.
  const CombinedMaterial steel{.g = 82000.0, .nu = 0.28, .k = 0.0};
  CombinedMaterial layered = steel;
  layered.layer_compliance = 2e-6;
  layered.normal_layer_compliance = 1e-6;
  for (const CombinedMaterial& m : {steel, layered}) {
    for (double d : {0.5, 0.2, 0.1, 1.0 / 3.0}) {
      const Grid g{.mx = 24, .my = 40, .xl = 0, .yl = 0, .dx = d, .dy = 0.7 * d};
      KernelLibrary lib;
      const std::vector<Component> cs{Component::xx, Component::xy, Component::yy, Component::nn};
      lib.kernels(cs, g, m);  // the unshifted ones kept
      const std::size_t tabulated = lib.computed();
      for (auto [sx, sy] :
           {std::pair{1.0, 0.0}, std::pair{-1.0, 0.0}, std::pair{2.0, 1.0}, std::pair{0.0, -1.0}}) {
        const std::vector<Kernel> k = lib.kernels(cs, g, m, sx * g.dx, sy * g.dy);
        for (std::size_t q = 0; q < cs.size(); ++q)
          EXPECT_EQ(k[q].data(), make_kernel(cs[q], g, m, sx * g.dx, sy * g.dy).data())
              << static_cast<int>(cs[q]) << " dx " << d << " shift " << sx << "," << sy;
      }
      // Within the unshifted kernels' margin after the first outgrowing request.
      EXPECT_LE(lib.computed(), tabulated + cs.size());
      const std::size_t before_part = lib.computed();
      const Kernel part = lib.kernel(Component::xx, g, m, 0.5 * g.dx, 0.0);
      EXPECT_EQ(part.data(), make_kernel(Component::xx, g, m, 0.5 * g.dx, 0.0).data());
      EXPECT_EQ(lib.computed(), before_part + 1);
    }
  }
}

}  // namespace
}  // namespace rollcontact::elastic

namespace rollcontact::elastic {
namespace {

TEST(KernelLibrary, CoveringKernelsReadLikeTheGridsOwn) {
  const CombinedMaterial m{.g = 82000.0, .nu = 0.28, .k = 0.0};
  KernelLibrary lib;
  lib.kernel(Component::nn, grid(30, 50), m);  // kept at 31 × 51
  for (auto [mx, my] : {std::pair{24, 40}, std::pair{30, 50}, std::pair{35, 20}}) {
    const Kernel& c = lib.covering(Component::nn, grid(mx, my), m);
    ASSERT_GE(c.mx(), mx);
    ASSERT_GE(c.my(), my);
    const Kernel own = make_kernel(Component::nn, grid(mx, my), m);
    for (int diy = -(my - 1); diy <= my - 1; ++diy)
      for (int dix = -(mx - 1); dix <= mx - 1; ++dix)
        ASSERT_EQ(c.at(dix, diy), own.at(dix, diy))
            << mx << "x" << my << " at " << dix << ", " << diy;
  }
  EXPECT_EQ(lib.computed(), 2u);  // 35 × 20 outgrew the kept kernel in x: tabulated once more
}

}  // namespace
}  // namespace rollcontact::elastic
