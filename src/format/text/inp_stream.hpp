#pragma once
// Group and array reading over the lines of an .inp file (spec/inp-format.md §1, "Reading a
// group"). Shared by the module-1 and module-3 readers; every error is an InputError naming the
// file, the line and the offending word.

#include <cstddef>
#include <functional>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

namespace rollcontact::format {

/// Type of one value of a group.
/// integer: as CONTACT reads integers, integral reals included (`1.0`); digits: a digit-packed
/// control word, written as an integer only.
enum class FieldKind { integer, digits, real, angle, string, logical };

/// One field of a group: its name as in the manual (used in messages) and its type. Optional
/// fields must follow all mandatory ones.
struct FieldSpec {
  std::string_view name;
  FieldKind kind = FieldKind::real;
  bool optional = false;
};

/// Values of one group, in field order, with the line each value came from.
class GroupValues {
 public:
  struct Item {
    bool present = false;
    int integer = 0;
    double real = 0.0;
    bool logical = false;
    std::string text;
    int line = 0;
  };

  explicit GroupValues(std::vector<Item> items) : items_(std::move(items)) {}

  bool has(std::size_t i) const { return i < items_.size() && items_[i].present; }
  int integer(std::size_t i) const { return items_.at(i).integer; }
  double real(std::size_t i) const { return items_.at(i).real; }
  bool logical(std::size_t i) const { return items_.at(i).logical; }
  const std::string& text(std::size_t i) const { return items_.at(i).text; }
  /// Line of value i (for an absent optional value: the line of the last mandatory value).
  int line(std::size_t i) const { return items_.at(i).line; }

 private:
  std::vector<Item> items_;
};

/// Cursor over the lines of one input text. Each group or array starts on a fresh content line
/// and consumes whole lines: the rest of the line holding its last value is ignored.
class InpStream {
 public:
  InpStream(std::string_view text, std::string file_name);

  const std::string& file() const noexcept { return file_; }

  /// True when no line with words remains.
  bool at_end();
  /// Line number (1-based) of the next line with words, or of the last line at end of file.
  int next_line();
  /// Line number of the last line consumed by a group or array (0 before the first).
  int last_line() const noexcept { return last_line_; }
  /// Number of lines of the text (the line reported for "end of file" errors).
  int line_count() const noexcept { return static_cast<int>(lines_.size()); }

  /// Reads one group. `what` names the group in messages, e.g. "the IPOTCN=1 line".
  GroupValues read_group(std::initializer_list<FieldSpec> fields, std::string_view what);

  /// Fills an array of n reals (or angles where `is_angle(k)` is true) from as many lines as
  /// needed. `what` names the array in messages, e.g. "B(1..6) of the IBASE=1 block".
  std::vector<double> read_reals(std::size_t n, std::string_view what,
                                 const std::function<bool(std::size_t)>& is_angle = {});
  /// Fills an array of n integers.
  std::vector<int> read_integers(std::size_t n, std::string_view what);

  /// Throws InputError(file, line, message, offending).
  [[noreturn]] void fail(int line, std::string message, std::string offending = {}) const;

 private:
  /// Advances to the next line with words; returns false at end of text.
  bool skip_to_content();
  template <typename Parse>
  void fill_array(std::size_t n, std::string_view what, std::string_view kind_name, Parse parse);

  std::string file_;
  std::vector<std::string> lines_;
  std::size_t next_ = 0;  ///< index of the next unread line
  int last_line_ = 0;
  /// The last group whose values continued onto a later line (list-directed input allows it):
  /// a value missing on its first line shifts every value after it, and the error surfaces
  /// lines later, so the messages of errors shortly after it point back at it.
  struct SpannedGroup {
    int first_line = 0, last_line = 0;
    std::string what;
  } spanned_;
  /// Errors up to this many lines after a spanned group mention it.
  static constexpr int kSpannedHintLines = 5;
};

}  // namespace rollcontact::format
