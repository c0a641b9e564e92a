#pragma once
// Reader of CONTACT-style `.out` reports — CONTACT's own (`.ref_out`) and ours, which share the
// layout (spec/outputs.md §3) — following spec/validation.md §2: cases split at `^ Case\s+(\d+)`,
// reading stops at the timing table (`^|`), values are taken by position from the line after a
// label line, and the labels say what the X/Y values mean. Trace lines are never interpreted.

#include <filesystem>
#include <iosfwd>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rollcontact::format {

/// The numbers one case of a report prints, by name. Names are the report's labels with
/// `ELAST.EN.` → `ELEN` and `FRIC.POWER` / `FRIC.WORK` → `FRIC`:
///  * force block: `FN FX FY MZ ELEN FRIC` and `FN/G`, then `FX/FSTAT/FN` or the solved
///    `CREEP X` / `SHIFT X`, then `FY/FSTAT/FN` or `CREEP Y` / `SHIFT Y`, `APPROACH`, `PMAX`,
///    `MAX(T1,T2)` (module 1 per patch: `FS`, `MN`, `FS/FSTAT/FN`; D=4 `BAR_FN`, `TILDE_FN`, …);
///  * statistics: `NPOT NCON NADH NSLIP [NPLAST] INORM ITANG`;
///  * module 1, per case: `FX(TR) FY(TR) FZ(TR) FX(WS) FY(WS) FZ(WS)`, `S_WS Y_WS Z_WS …`;
///    per patch: `XCP(TR) YCP(TR) ZCP(TR) DELTCP(TR) YCP(R) ZCP(R)`, `XCP(W) YCP(W) ZCP(W)`,
///    `CHI DQ VELOC CKSI CETA CPHI`.
///  * subsurface stresses: the extremes of block b as `SUBS b/SIGHYD`, `SIGVM`, `SIGTR`,
///    `SIGMA1`, `SIGMA3`, `SIGXX`, `SIGYY`, `SIGZZ` (their locations are not kept).
/// Module-1 quantities of contact patch k carry the prefix `patch k/` (`patch 1/FN`); module 3
/// has one implicit patch and no prefix. A field printed as asterisks (Fortran overflow) is NaN.
struct ReportCase {
  int number = 0;
  /// Our reports only: the ` ERROR: ` message of a case that was not solved (not supported,
  /// inadmissible data), continuation lines joined by blanks. Empty for a solved case.
  std::string error;
  std::map<std::string, double> values;

  /// The value named `name`, if the case printed it.
  std::optional<double> value(std::string_view name) const;
};

/// All cases of a report in file order.
struct Report {
  std::vector<ReportCase> cases;

  /// The first case numbered `number`, or nullptr.
  const ReportCase* find(int number) const;
};

/// Parses one report token as a real: `10000.`, `1.000E+04`, `0.1000E-03`, `-0.000`, `1.0D+03`,
/// Fortran's three-digit exponent without letter (`0.1000-100`). nullopt when it is not a number.
std::optional<double> parse_report_real(std::string_view token);

/// Parses a whole report. Never throws on odd content: unknown lines are skipped.
Report parse_report(std::istream& in);
/// Same for a file; throws rollcontact::Error when it cannot be opened.
Report parse_report_file(const std::filesystem::path& path);

}  // namespace rollcontact::format
