#pragma once
// The operators a PatchSolver applies — influence operators with their FFT products and
// preconditioners — kept between cases and keyed by what they depend on: grid, material and,
// for the tangential ones, the kind of loading and the rolling step. Several entries per kind,
// so that a sequence of patches on different grids (two patches of a wheel, the coarse levels
// of the nested-iteration start) does not rebuild them case after case.
//
// Eviction is least-recently-used, but never of an entry used since the last begin_case(): the
// references handed out stay valid for the whole case. A cache may therefore hold more entries
// than its capacity while one case uses more.

#include <chrono>
#include <cstddef>
#include <list>
#include <memory>

#include "elastic/operators/operator_sets.hpp"
#include "normal/preconditioner.hpp"
#include "tangential/tangential_preconditioner.hpp"
#include "tangential/tangential_system.hpp"

namespace rollcontact {

/// C_nn/G with its FFT product and the circulant preconditioner of the normal CG (none for
/// viscoelastic bodies, whose normal problem is not solved by CG).
struct NormalOperators : elastic::operators::NormalOperatorSet {
  std::unique_ptr<normal::CirculantPreconditioner> preconditioner;
};

/// The tangential set with the block-circulant approximation of C_tt⁻¹·G (for steady rolling
/// combined with the row sums of (I − T)⁻¹ by the solver).
struct TangentialOperators : elastic::operators::TangentialOperatorSet {
  std::unique_ptr<tangential::TangentialPreconditioner> preconditioner;

  tangential::TangentialOperator view() const {
    return {&xx,         &xy,      &a_yx(),          &yy, a.get(), preconditioner.get(),
            symmetric(), steady(), interaction.get()};
  }
};

/// A coarse level of the steady-rolling start, with the preconditioner from its C_tt.
struct CoarseSteadyOperators : elastic::operators::SteadyRollingOperatorSet {
  std::unique_ptr<tangential::TangentialPreconditioner> preconditioner;

  tangential::TangentialOperator view() const {
    return {&xx, &xy, &xy, &yy, a.get(), preconditioner.get(), false, true};
  }
};

/// What an operator set depends on. Shifts are compared exactly: a different rolling step is a
/// different operator.
struct OperatorKey {
  Grid grid;
  CombinedMaterial material;
  model::TangentialKind kind = model::TangentialKind::None;
  double shift_x = 0.0, shift_y = 0.0;  ///< [mm]
  elastic::InteractionPtr interaction;  ///< compared by contents

  /// C=9 tables by contents: every case of a sequence reads its file again (a new table object),
  /// and operators built for the first serve the others.
  static bool same_table(const CombinedMaterial& a, const CombinedMaterial& b) noexcept {
    if (a.table == b.table) return true;
    return a.table && b.table && a.table->same_coefficients(*b.table);
  }

  friend bool operator==(const OperatorKey& a, const OperatorKey& b) noexcept {
    return a.grid.mx == b.grid.mx && a.grid.my == b.grid.my && a.grid.dx == b.grid.dx &&
           a.grid.dy == b.grid.dy && a.material.g == b.material.g &&
           a.material.nu == b.material.nu && a.material.k == b.material.k &&
           a.material.layer_compliance == b.material.layer_compliance &&
           a.material.normal_layer_compliance == b.material.normal_layer_compliance &&
           a.material.viscous == b.material.viscous && same_table(a.material, b.material) &&
           a.material.elements == b.material.elements &&
           a.material.inclination_variant == b.material.inclination_variant &&
           a.material.inclination_curvature_per_mm == b.material.inclination_curvature_per_mm &&
           a.kind == b.kind && a.shift_x == b.shift_x && a.shift_y == b.shift_y &&
           elastic::same_interaction(a.interaction, b.interaction);
  }
};

/// Least-recently-used entries of one kind; see the file comment for the eviction rule.
template <class Entry>
class OperatorShelf {
 public:
  explicit OperatorShelf(std::size_t capacity) : capacity_(capacity) {}

