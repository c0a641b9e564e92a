#pragma once
// Steady rolling sees the slip per rolling step: the displacement now minus the displacement of
// the same particle one step (shift_x, shift_y) [mm] earlier, i.e. the operator C − C′ with C′
// the coefficients observed one step downstream (spec/physics.md §3.2, §6).

#include "elastic/influence.hpp"

namespace rollcontact::elastic::operators {

/// a − b element-wise; both kernels on the same grid.
Kernel difference(const Kernel& a, const Kernel& b);

}  // namespace rollcontact::elastic::operators
