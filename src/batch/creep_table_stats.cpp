// Error statistics of creep-force tables; see creep_table_stats.hpp.

#include "batch/creep_table_stats.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "rollcontact/errors.hpp"

namespace rollcontact::batch {

namespace {

/// Running sums of one class.
struct Accumulator {
  ErrorSummary s;
  double sum_f = 0.0, sum_f2 = 0.0, sum_m = 0.0, sum_m2 = 0.0;

  void add(int number, double ef, double em) {
    ++s.count;
    sum_f += ef;
    sum_f2 += ef * ef;
    sum_m += em;
    sum_m2 += em * em;
    // Strict comparison: ties keep the first case in table order.
    if (s.worst_f == 0 || ef > s.max_f) {
      s.max_f = ef;
      s.worst_f = number;
    }
    if (s.worst_mz == 0 || em > s.max_mz) {
      s.max_mz = em;
      s.worst_mz = number;
    }
  }
  ErrorSummary finish() const {
    ErrorSummary r = s;
    if (r.count > 0) {
      const double n = r.count;
      r.mean_f = sum_f / n;
      r.rms_f = std::sqrt(sum_f2 / n);
      r.mean_mz = sum_m / n;
      r.rms_mz = std::sqrt(sum_m2 / n);
    }
    return r;
  }
};

bool same(double x, double y) {
  return std::abs(x - y) <= 1e-9 * std::max(1.0, std::abs(y));
}

std::string row_text(const std::string& label, const ErrorSummary& s) {
  return fmt::format(
      "{:<12} {:>5} {:>8.3f} {:>8.3f} {:>8.3f} {:>6} {:>8.3f} {:>8.3f} {:>8.3f} {:>6}{}\n", label,
      s.count, 100.0 * s.mean_f, 100.0 * s.rms_f, 100.0 * s.max_f, s.worst_f, 100.0 * s.mean_mz,
      100.0 * s.rms_mz, 100.0 * s.max_mz, s.worst_mz,
      s.skipped > 0 ? fmt::format("  ({} not converged)", s.skipped) : "");
}

std::string row_markdown(const std::string& label, const ErrorSummary& s) {
  return fmt::format(
      "| {} | {} | {:.2f} | {:.2f} | {:.2f} (#{}) | {:.2f} | {:.2f} | {:.2f} (#{}) | {} |\n", label,
      s.count, 100.0 * s.mean_f, 100.0 * s.rms_f, 100.0 * s.max_f, s.worst_f, 100.0 * s.mean_mz,
      100.0 * s.rms_mz, 100.0 * s.max_mz, s.worst_mz, s.skipped);
}

}  // namespace

TableStatistics compare_tables(std::span<const TableRow> rows,
                               std::span<const TableRow> reference) {
  std::map<int, const TableRow*> ref;
  for (const TableRow& r : reference) ref[r.tc.number] = &r;
  Accumulator all;
  std::map<double, Accumulator> by_aob, by_spin;
  for (const TableRow& r : rows) {
    const auto it = ref.find(r.tc.number);
    if (it == ref.end())
      throw InputError("reference table", 0, fmt::format("has no case {}", r.tc.number));
    const TableRow& q = *it->second;
    if (!same(r.tc.a_over_b, q.tc.a_over_b) || !same(r.tc.spin, q.tc.spin) ||
        !same(r.tc.angle_deg, q.tc.angle_deg) || !same(r.tc.magnitude, q.tc.magnitude))
      throw InputError("reference table", 0,
                       fmt::format("case {}: a/b, spin, angle or magnitude differ", r.tc.number));
    Accumulator& ca = by_aob[r.tc.a_over_b];
    Accumulator& cs = by_spin[r.tc.spin];
    const double ef = std::hypot(r.fx_rel - q.fx_rel, r.fy_rel - q.fy_rel);
    const double em = std::abs(r.mz_rel - q.mz_rel);
    if (!r.converged || !q.converged || !std::isfinite(ef) || !std::isfinite(em)) {
      ++all.s.skipped;
      ++ca.s.skipped;
      ++cs.s.skipped;
      continue;
    }
    all.add(r.tc.number, ef, em);
    ca.add(r.tc.number, ef, em);
    cs.add(r.tc.number, ef, em);
  }
  TableStatistics s;
  s.overall = all.finish();
  for (const auto& [k, acc] : by_aob) {
    s.aob_values.push_back(k);
    s.per_aob.push_back(acc.finish());
  }
  for (const auto& [k, acc] : by_spin) {
    s.spin_values.push_back(k);
    s.per_spin.push_back(acc.finish());
  }
  return s;
}

std::string format_statistics_text(const TableStatistics& s, const std::string& title) {
  std::string out = fmt::format(
      "{}: error against the reference, % of muFN (force vector) and of muFN*c (MZ)\n", title);
  out += fmt::format("{:<12} {:>5} {:>8} {:>8} {:>8} {:>6} {:>8} {:>8} {:>8} {:>6}\n", "class",
                     "cases", "F mean", "F rms", "F max", "case", "MZ mean", "MZ rms", "MZ max",
                     "case");
  out += row_text("all", s.overall);
  for (std::size_t i = 0; i < s.per_aob.size(); ++i)
    out += row_text(fmt::format("a/b={:g}", s.aob_values[i]), s.per_aob[i]);
  for (std::size_t i = 0; i < s.per_spin.size(); ++i)
    out += row_text(fmt::format("spin={:g}", s.spin_values[i]), s.per_spin[i]);
  return out;
}

std::string format_statistics_markdown(const TableStatistics& s, const std::string& title) {
  std::string out = fmt::format("### {}\n\n", title);
  out +=
      "Errors in % of μFN (force vector |(Fx, Fy) − ref|) and of μFN·c (MZ); (#n) the case of "
      "the maximum.\n\n"
      "| class | cases | F mean | F RMS | F max | MZ mean | MZ RMS | MZ max | not converged |\n"
      "|---|---|---|---|---|---|---|---|---|\n";
  out += row_markdown("all", s.overall);
  for (std::size_t i = 0; i < s.per_aob.size(); ++i)
    out += row_markdown(fmt::format("a/b = {:g}", s.aob_values[i]), s.per_aob[i]);
  for (std::size_t i = 0; i < s.per_spin.size(); ++i)
    out += row_markdown(fmt::format("spin = {:g}", s.spin_values[i]), s.per_spin[i]);
  return out;
}

}  // namespace rollcontact::batch
