// TangCG: placeholder delegating to ConvexGS until the CG solver lands.

#include "tangential/tangential_system.hpp"

namespace rollcontact::tangential {

TangentialResult solve_tang_cg(const TangentialSystem& sys, const TangentialSettings& settings,
                               const std::vector<double>* px0, const std::vector<double>* py0) {
  return solve_convex_gs(sys, settings, px0, py0);
}

}  // namespace rollcontact::tangential