  /// The entry for `key`, built by `build(Entry&)` in place if missing; the wall time of a
  /// build is added to `build_seconds`.
  template <class Build>
  Entry& get(const OperatorKey& key, unsigned long case_number, double& build_seconds,
             Build&& build) {
    for (auto it = entries_.begin(); it != entries_.end(); ++it)
      if (it->key == key) {
        it->last_case = case_number;
        entries_.splice(entries_.begin(), entries_, it);
        return *entries_.front().entry;
      }
    const auto start = std::chrono::steady_clock::now();
    auto entry = std::make_unique<Entry>();
    build(*entry);
    build_seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    entries_.push_front({key, std::move(entry), case_number});
    ++builds_;
    evict(case_number);
    return *entries_.front().entry;
  }

  std::size_t size() const noexcept { return entries_.size(); }
  std::size_t builds() const noexcept { return builds_; }

 private:
  struct Slot {
    OperatorKey key;
    std::unique_ptr<Entry> entry;
    unsigned long last_case = 0;
  };

  void evict(unsigned long case_number) {
    while (entries_.size() > capacity_) {
      auto victim = entries_.end();
      for (auto it = entries_.begin(); it != entries_.end(); ++it)
        if (it->last_case != case_number) victim = it;  // the last such is the least recent
      if (victim == entries_.end()) return;             // all in use by this case
      entries_.erase(victim);
    }
  }

  std::size_t capacity_;
  std::list<Slot> entries_;  ///< most recently used first
  std::size_t builds_ = 0;
};

/// Entries kept per kind. A tangential set of a 287×323 grid takes about 0.1 GB, a normal one
/// a tenth of that; coarse levels a quarter per level.
struct OperatorCacheCapacity {
  std::size_t normal = 8;
  std::size_t tangential = 3;  // the grid's, and the contact box's (contact_box.hpp)
  std::size_t coarse_steady = 8;
};

class OperatorCache {
 public:
  explicit OperatorCache(elastic::operators::FftChoice fft, OperatorCacheCapacity capacity = {});

  /// Marks the start of a case: entries used from now on are kept until the next call.
  void begin_case() noexcept { ++case_number_; }

  /// `interaction`: attenuation between parts of the grid (IPLAN=4), none by default. The
  /// preconditioners ignore it (they approximate the full-interaction operator).
  NormalOperators& normal(const Grid& grid, const CombinedMaterial& material,
                          elastic::InteractionPtr interaction = nullptr);
  /// Tangential operators for shifts, transient or steady rolling with the rolling step
  /// (shift_x, shift_y) [mm] (ignored for shifts).
  TangentialOperators& tangential(const Grid& grid, const CombinedMaterial& material,
                                  model::TangentialKind kind, double shift_x_mm, double shift_y_mm,
                                  elastic::InteractionPtr interaction = nullptr);
  /// Steady-rolling operator of a coarse level with its (coarse) rolling step [mm].
  CoarseSteadyOperators& coarse_steady(const Grid& grid, const CombinedMaterial& material,
                                       double shift_x_mm, double shift_y_mm);

  /// The grid's normal kernel C_nn / G from the kept kernels (approximate pressures that need
  /// the displacement at one point: KPEC's level; no operator set is built for them).
  /// At least the grid's size, valid until the next call (elastic::KernelLibrary::covering).
  const elastic::Kernel& normal_kernel(const Grid& grid, const CombinedMaterial& material) {
    return kernels_.covering(elastic::Component::nn, grid, material);
  }

  /// Operator sets assembled so far and held now, all kinds together (for tests and reports).
  std::size_t builds() const noexcept;
  std::size_t size() const noexcept;
  /// Wall time spent building operator sets so far [s] (kernels, FFT plans, preconditioners).
  double build_seconds() const noexcept { return build_seconds_; }

 private:
  elastic::operators::FftChoice fft_;
  elastic::KernelLibrary kernels_;  ///< kernels of all sets, reused across grid sizes
  unsigned long case_number_ = 0;
  double build_seconds_ = 0.0;
  OperatorShelf<NormalOperators> normal_;
  OperatorShelf<TangentialOperators> tangential_;
  OperatorShelf<CoarseSteadyOperators> coarse_steady_;
};

}  // namespace rollcontact
