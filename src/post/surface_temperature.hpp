#pragma once
// Surface temperatures of steady rolling (CONTACT H ≥ 1, spec/physics.md §15): the bodies enter
// the contact at their bulk temperatures, take a common temperature while in contact, relax
// back behind it, and heat up by the frictional (and plastic) work, which each row of elements
// carries downstream like a moving heat source on a half-space (Jaeger's large-Péclet limit:
// heat conducts only into the depth, so rows do not exchange heat).
//
// Units: mm, s, N/mm², °C; heat fluxes in N/(mm·s) = mW/mm².

#include <vector>

#include "rollcontact/model/heat.hpp"
#include "rollcontact/solution.hpp"

namespace rollcontact::post {

/// TEMP1, TEMP2 per element [°C] and their maxima over the contact.
struct SurfaceTemperatures {
  std::vector<double> temp1, temp2;
  double max1 = 0.0, max2 = 0.0;
};

/// Temperature rise at a distance `distance_mm` downstream of the centre of an element of length
/// `dx_mm` that carries a uniform unit flux, in units of f = 2/(β·√(πV)):
/// √(d + δx/2) − √(d − δx/2), and 2√(δx/2) for the element itself (d = 0) as physics.md §15
/// prescribes. 0 upstream (d < 0).
double flash_kernel(double distance_mm, double dx_mm);

/// Frictional heat flux per element [mW/mm²]: (|S|/δt + β_pl·|Δu_pl|/δt)·|p_t| in slip and
/// plastic elements, 0 elsewhere. S = sx·δq (Solution::sx is S/δq); `plastic_flow_mm` holds
/// |Δu_pl| of this step per element (empty: no plastic layer).
std::vector<double> frictional_heat_flux(const Solution& solution, double plastic_heat_fraction,
                                         const std::vector<double>& plastic_flow_mm);

/// Surface temperatures of a solved case. `rolling`: steady rolling (T=3) along x, χ = 0 rolling
/// towards +x (leading edge at high ix), χ = π towards −x (the direction is the sign of cos χ),
/// at V = Solution::kinematics.veloc. Not rolling (T=0): the bulk temperatures are the result.
SurfaceTemperatures surface_temperatures(const model::SurfaceHeat& heat, const Solution& solution,
                                         bool rolling,
                                         const std::vector<double>& plastic_flow_mm = {});

}  // namespace rollcontact::post
