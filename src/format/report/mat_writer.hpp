#pragma once
// ASCII per-element `.mat` file of a solved module-3 case (A digit 1 or 2), spec/outputs.md §5:
// six pairs of a `%` comment line and a value line (metadata, grid, material, friction; format
// version 2410), a column header and one row per element, in CONTACT's fixed 14-character
// columns (Fortran g14.6), readable by CONTACT's Matlab scripts.

#include <filesystem>
#include <string>
#include <vector>

#include "format/inp/case_record.hpp"
#include "format/inp/wheelrail_record.hpp"
#include "rollcontact/solution.hpp"
#include "rollcontact/wheelrail.hpp"

namespace rollcontact::format {

/// Version of the .mat layout written in the last column of line 2.
inline constexpr int kMatFormatVersion = 2410;

/// The wheel/rail context of a module-1 patch's file (lines 1–8, spec/outputs.md §5), in
/// CONTACT's output convention (track coordinates; a left wheel's values as reported).
struct MatWheelRailContext {
  double s_ws = 0.0, pitch_ws = 0.0;                          ///< S_WS [mm], TH_WS [rad]
  double y_r = 0.0, z_r = 0.0, roll_r = 0.0, rnom_rol = 0.0;  ///< rail marker, roller radius
  double x_w = 0.0, y_w = 0.0, z_w = 0.0, roll_w = 0.0, yaw_w = 0.0, rnom_whl = 0.0;
  double x_cp_r = 0.0, y_cp_r = 0.0, z_cp_r = 0.0, delt_cp_r = 0.0;  ///< rail-profile coords
  double x_cp_w = 0.0, y_cp_w = 0.0, z_cp_w = 0.0;                   ///< wheel-profile coords
  int npatch = 0, ipatch = 0;
  int c1 = 0, d = 2;
  double ynom_whl = 0.0;
  /// A left wheel: rows in reverse along y (iy → MY+1−iy, YL → −(YL+MY·DY)), PY and UY with the
  /// opposite sign (the patch fields are those of the mirrored computation).
  bool left = false;
};

/// The text of the .mat file: with digits.a == 1 the elements in contact (adhesion, slip,
/// plastic), with digits.a >= 2 every element of the potential contact area. `wheel_rail`
/// (module 1) fills the wheel/rail header values; module 3 writes zeros there.
std::string mat_file_text(const CaseRecord& problem, const Solution& solution,
                          const MatWheelRailContext* wheel_rail = nullptr);

/// `<stem>.<nnnn>.mat` (case number zero-padded to at least 4 digits).
std::filesystem::path mat_file_path(const std::filesystem::path& output_stem, int case_number);

/// Writes mat_file_text() atomically to mat_file_path() and returns the path.
/// Throws rollcontact::Error when the file cannot be written.
std::filesystem::path write_mat_file(const std::filesystem::path& output_stem,
                                     const CaseRecord& problem, const Solution& solution);

/// Module 1: one file per patch, `<stem>.<nnnn>a.mat`, `…b.mat`, … (A ≥ 1). `identity` is the
/// case's identity record (number, digits, solver, friction). Returns the paths written.
std::vector<std::filesystem::path> write_wheelrail_mat_files(
    const std::filesystem::path& output_stem, const WheelRailRecord& record,
    const CaseRecord& identity, const WheelRailSolution& solution);

}  // namespace rollcontact::format
