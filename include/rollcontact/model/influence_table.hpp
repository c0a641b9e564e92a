#pragma once
// Influence coefficients tabulated outside the solver (CONTACT C=9, spec/inp-format.md §8.5):
// C_ij on the offsets of a grid, combined for both bodies, in the normalisation of
// spec/physics.md §3.2, u_i(x_I) = (1/G) Σ_J C_ij(x_I − x_J) p_j(x_J).

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace rollcontact::model {

/// One set of coefficients for every grid row (CONTACT's NMATRIX = 1): block-Toeplitz in x and y.
struct InfluenceTable {
  /// Displacement component i due to a load in direction j (z = n), in the order of the file's
  /// columns.
  enum Component : std::size_t { zz, zx, zy, xz, xx, xy, yz, yx, yy, count };

  int mx = 0, my = 0;               ///< offsets |IXOFS| ≤ mx − 1, |IYOFS| ≤ my − 1
  double dx_mm = 0.0, dy_mm = 0.0;  ///< element size the coefficients were computed for [mm]
  std::string source;               ///< where the table came from (file name), for messages
  /// True when a coupling coefficient (zx, zy, xz, yz) is non-zero: the normal and tangential
  /// problems are then solved together. Set by whoever fills `values`.
  bool coupled = false;
  /// Per component (2mx − 1)(2my − 1) values, IXOFS fastest, both signs of the offsets
  /// present; C_ij without the factor 1/G [mm] (displacement·G per unit traction).
  std::array<std::vector<double>, count> values;

  [[nodiscard]] std::size_t index(int ixofs, int iyofs) const noexcept {
    return static_cast<std::size_t>(ixofs + mx - 1) +
           static_cast<std::size_t>(2 * mx - 1) * static_cast<std::size_t>(iyofs + my - 1);
  }
  /// The same coefficients for the same element size (wherever they were read from): operators
  /// built from one serve the other.
  [[nodiscard]] bool same_coefficients(const InfluenceTable& o) const noexcept {
    return mx == o.mx && my == o.my && dx_mm == o.dx_mm && dy_mm == o.dy_mm &&
           coupled == o.coupled && values == o.values;
  }
  /// C_ij at an offset [elements]; 0 beyond the table (a smaller file grid is zero-padded).
  [[nodiscard]] double at(Component c, int ixofs, int iyofs) const noexcept {
    if (ixofs <= -mx || ixofs >= mx || iyofs <= -my || iyofs >= my) return 0.0;
    return values[c][index(ixofs, iyofs)];
  }
};

}  // namespace rollcontact::model
