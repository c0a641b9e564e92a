// SteadyGS: steady rolling by Gauss–Seidel sweeps, rows from the trailing to the leading edge,
// with Anderson acceleration (see convex_gs.cpp: the sweeps are shared; for large grids the
// within-sweep updates are limited to a band of rows and the rest is refreshed by FFT).

#include "tangential/tangential_system.hpp"

namespace rollcontact::tangential {

TangentialResult solve_steady_gs(const TangentialSystem& sys, const TangentialSettings& settings,
                                 const std::vector<double>* px0, const std::vector<double>* py0) {
  return solve_convex_gs(sys, settings, px0, py0);
}

}  // namespace rollcontact::tangential
