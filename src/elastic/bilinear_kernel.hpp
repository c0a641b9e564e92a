#pragma once
// Influence coefficients of bilinear ("hat") traction elements (CONTACT C=3,
// spec-additions.md §B7): the Boussinesq–Cerruti kernels integrated against a hat of support
// 2δx × 2δy centred on the source element's centre, displacements at element centres.

#include <vector>

#include "elastic/influence.hpp"

namespace rollcontact::elastic {

/// C_ij of a unit hat for the observation-minus-source offset (ox, oy) [mm] on elements of
/// dx × dy [mm], WITHOUT 1/G, in the normalisation of §B7: the hat carries the load dx·dy of a
/// unit constant element, so far from the load C_ij equals influence_coefficient to
/// O((δ/r)²). Coupling components are 0 when |k| < kCouplingThreshold.
double bilinear_coefficient(Component c, double ox, double oy, double dx, double dy, double nu,
                            double k);

/// Components cs for every grid offset, divided by G, from one evaluation of the integrals per
/// offset (elastic part only: make_kernels adds the layer compliance). shift_x, shift_y [mm] move
/// the observation point (rolling, §3.2). Unshifted kernels are exactly even or odd in x and y.
std::vector<Kernel> bilinear_kernels(const std::vector<Component>& cs, const Grid& grid,
                                     const CombinedMaterial& material, double shift_x,
                                     double shift_y);

}  // namespace rollcontact::elastic
