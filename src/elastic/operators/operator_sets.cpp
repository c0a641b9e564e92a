#include "elastic/operators/operator_sets.hpp"

#include <vector>

#include "elastic/kernel_library.hpp"
#include "elastic/operators/rolling_difference.hpp"

namespace rollcontact::elastic::operators {

namespace {

/// From the library when there is one (the same values, cut from a kept larger kernel).
Kernel tabulate(KernelLibrary* library, Component c, const Grid& grid,
                const CombinedMaterial& material, double shift_x = 0.0, double shift_y = 0.0) {
  return library != nullptr ? library->kernel(c, grid, material, shift_x, shift_y)
                            : make_kernel(c, grid, material, shift_x, shift_y);
}

/// Several components at once: those not kept are tabulated on one corner lattice.
std::vector<Kernel> tabulate(KernelLibrary* library, const std::vector<Component>& cs,
                             const Grid& grid, const CombinedMaterial& material,
                             double shift_x = 0.0, double shift_y = 0.0) {
  return library != nullptr ? library->kernels(cs, grid, material, shift_x, shift_y)
                            : make_kernels(cs, grid, material, shift_x, shift_y);
}

/// xx, xy, yy, when coupled xn, yn, and when turned (C=4) yx, in that order, at the shift.
std::vector<Kernel> tangential_kernels(KernelLibrary* library, const Grid& grid,
                                       const CombinedMaterial& material, bool coupled,
                                       double shift_x, double shift_y) {
  std::vector<Component> cs{Component::xx, Component::xy, Component::yy};
  if (coupled) cs.insert(cs.end(), {Component::xn, Component::yn});
  if (material.inclination_corrected()) cs.push_back(Component::yx);
  return tabulate(library, cs, grid, material, shift_x, shift_y);
}

}  // namespace

void assemble_normal(NormalOperatorSet& set, const Grid& grid, const CombinedMaterial& material,
                     FftChoice fft, InteractionPtr interaction, KernelLibrary* lib) {
  set.grid = grid;
  set.material = material;
  set.interaction = std::move(interaction);
  set.kernel = tabulate(lib, Component::nn, grid, material);
  set.product = std::make_unique<FftConvolution>(set.kernel, fft.backend, fft.planning);
  set.product->set_interaction(set.interaction);
}

namespace {

/// The plain 3×3 C (zero couplings when K = 0) and the normal displacement due to p_t.
void assemble_plain(TangentialOperatorSet& s, bool coupled, FftChoice fft, KernelLibrary* lib,
                    SpectrumCache& spectra) {
  const Grid& grid = s.grid;
  const CombinedMaterial& material = s.material;
  std::vector<Component> cs{Component::xx, Component::xy, Component::yy, Component::nn};
  if (coupled) cs.insert(cs.end(), {Component::xn, Component::yn, Component::nx, Component::ny});
  if (s.turned()) cs.push_back(Component::yx);
  std::vector<Kernel> k = tabulate(lib, cs, grid, material);
  s.c_xx = std::move(k[0]);
  s.c_xy = std::move(k[1]);
  s.c_yy = std::move(k[2]);
  s.c_nn = std::move(k[3]);
  if (s.turned()) s.c_yx = std::move(k.back());
  if (coupled) {
    s.c_xn = std::move(k[4]);
    s.c_yn = std::move(k[5]);
    s.nt_x = std::move(k[6]);
    s.nt_y = std::move(k[7]);
    s.nt = std::make_unique<BlockConvolution>(1, 2, std::vector<const Kernel*>{&s.nt_x, &s.nt_y},
                                              fft.backend, fft.planning, &spectra);
  }
}

}  // namespace

BlockConvolution& TangentialOperatorSet::full_product() {
  if (!full_) {
    const bool k = coupled();
    const Kernel* xn = k ? &c_xn : nullptr;
    const Kernel* yn = k ? &c_yn : nullptr;
    const Kernel* nx = k ? &nt_x : nullptr;
    const Kernel* ny = k ? &nt_y : nullptr;
    const Kernel* c_yx_or_xy = turned() ? &c_yx : &c_xy;
    full_ = std::make_unique<BlockConvolution>(
        3, 3, std::vector<const Kernel*>{&c_xx, &c_xy, xn, c_yx_or_xy, &c_yy, yn, nx, ny, &c_nn},
        fft.backend, fft.planning, &spectra);
    full_->set_interaction(interaction);
  }
  return *full_;
}

BlockConvolution& TangentialOperatorSet::tangential_product() {
  if (!steady()) return *a;  // A = C_tt
  if (!plain_tt_) {
    plain_tt_ = std::make_unique<BlockConvolution>(
        2, 2, std::vector<const Kernel*>{&c_xx, &c_xy, turned() ? &c_yx : &c_xy, &c_yy},
        fft.backend, fft.planning, &spectra);
    plain_tt_->set_interaction(interaction);
  }
  return *plain_tt_;
}

namespace {

/// Steady rolling: A = C − C′ with C′ the coefficients seen from one step downstream.
void assemble_steady_part(TangentialOperatorSet& s, bool coupled, KernelLibrary* lib) {
  const std::vector<Kernel> k =
      tangential_kernels(lib, s.grid, s.material, coupled, s.shift_x, s.shift_y);
  s.xx = difference(s.c_xx, k[0]);
  s.xy = difference(s.c_xy, k[1]);
  s.yy = difference(s.c_yy, k[2]);
  if (coupled) {
    s.tn_x = difference(s.c_xn, k[3]);
    s.tn_y = difference(s.c_yn, k[4]);
  }
  if (s.turned()) s.yx = difference(s.c_yx, k.back());
}

/// Shift and transient rolling: A = C, and the previous-time displacement of the particles now
/// at the element centres (C′ when rolling, C for a shift).
void assemble_transient_part(TangentialOperatorSet& s, bool coupled, FftChoice fft,
                             KernelLibrary* lib, SpectrumCache& spectra) {
  const bool rolling = s.kind == model::TangentialKind::TransientRolling;
  const double sx = s.shift_x, sy = s.shift_y;
  s.xx = s.c_xx;
  s.xy = s.c_xy;
  s.yy = s.c_yy;
  if (coupled) {
    s.tn_x = s.c_xn;
    s.tn_y = s.c_yn;
  }
  if (s.turned()) s.yx = s.c_yx;
  std::vector<Kernel> k;
  if (rolling) k = tangential_kernels(lib, s.grid, s.material, coupled, sx, sy);
  if (s.turned()) s.prev_yx = rolling ? std::move(k.back()) : s.yx;
  s.prev_xx = rolling ? std::move(k[0]) : s.xx;
  s.prev_xy = rolling ? std::move(k[1]) : s.xy;
  s.prev_yy = rolling ? std::move(k[2]) : s.yy;
  if (coupled) {
    s.prev_xn = rolling ? std::move(k[3]) : s.c_xn;
    s.prev_yn = rolling ? std::move(k[4]) : s.c_yn;
  }
  const Kernel* prev_yx = s.turned() ? &s.prev_yx : &s.prev_xy;
  s.prev = std::make_unique<BlockConvolution>(
      2, 3,
      std::vector<const Kernel*>{&s.prev_xx, &s.prev_xy, coupled ? &s.prev_xn : nullptr, prev_yx,
                                 &s.prev_yy, coupled ? &s.prev_yn : nullptr},
      fft.backend, fft.planning, &spectra);
}

}  // namespace

TangentialLoadingKey tangential_loading_key(model::TangentialKind kind, double shift_x_mm,
                                            double shift_y_mm) {
  // A shift uses C for the previous displacement (material-fixed grid): no rolling step.
  if (kind == model::TangentialKind::Shift) return {kind, 0.0, 0.0};
  if (kind == model::TangentialKind::None) kind = model::TangentialKind::SteadyRolling;
  return {kind, shift_x_mm, shift_y_mm};
}

void assemble_tangential(TangentialOperatorSet& set, const Grid& grid,
                         const CombinedMaterial& material, model::TangentialKind kind,
                         double shift_x_mm, double shift_y_mm, FftChoice fft,
                         InteractionPtr interaction, KernelLibrary* lib) {
  const TangentialLoadingKey key = tangential_loading_key(kind, shift_x_mm, shift_y_mm);
  set.grid = grid;
  set.material = material;
  set.kind = key.kind;
  set.shift_x = key.shift_x;
  set.shift_y = key.shift_y;
  set.fft = fft;
  const bool coupled = is_coupled(material);
  // The products share their kernels' spectra: for shifts and transient rolling A is C, and
  // the previous displacement of a shift is C again.
  SpectrumCache& spectra = set.spectra;
  assemble_plain(set, coupled, fft, lib, spectra);
  if (set.steady())
    assemble_steady_part(set, coupled, lib);
  else
    assemble_transient_part(set, coupled, fft, lib, spectra);
  set.a = std::make_unique<BlockConvolution>(
      2, 2, std::vector<const Kernel*>{&set.xx, &set.xy, &set.a_yx(), &set.yy}, fft.backend,
      fft.planning, &spectra);
  if (coupled)
    set.tn =
        std::make_unique<BlockConvolution>(2, 1, std::vector<const Kernel*>{&set.tn_x, &set.tn_y},
                                           fft.backend, fft.planning, &spectra);
  set.interaction = std::move(interaction);
  for (BlockConvolution* product : {set.a.get(), set.prev.get(), set.tn.get(), set.nt.get()})
    if (product != nullptr) product->set_interaction(set.interaction);
}

void assemble_steady_rolling(SteadyRollingOperatorSet& set, const Grid& grid,
                             const CombinedMaterial& material, double shift_x_mm, double shift_y_mm,
                             FftChoice fft, KernelLibrary* lib) {
  set.grid = grid;
  set.material = material;
  set.shift_x = shift_x_mm;
  set.shift_y = shift_y_mm;
  std::vector<Kernel> c = tangential_kernels(lib, grid, material, false, 0.0, 0.0);
  set.c_xx = std::move(c[0]);
  set.c_xy = std::move(c[1]);
  set.c_yy = std::move(c[2]);
  const std::vector<Kernel> shifted =
      tangential_kernels(lib, grid, material, false, shift_x_mm, shift_y_mm);
  set.xx = difference(set.c_xx, shifted[0]);
  set.xy = difference(set.c_xy, shifted[1]);
  set.yy = difference(set.c_yy, shifted[2]);
  set.a = std::make_unique<BlockConvolution>(
      2, 2, std::vector<const Kernel*>{&set.xx, &set.xy, &set.xy, &set.yy}, fft.backend,
      fft.planning);
}

}  // namespace rollcontact::elastic::operators
