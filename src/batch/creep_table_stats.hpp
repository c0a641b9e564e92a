#pragma once
// Error statistics of an approximate creep-force table against the exact one (Vollebregt et al.,
// VSD 2012): per case the error of the force vector |(fx, fy) − (fx, fy)_ref| [μFN] and of the
// spin moment |mz − mz_ref| [μFN·c]; mean, RMS and maximum overall, per ellipticity and per spin.

#include <span>
#include <string>
#include <vector>

#include "batch/creep_table.hpp"

namespace rollcontact::batch {

/// Statistics of one class of cases. Errors are non-dimensional (fractions of μFN, μFN·c).
struct ErrorSummary {
  int count = 0;    ///< cases compared (both converged)
  int skipped = 0;  ///< cases left out because either table has them not converged
  double mean_f = 0.0, rms_f = 0.0, max_f = 0.0;
  double mean_mz = 0.0, rms_mz = 0.0, max_mz = 0.0;
  int worst_f = 0, worst_mz = 0;  ///< case numbers of the maxima (0: none)
};

struct TableStatistics {
  ErrorSummary overall;
  std::vector<double> aob_values, spin_values;  ///< class keys, ascending
  std::vector<ErrorSummary> per_aob, per_spin;  ///< same order as the keys
};

/// Compares `rows` with the reference rows of the same case numbers. Throws InputError when the
/// reference lacks a case or its parameters (a/b, spin, angle, magnitude) differ.
TableStatistics compare_tables(std::span<const TableRow> rows, std::span<const TableRow> reference);

/// Plain-text table for the console and a Markdown version; `title` names the method.
std::string format_statistics_text(const TableStatistics& s, const std::string& title);
std::string format_statistics_markdown(const TableStatistics& s, const std::string& title);

}  // namespace rollcontact::batch
