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
  lib.kernel(Component::nn, grid(16, 16), m);  // keeps 16 × 16: its own size first
  EXPECT_EQ(lib.computed(), 1u);
  lib.kernel(Component::nn, grid(16, 8), m);  // inside: cut
  lib.kernel(Component::nn, grid(4, 4), m);
  EXPECT_EQ(lib.computed(), 1u);
  lib.kernel(Component::nn, grid(17, 8), m);  // outgrows in x: keeps 22 × 16 (a margin)
  EXPECT_EQ(lib.computed(), 2u);
  lib.kernel(Component::nn, grid(22, 16), m);  // inside the margin: cut
  EXPECT_EQ(lib.computed(), 2u);
  lib.kernel(Component::nn, grid(23, 8), m);  // outgrows again
  EXPECT_EQ(lib.computed(), 3u);
  lib.kernel(Component::yy, grid(4, 4), m);  // another component, element size or material
  lib.kernel(Component::nn, {.mx = 4, .my = 4, .xl = 0, .yl = 0, .dx = 0.1, .dy = 0.25}, m);
  lib.kernel(Component::nn, grid(4, 4), {.g = 2.0, .nu = 0.3, .k = 0.0});
  EXPECT_EQ(lib.computed(), 6u);
  // A budget too small to keep anything: every request tabulates, results unchanged.
  KernelLibrary none(16);
  none.kernel(Component::nn, grid(8, 8), m);
  EXPECT_EQ(none.kernel(Component::nn, grid(8, 8), m).data(),
            make_kernel(Component::nn, grid(8, 8), m).data());
  EXPECT_EQ(none.computed(), 2u);
}

}  // namespace
}  // namespace rollcontact::elastic
