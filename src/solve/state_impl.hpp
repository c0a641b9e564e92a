#pragma once
// What a State holds: cached operators per grid and material, and the previous solution.

#include <memory>
#include <optional>

#include "elastic/convolution.hpp"
#include "elastic/influence.hpp"
#include "normal/preconditioner.hpp"
#include "rollcontact/solve.hpp"

namespace rollcontact {

/// The normal influence operator of one grid/material, with its FFT plans and preconditioner.
struct NormalOperators {
  Grid grid;
  CombinedMaterial material;
  elastic::Kernel kernel;
  std::unique_ptr<elastic::FftConvolution> product;
  std::unique_ptr<normal::CirculantPreconditioner> preconditioner;

  bool matches(const Grid& g, const CombinedMaterial& m) const noexcept {
    return g.mx == grid.mx && g.my == grid.my && g.dx == grid.dx && g.dy == grid.dy &&
           m.g == material.g && m.nu == material.nu;
  }
};

struct State::Impl {
  SolveOptions options;
  std::unique_ptr<NormalOperators> normal;  ///< rebuilt when grid or material change
  std::optional<Solution> previous;         ///< last solved case (P=0 continuation, warm starts)

  /// The normal operators for this grid and material, built on first use and kept.
  NormalOperators& normal_operators(const Grid& grid, const CombinedMaterial& material);
};

}  // namespace rollcontact
