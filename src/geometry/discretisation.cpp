// From a Problem to grid + undeformed distance (spec/physics.md §2, §4, §8).

#include "geometry/discretisation.hpp"

#include <cmath>
#include <string>

#include "rollcontact/errors.hpp"

namespace rollcontact::geometry {

namespace {

Discretisation build(const model::PatchProblem& problem, const CombinedMaterial& material) {
  const model::PotentialContact& pot = problem.potential;
  Discretisation d;
  if (!pot.hertzian()) {
    d.grid = rectangular_grid(pot);
    d.h = undeformed_distance(d.grid, problem.gap);
    d.parts = planform_parts(d.grid, problem.gap);
    return d;
  }

  const double estar = material.g / (1.0 - material.nu);
  if (!(estar > 0.0) || !std::isfinite(estar)) {
    throw ProblemError("Hertzian potential contact needs E* = G/(1-nu) > 0 (G=" +
                       std::to_string(material.g) + ", nu=" + std::to_string(material.nu) + ")");
  }
  const bool force = problem.normal.kind == model::NormalLoadKind::Force;
  const HertzLoad load = force ? HertzLoad::Force : HertzLoad::Approach;
  const double value = force ? problem.normal.force_N : problem.normal.approach_mm;
  d.hertz = hertz_for_potential(pot, load, value, estar);
  d.grid = hertzian_grid(pot, d.hertz);

  // h = A1 x² + B1 y² at the element centres (2-D: B1 = 0).
  d.h.resize(d.grid.size());
  for (int iy = 0; iy < d.grid.my; ++iy) {
    const double y = d.grid.y_centre(iy);
    for (int ix = 0; ix < d.grid.mx; ++ix) {
      const double x = d.grid.x_centre(ix);
      d.h[d.grid.index(ix, iy)] = d.hertz.a1 * x * x + d.hertz.b1 * y * y;
    }
  }
  return d;
}

}  // namespace

HertzReport hertz_for_potential(const PotentialContact& pot, HertzLoad load, double value,
                                double estar) {
  const auto& v = pot.values;
  const bool two_d = pot.ipotcn == -4 || pot.ipotcn == -5;
  if (two_d && load != HertzLoad::Force) {
    throw ProblemError("2-D Hertzian potential contact (IPOTCN=" + std::to_string(pot.ipotcn) +
                       ") needs a prescribed normal force (N=1): 2-D Hertz theory defines no "
                       "approach");
  }
  HertzReport h;
  double scale = v[2];
  switch (pot.ipotcn) {
    case -1:
      h = hertz_from_curvatures(v[0], v[1], load, value, estar);
      break;
    case -2:
      h = hertz_from_a1_and_ratio(v[0], v[1], load, value, estar);
      break;
    case -3:
      h = hertz_from_semiaxes(v[0], v[1], load, value, estar);
      break;
    case -4:
      h = hertz_2d_from_curvature(v[0], v[1], value, estar);
      break;
    case -5:
      h = hertz_2d_from_half_length(v[0], v[1], value, estar);
      break;
    case -6: {  // SDEC: AA BNEG BPOS SCALE; the Hertz ellipse uses b = (bneg + bpos)/2
      if (!(v[1] > 0.0) || !(v[2] > 0.0)) {
        throw ProblemError("IPOTCN=-6 (SDEC) needs BNEG, BPOS > 0");
      }
      h = hertz_from_semiaxes(v[0], 0.5 * (v[1] + v[2]), load, value, estar);
      scale = v[3];
      break;
    }
    default:
      throw ProblemError("IPOTCN=" + std::to_string(pot.ipotcn) +
                         " is not a Hertzian option (-1..-6)");
  }
  if (!(scale > 0.0) || !std::isfinite(scale)) {
    throw ProblemError("Hertzian potential contact needs SCALE > 0, got " + std::to_string(scale));
  }
  h.scale = scale;
  return h;
}

Discretisation build_discretisation(const model::PatchProblem& problem,
                                    const CombinedMaterial& material) {
  try {
    return build(problem, material);
  } catch (const ProblemError& e) {
    // The front end adds where the case came from (it knows the file and the case number).
    throw GeometryError(e.what());
  }
}

}  // namespace rollcontact::geometry
