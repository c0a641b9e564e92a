#pragma once
// Creep-force lookup tables for multibody (MBS) codes: the steady-rolling creep forces of a
// Hertzian contact, computed once with the exact theory (or Fastsim) on a grid of semi-axis ratio
// and normalised creepages, stored in HDF5 and interpolated at every wheel and time step.
//
// Normalisation (quasi-identical elastic bodies, Poisson ratio fixed by the table): with
// c = √(ab) [mm], FN [N], G [N/mm²] and μ,
//   ξ̃ = G·c²·ξ/(μ·FN),  η̃ = G·c²·η/(μ·FN),  φ̃ = G·c³·φ/(μ·FN)   (φ in rad/mm),
// and the results F_x/(μ·FN), F_y/(μ·FN), M_z/(μ·FN·c). By the similarity of Hertzian contacts
// these depend on a/b and the normalised creepages only, so one table serves every load,
// size, modulus and friction coefficient.

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace rollcontact {

/// The grid of a table; every axis strictly increasing, at least 2 values.
struct CreepLookupAxes {
  std::vector<double> a_over_b;  ///< semi-axis ratio a/b (a along the rolling direction) [-]
  std::vector<double> ksi;       ///< normalised longitudinal creepage ξ̃ [-]
  std::vector<double> eta;       ///< normalised lateral creepage η̃ [-]
  std::vector<double> phi;       ///< normalised spin φ̃ [-]
};

/// Normalised results: F_x/(μFN), F_y/(μFN), M_z/(μFN·c). Forces act on body 1 (the wheel).
struct CreepLookupValue {
  double fx = 0.0, fy = 0.0, mz = 0.0;
};

/// What a table was computed with (stored in its file).
struct CreepLookupInfo {
  std::string method = "exact";  ///< exact, fastsim1, fastsim3, fastrip
  int mx = 15;                   ///< elements per semi-axis pair (grid mx × mx)
  double poisson_ratio = 0.28;   ///< ν of both bodies [-]
  std::string software;          ///< the rollcontact version that made it
};

/// Dimensional results of CreepLookupTable::forces().
struct CreepLookupForces {
  double fx_N = 0.0, fy_N = 0.0;  ///< creep forces on body 1 [N]
  double mz_Nmm = 0.0;            ///< spin moment [N·mm]
};

class CreepLookupTable {
 public:
  CreepLookupTable() = default;
  /// `values` holds one entry per node, in the order of node_index(). Throws
  /// InvalidValueError for an axis that is not strictly increasing or has fewer than 2 values,
  /// a size mismatch, or a non-finite value.
  CreepLookupTable(CreepLookupAxes axes, std::vector<CreepLookupValue> values,
                   CreepLookupInfo info);

  [[nodiscard]] const CreepLookupAxes& axes() const noexcept { return axes_; }
  [[nodiscard]] const CreepLookupInfo& info() const noexcept { return info_; }
  [[nodiscard]] const std::vector<CreepLookupValue>& values() const noexcept { return values_; }
  [[nodiscard]] bool empty() const noexcept { return values_.empty(); }

  /// Index of node (a/b index, ξ̃ index, η̃ index, φ̃ index); φ̃ runs fastest.
  [[nodiscard]] std::size_t node_index(std::size_t i_ab, std::size_t i_ksi, std::size_t i_eta,
                                       std::size_t i_phi) const noexcept {
    return ((i_ab * axes_.ksi.size() + i_ksi) * axes_.eta.size() + i_eta) * axes_.phi.size() +
           i_phi;
  }

  /// Multilinear interpolation in (ln a/b, ξ̃, η̃, φ̃); exact at the nodes. Outside the table a/b and
  /// φ̃ are clamped to their ranges, and (ξ̃, η̃) is scaled back onto the border of its box
  /// along the line to the origin (the creepage direction kept: beyond the box the contact
  /// slides fully and the force no longer grows). An empty table gives zeros.
  [[nodiscard]] CreepLookupValue evaluate(double a_over_b, double ksi_n, double eta_n,
                                          double phi_n) const noexcept;

  /// The same in physical units: semi-axes a, b [mm], normal force FN [N], combined shear
  /// modulus G [N/mm²], friction coefficient μ, creepages ξ, η [-] and spin φ [rad/mm].
  [[nodiscard]] CreepLookupForces forces(double a_mm, double b_mm, double fn_N, double g_N_mm2,
                                         double mu, double ksi, double eta,
                                         double phi_rad_mm) const noexcept;

 private:
  CreepLookupAxes axes_;
  std::vector<CreepLookupValue> values_;
  CreepLookupInfo info_;
};

/// Writes `table` as HDF5 (datasets /axes/{a_over_b,ksi,eta,phi}, /fx, /fy, /mz of shape
/// [a/b][ξ̃][η̃][φ̃], attributes with the method, grid, ν and normalisation). Throws Error when
/// the file cannot be written; an existing file is replaced atomically.
void save_creep_lookup(const CreepLookupTable& table, const std::filesystem::path& path);

/// Reads a table written by save_creep_lookup(). Throws InputError naming the file for a
/// missing, unreadable or malformed file.
CreepLookupTable load_creep_lookup(const std::filesystem::path& path);

}  // namespace rollcontact
