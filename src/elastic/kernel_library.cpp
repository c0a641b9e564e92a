#include "elastic/kernel_library.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include "elastic/inclination_correction.hpp"

namespace rollcontact::elastic {

namespace {

std::size_t bytes_for(int mx, int my) {
  return sizeof(double) * static_cast<std::size_t>(2 * mx - 1) *
         static_cast<std::size_t>(2 * my - 1);
}
std::size_t bytes_of(const Kernel& k) {
  return bytes_for(k.mx(), k.my());
}

/// A rolling shift of whole elements, (nx·dx, ny·dy) exactly, of a kernel whose closed forms
/// see the shift only through the corner abscissae: its kernel is the unshifted one read nx, ny
/// offsets on. The abscissae agree bit for bit: (i − mx + ½)·dx + nx·dx and (i + nx − mx + ½)·dx
/// are both exact in long double while the odd numerator 2(i − mx) + 1 + 2nx has at most 11 bits
/// (dx's 53 bits and those fit the 64-bit mantissa), hence the bound on the grid.
struct WholeSteps {
  int nx = 0, ny = 0;
};
std::optional<WholeSteps> whole_steps(const Grid& grid, const CombinedMaterial& m, double shift_x,
                                      double shift_y) {
  if (shift_x == 0.0 && shift_y == 0.0) return std::nullopt;
  if (m.elements != model::TractionElements::piecewise_constant) return std::nullopt;
  const auto steps = [](double shift, double d) -> std::optional<int> {
    const double n = std::round(shift / d);
    if (!(std::abs(n) <= 8.0) || n * d != shift) return std::nullopt;
    return static_cast<int>(n);
  };
  const std::optional<int> nx = steps(shift_x, grid.dx), ny = steps(shift_y, grid.dy);
  if (!nx || !ny) return std::nullopt;
  constexpr int kExactExtent = 1000;  // 2·1008 + 1 < 2^11
  if (grid.mx + std::abs(*nx) > kExactExtent || grid.my + std::abs(*ny) > kExactExtent)
    return std::nullopt;
  return WholeSteps{*nx, *ny};
}

}  // namespace

Kernel cut_kernel(const Kernel& big, int mx, int my, int ox, int oy) {
  Kernel k(mx, my);
  for (int diy = -(my - 1); diy <= my - 1; ++diy)
    for (int dix = -(mx - 1); dix <= mx - 1; ++dix) k.at(dix, diy) = big.at(dix + ox, diy + oy);
  return k;
}

Kernel KernelLibrary::kernel(Component c, const Grid& grid, const CombinedMaterial& m,
                             double shift_x, double shift_y) {
  return std::move(kernels({c}, grid, m, shift_x, shift_y).front());
}

const Kernel* KernelLibrary::find_covering(Component c, const Grid& grid,
                                           const CombinedMaterial& m) {
  // Never kept (kernels()): viscoelastic kernels, a table's, and turned ones (C=4), which are
  // made from the kept plain kernels.
  if (m.viscoelastic() || m.table || m.inclination_corrected()) return nullptr;
  for (auto it = entries_.begin(); it != entries_.end(); ++it)
    if (matches(*it, c, grid, m, 0.0, 0.0) && it->kernel.mx() >= grid.mx &&
        it->kernel.my() >= grid.my) {
      entries_.splice(entries_.begin(), entries_, it);
      return &entries_.front().kernel;
    }
  return nullptr;
}

const Kernel& KernelLibrary::covering(Component c, const Grid& grid, const CombinedMaterial& m) {
  if (const Kernel* kept = find_covering(c, grid, m)) return *kept;
  scratch_ = kernel(c, grid, m);  // the grid's own (tabulated, and kept for the next call)
  return scratch_;
}

bool KernelLibrary::matches(const Entry& e, Component c, const Grid& grid,
                            const CombinedMaterial& m, double shift_x, double shift_y) {
  return e.c == c && e.dx == grid.dx && e.dy == grid.dy && e.g == m.g && e.nu == m.nu &&
         e.k == m.k && e.layer == m.layer_compliance &&
         e.normal_layer == m.normal_layer_compliance && e.shift_x == shift_x &&
         e.shift_y == shift_y && e.viscous == m.viscous && e.elements == m.elements;
}

std::optional<Kernel> KernelLibrary::cut_kept(Component c, const Grid& grid,
                                              const CombinedMaterial& m, double shift_x,
                                              double shift_y, Grid& big) {
  big = grid;
  for (auto it = entries_.begin(); it != entries_.end(); ++it) {
    const Entry& e = *it;
    if (!matches(e, c, grid, m, shift_x, shift_y)) continue;
    if (e.kernel.mx() >= grid.mx && e.kernel.my() >= grid.my) {
      entries_.splice(entries_.begin(), entries_, it);
      return cut_kernel(entries_.front().kernel, grid.mx, grid.my);
    }
    // A grid that outgrew its kernel is a growing patch: a quarter more than asked in each
    // direction and half as much again as kept in a direction it outgrew, so that a patch
    // growing case by case (a wheel/rail sweep: 24 → 32 → 48 elements) tabulates a few times,
    // not at every step.
    const auto grown = [](int asked, int kept) {
      const int margin = asked + (asked + 3) / 4;
      return asked > kept ? std::max(margin, kept + kept / 2) : std::max(margin, kept);
    };
    big.mx = grown(grid.mx, e.kernel.mx());
    big.my = grown(grid.my, e.kernel.my());
    kept_bytes_ -= bytes_of(it->kernel);
    entries_.erase(it);  // too small: replaced by a larger one
    return std::nullopt;
  }
  // A first request gets its own size and one element more each way, for the rolling step
  // of one element that steady rolling reads from it (kernels(): whole steps): most grids never
  // grow (a module-3 sequence), and the closed forms are the set-up.
  big.mx = grid.mx + 1;
  big.my = grid.my + 1;
  return std::nullopt;
}

std::vector<Kernel> KernelLibrary::kernels(const std::vector<Component>& cs, const Grid& grid,
                                           const CombinedMaterial& m, double shift_x,
                                           double shift_y) {
  // Turned coefficients (C=4): the plain ones kept here, turned for this curvature (which a
  // conformal patch's rows change from solve to solve) — a pass over the kernels instead of
  // their closed forms.
  if (m.inclination_corrected()) {
    const CombinedMaterial plain = uncorrected(m);
    return turned_kernels(cs, kernels(plain_components(plain), grid, plain, shift_x, shift_y), grid,
                          m, shift_y);
  }
  // The quadrature of a viscous part follows the grid's length (its kinks), so a kernel cut from
  // a larger grid's would differ in the last digits: viscoelastic kernels are made directly.
  // Kernels from a file's table (C=9) are copies of it, cheaper than the search.
  if (m.viscoelastic() || m.table) {
    computed_ += cs.size();
    return make_kernels(cs, grid, m, shift_x, shift_y);
  }
  // Steady rolling's shift of one element: the unshifted kernels one element wider, read one
  // offset on, instead of a second tabulation on a lattice that lacks the unshifted one's mirror
  // symmetry (twice its logarithms).
  if (const std::optional<WholeSteps> w = whole_steps(grid, m, shift_x, shift_y)) {
    Grid wider = grid;
    wider.mx += std::abs(w->nx);
    wider.my += std::abs(w->ny);
    std::vector<Kernel> shifted;
    shifted.reserve(cs.size());
    for (const Kernel& k : kernels(cs, wider, m, 0.0, 0.0))
      shifted.push_back(cut_kernel(k, grid.mx, grid.my, w->nx, w->ny));
    return shifted;
  }
  std::vector<std::optional<Kernel>> out(cs.size());
  // Missing components, grouped by the size they are tabulated at (usually one group): each
  // group on one corner lattice.
  struct Group {
    Grid size;
    bool keep;
    std::vector<std::size_t> members;
  };
  std::vector<Group> groups;
  for (std::size_t q = 0; q < cs.size(); ++q) {
    Grid big;
    out[q] = cut_kept(cs[q], grid, m, shift_x, shift_y, big);
    if (out[q]) continue;
    // Kept only while a quarter of the budget holds it with the margin of a growing patch:
    // large module-3 grids build their operators once, and their kernels would only double the
    // memory. Those are made at their own size and not kept.
    const int margin_mx = std::max(big.mx, grid.mx + (grid.mx + 3) / 4);
    const int margin_my = std::max(big.my, grid.my + (grid.my + 3) / 4);
    const bool keep = 4 * bytes_for(margin_mx, margin_my) <= budget_bytes_;
    if (!keep) big = grid;
    auto g = std::find_if(groups.begin(), groups.end(), [&](const Group& x) {
      return x.size.mx == big.mx && x.size.my == big.my && x.keep == keep;
    });
    if (g == groups.end()) g = groups.insert(groups.end(), Group{big, keep, {}});
    g->members.push_back(q);
  }
  for (const Group& group : groups) {
    std::vector<Component> comps;
    for (std::size_t q : group.members) comps.push_back(cs[q]);
    std::vector<Kernel> made = make_kernels(comps, group.size, m, shift_x, shift_y);
    computed_ += comps.size();
    for (std::size_t k = 0; k < group.members.size(); ++k) {
      const std::size_t q = group.members[k];
      if (!group.keep) {
        out[q] = std::move(made[k]);
        continue;
      }
      out[q] = cut_kernel(made[k], grid.mx, grid.my);
      entries_.push_front({cs[q], grid.dx, grid.dy, m.g, m.nu, m.k, m.layer_compliance,
                           m.normal_layer_compliance, shift_x, shift_y, m.viscous, m.elements,
                           std::move(made[k])});
      kept_bytes_ += bytes_of(entries_.front().kernel);
    }
  }
  while (kept_bytes_ > budget_bytes_ && !entries_.empty()) {
    kept_bytes_ -= bytes_of(entries_.back().kernel);
    entries_.pop_back();
  }
  std::vector<Kernel> result;
  result.reserve(cs.size());
  for (auto& k : out) result.push_back(std::move(*k));
  return result;
}

}  // namespace rollcontact::elastic
