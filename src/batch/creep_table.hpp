#pragma once
// The creep-force table of Vollebregt, Iwnicki, Xie & Shackleton (Vehicle System Dynamics 50(1),
// 2012): 3220 steady-rolling Hertzian cases over ellipticity, spin, creepage direction and
// magnitude, solved with one method (exact theory, Fastsim, FaStrip) and written as CSV, so that
// the approximate methods can be assessed against the exact one (creep_table_stats.hpp).
//
// Units: semi-axes in mm, forces in N, G in N/mm², V in mm/s. The table itself is
// non-dimensional: fx_rel = Fx/(μFN), fy_rel = Fy/(μFN), mz_rel = Mz/(μFN·c), c = √(ab).

#include <cstddef>
#include <functional>
#include <iosfwd>
#include <span>
#include <string>
#include <vector>

#include "batch/distribution.hpp"
#include "rollcontact/solve.hpp"

namespace rollcontact::batch {

/// Method of the table. Exact: B digit with M=0; the others: M = 2, 3, 5.
enum class TableMethod { Exact, Fastsim1, Fastsim3, FaStrip };

/// Parses "exact", "fastsim1", "fastsim3", "fastrip"; throws InputError otherwise.
TableMethod parse_table_method(const std::string& name);
std::string table_method_name(TableMethod method);

/// How every case of the table is solved.
struct TableSettings {
  TableMethod method = TableMethod::Exact;
  /// Normal pressure: 0 exact (half-space) normal solve, 2 elliptic, 3 parabolic (B digit);
  /// -1: the default of the method (0 for exact, 2 for the approximate methods).
  int bound = -1;
  int mx = 11;        ///< elements per axis of the potential contact (mx = my)
  double eps = 1e-5;  ///< solver tolerance (exact theory)
};

/// The B digit in effect for `s` (resolves the default -1).
int effective_bound(const TableSettings& s);

/// Throws InputError (naming the option) unless the bound in effect is 0, 2 or 3 and mx ≥ 5.
void check_table_settings(const TableSettings& s);

/// Fixed data of the assessment.
inline constexpr double table_g = 82000.0;      ///< shear modulus of both bodies [N/mm²]
inline constexpr double table_nu = 0.28;        ///< Poisson ratio of both bodies [-]
inline constexpr double table_mu = 0.3;         ///< friction coefficient [-]
inline constexpr double table_fn = 82000.0;     ///< normal force [N]
inline constexpr double table_veloc = 10000.0;  ///< rolling velocity [mm/s]
inline constexpr std::size_t table_case_count = 3220;

/// One case of the table (parameters only).
struct TableCase {
  int number = 0;          ///< 1-based, in table order
  double a_over_b = 1.0;   ///< semi-axis ratio a/b [-] (a along the rolling direction)
  double a = 9.0;          ///< semi-axis a [mm]
  double b = 9.0;          ///< semi-axis b [mm]
  double spin = 0.0;       ///< non-dimensional spin φρ/μ [-]
  double angle_deg = 0.0;  ///< direction θ of the creepage (ξ, η) [deg]
  double magnitude = 0.0;  ///< non-dimensional creepage magnitude √(ξ²+η²)·ρ/(μc) [-]
};

/// All 3220 cases: magnitude fastest, then direction, spin, ellipticity (a/b = 0.2, 0.5, 1, 2, 5
/// with a = 4, 6, 9, 12, 20 mm).
std::vector<TableCase> table_cases();

/// Dimensional creepages of a case: ξ = m·μ·cosθ·c/ρ, η = m·μ·sinθ·c/ρ, φ = μ·spin/ρ [rad/mm],
/// with ρ = 2/(A1+B1) [mm] of the Hertz solution for the semi-axes and FN, c = √(ab) [mm].
struct TableCreepages {
  double cksi = 0.0, ceta = 0.0, cphi = 0.0;
  double rho = 0.0, c = 0.0;
};
TableCreepages table_creepages(const TableCase& tc);

/// The patch problem of a case: a Hertzian potential contact from the semi-axes (IPOTCN = −3),
/// mx × mx elements over mx/(mx−4) times the Hertz ellipse, steady rolling, normal force
/// prescribed, a new sequence (no dependence on earlier cases). fastsim1 uses one flexibility L =
/// (L1+L2+L3)/3 of Kalker's three; fastsim3 and fastrip run with K0_MF = ALFAMF = 1 (original, not
/// slope-reduced, Fastsim).
model::PatchProblem table_problem(const TableCase& tc, const TableSettings& s);

/// Result of one case.
struct TableRow {
  TableCase tc;
  double fx_rel = 0.0, fy_rel = 0.0, mz_rel = 0.0;  ///< see the file comment
  double slip_percent = 0.0;                        ///< 100·NSLIP/NCON
  bool converged = true;  ///< false: solver did not converge or the case threw
  std::string message;    ///< why not converged (not written to the CSV)
};

/// Solves one case with `solver` (one PatchSolver per thread). Solver errors do not throw: they
/// give converged = false with the message.
TableRow solve_table_case(const TableCase& tc, const TableSettings& s, PatchSolver& solver);

/// Solves `cases` on `threads` threads (each with its own PatchSolver; case i of the list goes to
/// thread i mod threads, so the split is deterministic) and returns the rows in the order of
/// `cases`. `progress(done)` is called from the calling thread every ~0.2 s and at the end.
std::vector<TableRow> run_table(std::span<const TableCase> cases, const TableSettings& s,
                                int threads, const std::function<void(std::size_t)>& progress = {});

/// Solves `cases` over the processes of `distribution` (one PatchSolver each, cases handed out
/// dynamically in chunks) and returns the rows in the order of `cases` on the root (empty on the
/// other processes): the same rows, bit for bit, as run_table() on one process.
std::vector<TableRow> run_table_distributed(std::span<const TableCase> cases,
                                            const TableSettings& s, Distribution& distribution);

/// A row's results as bytes for another process (doubles bit-exact, the message verbatim) and
/// back; the case parameters travel as the case itself.
std::string encode_table_row(const TableRow& row);
TableRow decode_table_row(const std::string& bytes, const TableCase& tc);

/// Selection "1-50,60,100-120" of 1-based case numbers, sorted and unique, each in 1..total.
/// Empty text selects all. Throws InputError for malformed text or out-of-range numbers.
std::vector<int> parse_case_selection(const std::string& text, std::size_t total);

/// The table cases of a selection as parse_case_selection() reads it (empty: all 3220).
std::vector<TableCase> select_table_cases(const std::string& selection);

/// CSV header and rows (a final column `converged` 1/0 after the required ones). The number
/// format does not depend on the locale: the same rows give the same bytes.
std::string table_csv_header();
void write_table_csv(std::ostream& out, std::span<const TableRow> rows);
/// Reads a CSV written by write_table_csv (a missing `converged` column means converged).
/// Throws InputError naming the line for a malformed file. Messages are not stored.
std::vector<TableRow> read_table_csv(std::istream& in, const std::string& name);
/// The same from a file; InputError when it cannot be opened.
std::vector<TableRow> read_table_csv_file(const std::string& path);

}  // namespace rollcontact::batch
