#pragma once
// Number formats of CONTACT reports (spec/outputs.md §2): CONTACT's significant-digit format and
// the Fortran edit descriptors (Fw.d, Ew.d, Gw.d, Iw) as gfortran writes them. Report readers
// parse these columns by position, so every function returns exactly `width` characters (or
// `width` asterisks when the value does not fit, as Fortran does).

#include <string>

namespace rollcontact::format {

/// CONTACT's fmt_gs(w, d, e, v): lg = floor(log10|v| + 1e-7) (0 for |v| < 1e-20); scientific
/// with `sci_digits` significant digits when lg >= digits or lg <= -2 (`1.998E-02`), otherwise
/// fixed with max(0, digits - lg - 1) decimals (`9.195`, `-36.24`, `10000.`). Right-aligned.
std::string fmt_sig(int width, int digits, int sci_digits, double v);
/// fmt_sig() appended to `out` (for files of many numbers).
void append_fmt_sig(std::string& out, int width, int digits, int sci_digits, double v);

/// Fortran Fw.d (`f10.1`): fixed with `decimals` decimals; leading zero dropped if needed to fit.
std::string fortran_f(double v, int width, int decimals);

/// Fortran Ew.d (`0.1000E-03`): mantissa in [0.1, 1) with `decimals` digits, exponent 2 digits
/// (3 digits without the letter E when |exponent| > 99).
std::string fortran_e(double v, int width, int decimals);

/// Fortran Gw.d (`g12.4`: `0.4200    `, `200.0    `, `0.1000E-03`): fixed F(w-4).(d-s) plus four
/// blanks when 0.1 <= |v| < 10^d after rounding to d significant digits, else Ew.d.
std::string fortran_g(double v, int width, int decimals);
/// fortran_g() appended to `out` (no string of its own: for files of many numbers).
void append_fortran_g(std::string& out, double v, int width, int decimals);

/// Fortran Iw: right-aligned integer.
std::string fortran_i(long long v, int width);

/// Returns `v`, or 0 when |v| < threshold (CONTACT's filt_sml: values dominated by noise).
double filter_small(double v, double threshold);

}  // namespace rollcontact::format
