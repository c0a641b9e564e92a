#pragma once
// Subsurface displacements and stresses at the element centres of the grid, by FFT
// convolutions (spec/physics.md §16): at one depth every corner sum of the direct method,
// Σ_nodes w·F_k(x − ξ, y − η, z), is a discrete convolution of the nodal loads with the corner
// function F_k sampled at the centre-to-node offsets, and the response is linear in the sums.
// So per depth: the 21 corner functions on the offset lattice, their transforms, and 9 inverse
// transforms (3 displacements, 6 stresses), instead of points × loaded nodes corner evaluations
// — the direct method's cost grows with the square of the grid, this one with N log N.

#include <array>
#include <complex>
#include <memory>
#include <vector>

#include "core/fft_backend.hpp"
#include "post/half_space_response.hpp"
#include "rollcontact/grid.hpp"

namespace rollcontact::post {

/// The nine fields of the response, in the order of `LatticeFields`.
enum LatticeField : std::size_t { kUx, kUy, kUz, kSxx, kSxy, kSxz, kSyy, kSyz, kSzz, kFieldCount };

/// Per field, one value per element centre (ix + mx·iy).
using LatticeFields = std::array<std::vector<double>, kFieldCount>;

/// The nine fields of one response, in LatticeField order.
std::array<double, kFieldCount> fields_of(const HalfSpaceResponse& h);

class SubsurfaceLattice {
 public:
  /// px, py, pn: tractions on body 1 per element [N/mm²] (element order ix + mx·iy).
  SubsurfaceLattice(const Grid& grid, const std::vector<double>& px, const std::vector<double>& py,
                    const std::vector<double>& pn);
  ~SubsurfaceLattice();

  /// The response of the half-space z ≥ 0 (shear modulus g, Poisson ratio nu) at depth
  /// `depth` > 0 under the tractions with their tangential parts multiplied by
  /// `tangential_sign` (−1: body 2, whose frame the caller mirrors), at every element centre.
  void evaluate(double depth, double g, double nu, double tangential_sign, LatticeFields& out);

 private:
  Grid grid_;
  int n_fast_ = 0, n_slow_ = 0;
  std::unique_ptr<core::FftEngine> fft_;
  std::array<std::vector<std::complex<double>>, 3> load_spectra_;  ///< x, y, n nodal weights
};

}  // namespace rollcontact::post
