#include "wheelrail/friction_variation.hpp"

#include <algorithm>

namespace rollcontact::wheelrail {

model::Friction friction_at(const model::FrictionVariation& variation, double key) {
  const auto& x = variation.positions;
  const auto& f = variation.values;
  if (x.empty() || f.size() != x.size()) return {};
  if (key <= x.front()) return f.front();
  if (key >= x.back()) return f.back();
  const std::size_t k =
      static_cast<std::size_t>(std::upper_bound(x.begin(), x.end(), key) - x.begin()) - 1;
  const double t = (key - x[k]) / (x[k + 1] - x[k]);
  return {f[k].static_coefficient + t * (f[k + 1].static_coefficient - f[k].static_coefficient),
          f[k].kinetic_coefficient + t * (f[k + 1].kinetic_coefficient - f[k].kinetic_coefficient)};
}

}  // namespace rollcontact::wheelrail
