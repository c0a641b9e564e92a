#include "elastic/operators/rolling_difference.hpp"

namespace rollcontact::elastic::operators {

Kernel difference(const Kernel& a, const Kernel& b) {
  Kernel d(a.mx(), a.my());
  for (int diy = -(a.my() - 1); diy < a.my(); ++diy)
    for (int dix = -(a.mx() - 1); dix < a.mx(); ++dix)
      d.at(dix, diy) = a.at(dix, diy) - b.at(dix, diy);
  return d;
}

}  // namespace rollcontact::elastic::operators
