#pragma once
// Control words of a case (spec/inp-format.md §3): decimal place-value decoding of the digit
// words and validation of each digit's admissible values.

#include <array>

#include "format/inp/case_record.hpp"
#include "format/text/inp_stream.hpp"

namespace rollcontact::format {

/// Digits of one case as read, with the line of each control word (0 for an absent word 4).
struct ControlWords {
  ControlDigits digits;
  std::array<int, 4> lines{};
};

/// Reads words 1-3 (and word 4 when X=1) of a module-3 case: PBTNFS, LDCMZE {10*GAPWGT+M2},
/// XHGIAOWR, PSFLCIN {READLN}. Throws InputError for words with too many digits and for digit
/// values outside their admissible sets.
ControlWords read_control_words_module3(InpStream& in);

/// Control words of a module-1 case: CPBTNFS, VLDCMZE {10*GAPWGT+M2}, XHGIAOWR and PSFLCIN
/// {READLN} when X=1, with C1 (the configuration) apart from the digits.
struct Module1Words {
  ControlDigits digits;
  int config = 0;
  std::array<int, 4> lines{};
};
Module1Words read_control_words_module1(InpStream& in);

/// Digits X H G I A O W R of control word 3 (same layout in both modules); unchecked.
void decode_word3(int v3, ControlDigits& d);

/// Debug print levels of control word 4 (`PSFLCIN {READLN}`), shared by both modules; they have
/// no effect on results.
DebugDigits decode_debug_word(const GroupValues& w4);

/// Decimal digit k (0 = rightmost) of a non-negative control word.
constexpr int digit_of(int word, int k) {
  for (int j = 0; j < k; ++j) word /= 10;
  return word % 10;
}

}  // namespace rollcontact::format
