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
  auto lerp = [t](double a, double b) { return a + t * (b - a); };
  // Every parameter of the law is interpolated (spec-additions A8); the law and the memory
  // line are shared by all sets.
  model::Friction out = f[k];
  out.static_coefficient = lerp(f[k].static_coefficient, f[k + 1].static_coefficient);
  out.kinetic_coefficient = lerp(f[k].kinetic_coefficient, f[k + 1].kinetic_coefficient);
  for (std::size_t j = 0; j < out.terms.size(); ++j) {
    out.terms[j].coefficient = lerp(f[k].terms[j].coefficient, f[k + 1].terms[j].coefficient);
    out.terms[j].speed_mm_s = lerp(f[k].terms[j].speed_mm_s, f[k + 1].terms[j].speed_mm_s);
  }
  return out;
}

}  // namespace rollcontact::wheelrail
