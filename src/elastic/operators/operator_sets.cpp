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
void assemble_plain(TangentialOperatorSet& s, bool coupled, FftChoice fft, KernelLibrary* lib) {
  const Grid& grid = s.grid;
  const CombinedMaterial& material = s.material;
  s.c_xx = tabulate(lib, Component::xx, grid, material);
  s.c_xy = tabulate(lib, Component::xy, grid, material);
  s.c_yy = tabulate(lib, Component::yy, grid, material);
  s.c_nn = tabulate(lib, Component::nn, grid, material);
  if (coupled) {
    s.c_xn = tabulate(lib, Component::xn, grid, material);
    s.c_yn = tabulate(lib, Component::yn, grid, material);
    s.nt_x = tabulate(lib, Component::nx, grid, material);
    s.nt_y = tabulate(lib, Component::ny, grid, material);
    s.nt = std::make_unique<BlockConvolution>(1, 2, std::vector<const Kernel*>{&s.nt_x, &s.nt_y},
                                              fft.backend, fft.planning);
  }
  const Kernel* xn = coupled ? &s.c_xn : nullptr;
  const Kernel* yn = coupled ? &s.c_yn : nullptr;
  const Kernel* nx = coupled ? &s.nt_x : nullptr;
  const Kernel* ny = coupled ? &s.nt_y : nullptr;
  s.full = std::make_unique<BlockConvolution>(
      3, 3, std::vector<const Kernel*>{&s.c_xx, &s.c_xy, xn, &s.c_xy, &s.c_yy, yn, nx, ny, &s.c_nn},
      fft.backend, fft.planning);
}

/// Steady rolling: A = C − C′ with C′ the coefficients seen from one step downstream.
void assemble_steady_part(TangentialOperatorSet& s, bool coupled, KernelLibrary* lib) {
  const double sx = s.shift_x, sy = s.shift_y;
  s.xx = difference(s.c_xx, tabulate(lib, Component::xx, s.grid, s.material, sx, sy));
  s.xy = difference(s.c_xy, tabulate(lib, Component::xy, s.grid, s.material, sx, sy));
  s.yy = difference(s.c_yy, tabulate(lib, Component::yy, s.grid, s.material, sx, sy));
  if (coupled) {
    s.tn_x = difference(s.c_xn, tabulate(lib, Component::xn, s.grid, s.material, sx, sy));
    s.tn_y = difference(s.c_yn, tabulate(lib, Component::yn, s.grid, s.material, sx, sy));
  }
}

/// Shift and transient rolling: A = C, and the previous-time displacement of the particles now
/// at the element centres (C′ when rolling, C for a shift).
void assemble_transient_part(TangentialOperatorSet& s, bool coupled, FftChoice fft,
                             KernelLibrary* lib) {
  const bool rolling = s.kind == model::TangentialKind::TransientRolling;
  const double sx = s.shift_x, sy = s.shift_y;
  s.xx = s.c_xx;
  s.xy = s.c_xy;
  s.yy = s.c_yy;
  if (coupled) {
    s.tn_x = s.c_xn;
    s.tn_y = s.c_yn;
  }
  s.prev_xx = rolling ? tabulate(lib, Component::xx, s.grid, s.material, sx, sy) : s.xx;
  s.prev_xy = rolling ? tabulate(lib, Component::xy, s.grid, s.material, sx, sy) : s.xy;
  s.prev_yy = rolling ? tabulate(lib, Component::yy, s.grid, s.material, sx, sy) : s.yy;
  if (coupled) {
    s.prev_xn = rolling ? tabulate(lib, Component::xn, s.grid, s.material, sx, sy) : s.c_xn;
    s.prev_yn = rolling ? tabulate(lib, Component::yn, s.grid, s.material, sx, sy) : s.c_yn;
  }
  s.prev = std::make_unique<BlockConvolution>(
      2, 3,
      std::vector<const Kernel*>{&s.prev_xx, &s.prev_xy, coupled ? &s.prev_xn : nullptr, &s.prev_xy,
                                 &s.prev_yy, coupled ? &s.prev_yn : nullptr},
      fft.backend, fft.planning);
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
  const bool coupled = is_coupled(material);
  assemble_plain(set, coupled, fft, lib);
  if (set.steady())
    assemble_steady_part(set, coupled, lib);
  else
    assemble_transient_part(set, coupled, fft, lib);
  set.a = std::make_unique<BlockConvolution>(
      2, 2, std::vector<const Kernel*>{&set.xx, &set.xy, &set.xy, &set.yy}, fft.backend,
      fft.planning);
  if (coupled)
    set.tn = std::make_unique<BlockConvolution>(
        2, 1, std::vector<const Kernel*>{&set.tn_x, &set.tn_y}, fft.backend, fft.planning);
  set.interaction = std::move(interaction);
  for (BlockConvolution* product :
       {set.a.get(), set.prev.get(), set.tn.get(), set.nt.get(), set.full.get()})
    if (product != nullptr) product->set_interaction(set.interaction);
}

void assemble_steady_rolling(SteadyRollingOperatorSet& set, const Grid& grid,
                             const CombinedMaterial& material, double shift_x_mm, double shift_y_mm,
                             FftChoice fft, KernelLibrary* lib) {
  set.grid = grid;
  set.material = material;
  set.shift_x = shift_x_mm;
  set.shift_y = shift_y_mm;
  set.c_xx = tabulate(lib, Component::xx, grid, material);
  set.c_xy = tabulate(lib, Component::xy, grid, material);
  set.c_yy = tabulate(lib, Component::yy, grid, material);
  set.xx =
      difference(set.c_xx, tabulate(lib, Component::xx, grid, material, shift_x_mm, shift_y_mm));
  set.xy =
      difference(set.c_xy, tabulate(lib, Component::xy, grid, material, shift_x_mm, shift_y_mm));
  set.yy =
      difference(set.c_yy, tabulate(lib, Component::yy, grid, material, shift_x_mm, shift_y_mm));
  set.a = std::make_unique<BlockConvolution>(
      2, 2, std::vector<const Kernel*>{&set.xx, &set.xy, &set.xy, &set.yy}, fft.backend,
      fft.planning);
}

}  // namespace rollcontact::elastic::operators
