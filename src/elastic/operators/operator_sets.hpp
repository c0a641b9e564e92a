#pragma once
// The influence operators of one grid and material (and rolling step), assembled once and then
// applied by FFT many times. The solvers' preconditioners are added by the contact layer, which
// caches these sets (contact/operator_cache.hpp).
//
// A set is assembled in place (assemble_*): the FFT products are built from kernels that live
// in the same object, so a set is created where it stays, never copied or moved.

#include <memory>

#include "elastic/block_convolution.hpp"
#include "elastic/convolution.hpp"
#include "elastic/influence.hpp"
#include "elastic/interaction.hpp"
#include "elastic/kernel_library.hpp"
#include "rollcontact/fft_options.hpp"
#include "rollcontact/model/loading.hpp"

namespace rollcontact::elastic::operators {

struct FftChoice {
  FftBackendKind backend = FftBackendKind::Default;
  FftPlanning planning = FftPlanning::Estimate;
};

/// C_nn/G of one grid and material and its FFT product (the normal problem).
struct NormalOperatorSet {
  Grid grid;
  CombinedMaterial material;
  InteractionPtr interaction;  ///< attenuation between parts of the grid, or none
  Kernel kernel;
  std::unique_ptr<FftConvolution> product;
};
/// `lib` (optional) supplies the kernels (cut from kept larger ones, the same values).
void assemble_normal(NormalOperatorSet& set, const Grid& grid, const CombinedMaterial& material,
                     FftChoice fft, InteractionPtr interaction = nullptr,
                     KernelLibrary* lib = nullptr);

/// Tangential operators of one grid, material and kind of loading, with the rolling step
/// (shift_x, shift_y) [mm] (no shift for shifts, model::TangentialKind::Shift):
///  a     — A = C_tt/G (shift, transient rolling) or (C − C′)_tt/G (steady rolling), 2×2;
///  prev  — (u′_x, u′_y) from (p_x, p_y, p_n) of the previous time, with C′ (transient rolling)
///          or C (shift); not for steady rolling;
///  tn    — tangential displacement per step due to p_n (K ≠ 0), with C or C − C′;
///  nt    — normal displacement due to (p_x, p_y) with C (K ≠ 0);
///  full  — plain C (3×3 with the couplings when K ≠ 0) for displacement fields and energy,
///          made on first use (full_product()): the sets of a contact box and of grids whose
///          solves only inform an iteration never need it.
struct TangentialOperatorSet {
  TangentialOperatorSet() = default;
  // `spectra` refers to the kernels by address: the set stays where it was assembled.
  TangentialOperatorSet(const TangentialOperatorSet&) = delete;
  TangentialOperatorSet& operator=(const TangentialOperatorSet&) = delete;

  Grid grid;
  CombinedMaterial material;
  InteractionPtr interaction;  ///< attenuation between parts of the grid (all products), or none
  model::TangentialKind kind = model::TangentialKind::Shift;
  double shift_x = 0.0, shift_y = 0.0;  ///< [mm]
  Kernel xx, xy, yy;
  std::unique_ptr<BlockConvolution> a;
  Kernel prev_xx, prev_xy, prev_yy, prev_xn, prev_yn;
  std::unique_ptr<BlockConvolution> prev;
  Kernel tn_x, tn_y, nt_x, nt_y;
  std::unique_ptr<BlockConvolution> tn, nt;
  Kernel c_xx, c_xy, c_yy, c_xn, c_yn, c_nn;
  /// C_yx of turned coefficients (C=4, turned()), which differs from C_xy; empty otherwise (the
  /// products use C_xy for it, the half-space's symmetry).
  Kernel c_yx, yx, prev_yx;
  FftChoice fft;          ///< of the products, for full_product()
  SpectrumCache spectra;  ///< the kernels' spectra the products share

  bool steady() const noexcept { return kind == model::TangentialKind::SteadyRolling; }
  bool coupled() const noexcept { return is_coupled(material); }
  /// The coefficients are turned by the surface's inclination (C=4): C_yx has its own kernels.
  bool turned() const noexcept { return material.inclination_corrected(); }
  /// The yx kernel of A (xy where the coefficients are not turned).
  const Kernel& a_yx() const noexcept { return turned() ? yx : xy; }
  /// A = Aᵀ: shifts and transient rolling, unless turned by a variant other than the symmetric
  /// one (4).
  bool symmetric() const noexcept {
    return !steady() && (!turned() || material.inclination_variant == 4);
  }
  /// The plain 3×3 C, with the set's interaction.
  BlockConvolution& full_product();
  /// The plain 2×2 C_tt, with the set's interaction: `a` itself unless steady rolling, else
  /// made on first use. Without couplings (K = 0) the tangential displacements are this product
  /// alone, and the normal ones are the normal solve's.
  BlockConvolution& tangential_product();

 private:
  std::unique_ptr<BlockConvolution> full_, plain_tt_;
};
/// What a tangential set depends on besides grid and material: the kind of loading (None is
/// treated as steady rolling, as the solver never asks for it) and the rolling step [mm], zero
/// for shifts (their previous displacement is taken with C itself).
struct TangentialLoadingKey {
  model::TangentialKind kind = model::TangentialKind::SteadyRolling;
  double shift_x = 0.0, shift_y = 0.0;
};
TangentialLoadingKey tangential_loading_key(model::TangentialKind kind, double shift_x_mm,
                                            double shift_y_mm);

/// Assembles the set for tangential_loading_key(kind, shift_x_mm, shift_y_mm).
void assemble_tangential(TangentialOperatorSet& set, const Grid& grid,
                         const CombinedMaterial& material, model::TangentialKind kind,
                         double shift_x_mm, double shift_y_mm, FftChoice fft,
                         InteractionPtr interaction = nullptr, KernelLibrary* lib = nullptr);

/// The steady-rolling operator A = (C − C′)_tt alone, with the plain C_tt its preconditioner is
/// built from: the coarse levels of the nested-iteration start.
struct SteadyRollingOperatorSet {
  Grid grid;
  CombinedMaterial material;
  double shift_x = 0.0, shift_y = 0.0;  ///< [mm]
  Kernel xx, xy, yy;                    ///< C − C′
  Kernel c_xx, c_xy, c_yy;              ///< C
  std::unique_ptr<BlockConvolution> a;
};
void assemble_steady_rolling(SteadyRollingOperatorSet& set, const Grid& grid,
                             const CombinedMaterial& material, double shift_x_mm, double shift_y_mm,
                             FftChoice fft, KernelLibrary* lib = nullptr);

}  // namespace rollcontact::elastic::operators
