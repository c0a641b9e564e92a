#pragma once
// The state behind the cntc_* C interface (spec library-api.md §1): result elements (ire) with
// their contact problems (icp), the units of each problem, the log, and the access rules of
// §1.3. The handle table is process-wide because the C interface is: it is the one object of
// its kind, reached through library(), and every access to it is under its mutex. Each
// problem has its own lock for calculate, so that different (ire, icp) solve concurrently.

#include <array>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "format/inp/case_record.hpp"
#include "format/inp/wheelrail_record.hpp"
#include "rollcontact/solution.hpp"
#include "rollcontact/solve.hpp"
#include "rollcontact/wheelrail.hpp"

namespace rollcontact::cntc {

/// Scale factors of a unit convention: internal value = external value × factor (§1.4).
struct Units {
  int code = 1934;        ///< CNTC_un_*
  double length = 1.0;    ///< mm per external length unit
  double velocity = 1.0;  ///< mm/s per external velocity unit
  double body = 1.0;      ///< +1: forces act on body 1; −1 (SIMPACK): on body 2
  double area() const { return length * length; }
  double pressure() const { return 1.0 / area(); }  ///< N/mm² per external pressure unit
};

/// Units for a CNTC_un_* code; false for an unknown code.
bool units_for_code(int code, Units& units);

/// Flags cntc_setflags stores and cntc_getflags returns that no solver reads here (§2.2): the
/// sensitivities' and subsurface output digits, the debug switch, the input-file writing.
struct StoredFlags {
  int sens = 0;      ///< S2 (1988), [0, 3]
  int sbsout = 0;    ///< O_s (1991), [0, 4], 3 becomes 2
  int sbsfil = 0;    ///< A_s (1992), 0..2
  int xflow = 0;     ///< X (1981): extended debug output on (1) or off
  int wrtinp = 0;    ///< 2002, as given
  int npot_max = 0;  ///< 1993 in module 3 (module 1 keeps it in its record)
};

/// One module-3 contact problem: the case as CONTACT's digits and blocks describe it, built by
/// the setters; the solver that keeps its sequence; the last solution.
struct Module3Problem {
  format::CaseRecord record;
  Units units;
  bool grid_given = false;      ///< setpotcontact or sethertzcontact was called
  bool geometry_given = false;  ///< setundeformeddistc was called
  int cases = 0;                ///< calculations done
  PatchSolver solver;
  std::optional<Solution> result;
  std::vector<model::SubsurfaceBlock> subs_blocks;  ///< subs_addblock
  std::vector<SubsurfaceResult> subs_results;       ///< subs_calculate, one per block
  std::array<double, 9> metadata{};                 ///< setmetadata (recorded only)
  StoredFlags flags;
  double cpu_seconds = 0.0, wall_seconds = 0.0;
  std::mutex busy;  ///< held by calculate
  Module3Problem();
};

/// The wheel/rail problem of a module-1 result element: the case as a WheelRailRecord built by
/// the setters, the solver that keeps profiles and operators, the last solution.
struct Module1Problem {
  format::WheelRailRecord record;
  Units units;
  bool friction_given = false;
  std::string rail_error, wheel_error;  ///< why a profile could not be read (empty: fine)
  int cases = 0;
  WheelsetSolver solver;
  std::optional<WheelRailSolution> result;
  std::vector<model::SubsurfaceBlock> subs_blocks;  ///< subs_addblock (all patches)
  /// subs_addblock with a patch number: that patch's own blocks (instead of the common ones).
  std::map<int, std::vector<model::SubsurfaceBlock>> patch_subs_blocks;
  /// subs_calculate: per patch (index icp − 1), one result per block.
  std::vector<std::vector<SubsurfaceResult>> subs_results;
  std::array<double, 9> metadata{};
  StoredFlags flags;
  double sequence_dx = 0.0, sequence_ds = 0.0;  ///< DX, DS of the last calculate [mm]
  double cpu_seconds = 0.0, wall_seconds = 0.0;
  std::mutex busy;  ///< held by calculate
  Module1Problem();
};

struct ResultElement {
  int module = 3;
  std::array<std::unique_ptr<Module3Problem>, 10> problems;  ///< module 3: icp 1..9
  std::unique_ptr<Module1Problem> wheel_rail;                ///< module 1
};

/// What a routine works on after the access check: a module-3 problem, or a module-1 problem
/// with icp = −1 (the whole case) or a patch number.
struct Target {
  Module3Problem* m3 = nullptr;
  Module1Problem* m1 = nullptr;
  int icp = 0;
  explicit operator bool() const { return m3 != nullptr || m1 != nullptr; }
  const Units& units() const { return m3 != nullptr ? m3->units : m1->units; }
};

/// Access categories of the routines (§1.3 table).
enum class Access {
  Module3,        ///< cat 1: module 3, icp 1..9
  Module1,        ///< cat 2: module 1, no icp
  Module1Patch,   ///< cat 3
  Module1Forces,  ///< cat 4
  Settings,       ///< cat 5: module 1 icp = −1, module 3 icp 1..9
  Results,        ///< cat 6: a patch, icp ≥ 1
  Either,         ///< cat 7: −1 or a patch
};

/// The internal codes of a refused access (§1.3).
constexpr int kBadIre = -101, kNotInModule1 = -102, kNotInModule3 = -103, kBadIcp = -104,
              kNeedsPatch = -105, kNoPatchAllowed = -106;
/// A module-1 patch number beyond the last calculate's patches (CNTC_err_icp).
constexpr int kNoSuchPatch = -31;

class Library {
 public:
  /// cntc_initializefirst: opens <outdir><expnam>.out (once; later calls only return false).
  bool initialize_first(int output_to_screen, const std::string& wrkdir, const std::string& outdir,
                        const std::string& expnam);
  /// cntc_initialize: creates `ire` with module 1 or 3; −12 when 100 are active already.
  int create(int ire, int module);
  void finalize(int ire);
  void finalize_last();

  /// The problem (ire, icp) for a routine of category `access`, its element created if new;
  /// an empty Target and a logged message (code in *code when given) when the access is refused.
  Target open(int ire, int icp, Access access, const char* routine, int* code = nullptr);

  /// Appends a line to the log (the .out file; also stdout when asked for).
  void log(const std::string& line);

  /// The effective working folder (relative profile names are resolved against it).
  std::filesystem::path working_folder();

  int debug_level() const { return debug_level_; }
  void set_debug_level(int level) { debug_level_ = level; }

 private:
  int check(int ire, int icp, Access access, int module) const;
  /// kNoSuchPatch when a module-1 routine names a patch the last calculate did not find.
  int check_patch_exists(int icp, Access access, const ResultElement& e) const;
  ResultElement* element_or_create(int ire, int icp);

  std::mutex mutex_;
  bool initialised_ = false;
  bool to_screen_ = false;
  std::ofstream out_;
  std::filesystem::path work_;
  std::map<int, std::unique_ptr<ResultElement>> elements_;
  int debug_level_ = 0;
};

/// The library's handle table (the C interface has no other place to keep it).
Library& library();

/// library().open() for the pointer arguments of a routine: a null handle is refused (logged; the
/// code CNTC_err_icp in *code when given).
Target open_target(const int* ire, const int* icp, Access access, const char* routine,
                   int* code = nullptr);

/// Logs that `routine` refused its arguments: nothing was changed (the spec's "rejected").
void reject(const char* routine, const std::string& why);

/// A C string argument: at most `len` characters, up to the first NUL; blank means empty.
std::string c_string(const char* s, const int* len);

}  // namespace rollcontact::cntc
