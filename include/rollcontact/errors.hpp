#pragma once
// Exceptions thrown by the rollcontact library. Everything derives from rollcontact::Error, and
// every exception type carries the error code that a C interface returns for it (CONTACT's codes,
// spec/library-api.md §3.5), so that the C layer never has to guess.

#include <stdexcept>
#include <string>

namespace rollcontact {

/// Error codes as CONTACT's library returns them (spec/library-api.md §3.5). 0 is success.
enum class ErrorCode : int {
  Ok = 0,
  Search = -25,          ///< CNTC_err_search: contact search failed
  TotalForce = -26,      ///< CNTC_err_ftot: total-force iteration failed
  Normal = -27,          ///< CNTC_err_norm: normal problem did not converge
  Tangential = -28,      ///< CNTC_err_tang: tangential problem did not converge
  Tolerance = -29,       ///< CNTC_err_tol: stopped with the residual above the tolerance
  Patch = -31,           ///< CNTC_err_icp: invalid result element / contact patch
  Profile = -32,         ///< CNTC_err_profil: profile read or processing error
  Friction = -33,        ///< CNTC_err_frclaw: invalid or missing friction data
  Discretisation = -34,  ///< CNTC_err_discr: invalid discretisation
  Input = -39,           ///< CNTC_err_input: input file error
  Other = -99,           ///< CNTC_err_other: unspecified
};

/// Base class of all rollcontact exceptions.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
  /// The code a C interface returns for this error.
  virtual ErrorCode code() const noexcept { return ErrorCode::Other; }
};

/// Bad input: carries the file, 1-based line (0 = unknown) and the offending text.
/// what() reads "file:line: message" so a user can jump to the place.
class InputError : public Error {
 public:
  InputError(std::string file, int line, std::string message, std::string offending = {})
      : Error(compose(file, line, message, offending)),
        file_(std::move(file)),
        line_(line),
        message_(std::move(message)),
        offending_(std::move(offending)) {}

  const std::string& file() const noexcept { return file_; }
  int line() const noexcept { return line_; }
  const std::string& message() const noexcept { return message_; }
  const std::string& offending() const noexcept { return offending_; }
  ErrorCode code() const noexcept override { return ErrorCode::Input; }

 private:
  static std::string compose(const std::string& file, int line, const std::string& message,
                             const std::string& offending) {
    // Built with append() only: GCC 12 reports a false -Wrestrict for chained operator+ here.
    std::string s;
    s.append(file.empty() ? std::string("<input>") : file);
    if (line > 0) s.append(":").append(std::to_string(line));
    s.append(": ").append(message);
    if (!offending.empty()) s.append(" (found '").append(printable(offending)).append("')");
    return s;
  }
  /// The offending text with control bytes (NUL, escape sequences of a binary file) written as
  /// \xNN, so that a message never carries them to a terminal or a log.
  static std::string printable(const std::string& text) {
    static constexpr char kHex[] = "0123456789ABCDEF";
    std::string out;
    for (const char c : text) {
      const auto u = static_cast<unsigned char>(c);
      if (u < 0x20 || u == 0x7F) {
        out.append("\\x").push_back(kHex[u >> 4]);
        out.push_back(kHex[u & 0xF]);
      } else {
        out.push_back(c);
      }
    }
    return out;
  }
  std::string file_;
  int line_;
  std::string message_;
  std::string offending_;
};

/// A physically or numerically inadmissible problem detected after parsing
/// (e.g. all elements excluded, non-positive modulus given through the API).
class ProblemError : public Error {
 public:
  using Error::Error;
  ErrorCode code() const noexcept override { return ErrorCode::Other; }
};

/// The potential contact area or the undeformed distance is inadmissible (no element left, a
/// grid too large or too fine, inconsistent geometry data).
class GeometryError : public ProblemError {
 public:
  using ProblemError::ProblemError;
  ErrorCode code() const noexcept override { return ErrorCode::Discretisation; }
};

/// A value of a model::PatchProblem that no solver can use (not finite, out of its physical
/// range). field() names it as in the model ("normal.force_N"); what() reads
/// "normal.force_N = inf: must be a finite number". Front ends add the file, line and case.
class InvalidValueError : public ProblemError {
 public:
  InvalidValueError(std::string field, const std::string& message)
      : ProblemError(field + message), field_(std::move(field)) {}
  const std::string& field() const noexcept { return field_; }
  ErrorCode code() const noexcept override { return ErrorCode::Input; }

 private:
  std::string field_;
};

/// A solver failed to converge and the caller asked for strictness.
class SolverError : public Error {
 public:
  using Error::Error;
  ErrorCode code() const noexcept override { return ErrorCode::Tolerance; }
};

/// A feature that exists in CONTACT but is not implemented (yet) in rollcontact.
class NotSupportedError : public Error {
 public:
  using Error::Error;
};

/// A feature implemented but known to give results that differ from CONTACT's reference
/// outputs, refused because the problem asked for validated results only
/// (model::WheelRailProblem::validated_only); solved with a warning on request.
class NotValidatedError : public NotSupportedError {
 public:
  using NotSupportedError::NotSupportedError;
};

}  // namespace rollcontact
