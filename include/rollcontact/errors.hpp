#pragma once
// Exceptions thrown by the rollcontact library. Everything derives from rollcontact::Error.

#include <stdexcept>
#include <string>

namespace rollcontact {

/// Base class of all rollcontact exceptions.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
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

 private:
  static std::string compose(const std::string& file, int line, const std::string& message,
                             const std::string& offending) {
    // Built with append() only: GCC 12 reports a false -Wrestrict for chained operator+ here.
    std::string s;
    s.append(file.empty() ? std::string("<input>") : file);
    if (line > 0) s.append(":").append(std::to_string(line));
    s.append(": ").append(message);
    if (!offending.empty()) s.append(" (found '").append(offending).append("')");
    return s;
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
};

/// A solver failed to converge and the caller asked for strictness.
class SolverError : public Error {
 public:
  using Error::Error;
};

/// A feature that exists in CONTACT but is not implemented (yet) in rollcontact.
class NotSupportedError : public Error {
 public:
  using Error::Error;
};

}  // namespace rollcontact
