#include "elastic/kernel_library.hpp"

#include <algorithm>
#include <cmath>

namespace rollcontact::elastic {

namespace {

std::size_t bytes_for(int mx, int my) {
  return sizeof(double) * static_cast<std::size_t>(2 * mx - 1) *
         static_cast<std::size_t>(2 * my - 1);
}
std::size_t bytes_of(const Kernel& k) {
  return bytes_for(k.mx(), k.my());
}

}  // namespace

Kernel cut_kernel(const Kernel& big, int mx, int my) {
  Kernel k(mx, my);
  for (int diy = -(my - 1); diy <= my - 1; ++diy)
    for (int dix = -(mx - 1); dix <= mx - 1; ++dix) k.at(dix, diy) = big.at(dix, diy);
  return k;
}

Kernel KernelLibrary::kernel(Component c, const Grid& grid, const CombinedMaterial& m,
                             double shift_x, double shift_y) {
  // The quadrature of a viscous part follows the grid's length (its kinks), so a kernel cut from
  // a larger grid's would differ in the last digits: viscoelastic kernels are made directly.
  if (m.viscoelastic()) {
    ++computed_;
    return make_kernel(c, grid, m, shift_x, shift_y);
  }
  bool outgrown = false;
  int kept_mx = 0, kept_my = 0;  // of the entry a grid outgrew
  for (auto it = entries_.begin(); it != entries_.end(); ++it) {
    const Entry& e = *it;
    if (e.c != c || e.dx != grid.dx || e.dy != grid.dy || e.g != m.g || e.nu != m.nu ||
        e.k != m.k || e.layer != m.layer_compliance ||
        e.normal_layer != m.normal_layer_compliance || e.shift_x != shift_x ||
        e.shift_y != shift_y || e.viscous != m.viscous)
      continue;
    if (e.kernel.mx() >= grid.mx && e.kernel.my() >= grid.my) {
      entries_.splice(entries_.begin(), entries_, it);
      return cut_kernel(entries_.front().kernel, grid.mx, grid.my);
    }
    kept_mx = e.kernel.mx();
    kept_my = e.kernel.my();
    kept_bytes_ -= bytes_of(it->kernel);
    entries_.erase(it);  // too small: replaced by a larger one below
    outgrown = true;
    break;
  }
  // A grid that outgrew its kernel is a growing patch: a quarter more than asked in each
  // direction, so that it does not tabulate again at every step. A first request gets its own
  // size: most grids never grow (a module-3 sequence), and the closed forms are the set-up.
  Grid big = grid;
  if (outgrown) {
    big.mx = std::max(grid.mx + (grid.mx + 3) / 4, kept_mx);
    big.my = std::max(grid.my + (grid.my + 3) / 4, kept_my);
  }
  ++computed_;
  if (4 * bytes_for(big.mx, big.my) > budget_bytes_)
    return make_kernel(c, grid, m, shift_x, shift_y);
  entries_.push_front({c, grid.dx, grid.dy, m.g, m.nu, m.k, m.layer_compliance,
                       m.normal_layer_compliance, shift_x, shift_y, m.viscous,
                       make_kernel(c, big, m, shift_x, shift_y)});
  kept_bytes_ += bytes_of(entries_.front().kernel);
  while (kept_bytes_ > budget_bytes_) {
    kept_bytes_ -= bytes_of(entries_.back().kernel);
    entries_.pop_back();
  }
  return cut_kernel(entries_.front().kernel, grid.mx, grid.my);
}

}  // namespace rollcontact::elastic
