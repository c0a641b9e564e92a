#include "format/inp/inp_control.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

namespace rollcontact::format {

void decode_word3(int v3, ControlDigits& d) {
  d.x = digit_of(v3, 7);
  d.h = digit_of(v3, 6);
  d.g = digit_of(v3, 5);
  d.i = digit_of(v3, 4);
  d.a = digit_of(v3, 3);
  d.o = digit_of(v3, 2);
  d.w = digit_of(v3, 1);
  d.r = digit_of(v3, 0);
}

DebugDigits decode_debug_word(const GroupValues& w4) {
  const int v4 = w4.integer(0);
  DebugDigits g;
  g.p = digit_of(v4, 6);
  g.s = digit_of(v4, 5);
  g.f = digit_of(v4, 4);
  g.l = digit_of(v4, 3);
  g.c = digit_of(v4, 2);
  g.i = digit_of(v4, 1);
  g.n = digit_of(v4, 0);
  if (w4.has(1)) g.readln = w4.integer(1);
  return g;
}

namespace {

/// Reads one control word (with an optional second integer) and checks its digit count.
GroupValues read_word(InpStream& in, std::string_view name, int max_digits, bool with_second,
                      std::string_view second_name) {
  const GroupValues g = with_second
                            ? in.read_group({{name, FieldKind::digits},
                                             {second_name, FieldKind::integer, /*optional=*/true}},
                                            "the control words")
                            : in.read_group({{name, FieldKind::digits}}, "the control words");
  const int value = g.integer(0);
  if (value < 0) {
    in.fail(g.line(0), fmt::format("{} must be a non-negative integer", name),
            std::to_string(value));
  }
  int limit = 1;
  for (int k = 0; k < max_digits; ++k) limit *= 10;
  if (value >= limit) {
    in.fail(g.line(0), fmt::format("{} has more than {} digits", name, max_digits),
            std::to_string(value));
  }
  return g;
}

std::string describe(const std::vector<int>& allowed) {
  bool contiguous = true;
  for (std::size_t k = 1; k < allowed.size(); ++k) contiguous &= allowed[k] == allowed[k - 1] + 1;
  if (contiguous && allowed.size() > 2)
    return fmt::format("{}..{}", allowed.front(), allowed.back());
  return fmt::format("{}", fmt::join(allowed, ", "));
}

void check_digit(InpStream& in, int line, std::string_view name, int value,
                 const std::vector<int>& allowed) {
  if (std::find(allowed.begin(), allowed.end(), value) == allowed.end()) {
    in.fail(line,
            fmt::format("digit {}={} is not a valid value ({})", name, value, describe(allowed)));
  }
}

std::vector<int> range(int lo, int hi) {
  std::vector<int> v;
  for (int k = lo; k <= hi; ++k) v.push_back(k);
  return v;
}

/// Digits P B T N F S of control word 1 (same places in both modules).
void decode_pbtnfs(int v1, ControlDigits& d) {
  d.p = digit_of(v1, 5);
  d.b = digit_of(v1, 4);
  d.t = digit_of(v1, 3);
  d.n = digit_of(v1, 2);
  d.f = digit_of(v1, 1);
  d.s = digit_of(v1, 0);
}

/// Digits V L D C M Z E of control word 2 (same places in both modules).
void decode_vldcmze(int v2, ControlDigits& d) {
  d.v = digit_of(v2, 6);
  d.l = digit_of(v2, 5);
  d.d = digit_of(v2, 4);
  d.c = digit_of(v2, 3);
  d.m = digit_of(v2, 2);
  d.z = digit_of(v2, 1);
  d.e = digit_of(v2, 0);
}

/// L=5 exists in CONTACT's library only; the message says so instead of "not a valid value".
void reject_polach(InpStream& in, int line, const ControlDigits& d) {
  if (d.l == 5) {
    in.fail(line,
            "digit L=5 (Polach friction) is only available through the library interface, not in "
            ".inp files");
  }
}

/// The optional second integer of word 2, 10*GAPWGT + M2 (defaults: M2 = 1, GAPWGT = 0).
void decode_m2_gapwgt(InpStream& in, const GroupValues& w2, int line, ControlDigits& d) {
  d.m2 = 1;
  d.gapwgt = 0;
  if (!w2.has(1)) return;
  const int second = w2.integer(1);
  if (second < 0 || second > 12 || second % 10 > 2) {
    in.fail(line,
            "second integer of control word 2 (10*GAPWGT + M2) must have GAPWGT 0..1 and M2 0..2",
            std::to_string(second));
  }
  d.m2 = second % 10;
  d.gapwgt = second / 10;
}

/// Word 4 (X=1): debug levels P S F L C I N, optional READLN. No effect on results.
void read_debug_word(InpStream& in, ControlDigits& d, int& line) {
  d.debug = DebugDigits{};
  if (d.x != 1) return;
  const GroupValues w4 = read_word(in, "control word 4 (PSFLCIN)", 7, true, "READLN");
  line = w4.line(0);
  d.debug = decode_debug_word(w4);
}

}  // namespace

ControlWords read_control_words_module3(InpStream& in) {
  ControlWords out;
  ControlDigits& d = out.digits;

  // Word 1: (C) P B T N F S; a leading 7th digit C is accepted and ignored in module 3.
  const GroupValues w1 = read_word(in, "control word 1 (PBTNFS)", 7, false, {});
  const int l1 = out.lines[0] = w1.line(0);
  decode_pbtnfs(w1.integer(0), d);
  check_digit(in, l1, "P", d.p, range(0, 3));
  check_digit(in, l1, "B", d.b, range(0, 6));
  check_digit(in, l1, "T", d.t, range(0, 3));
  check_digit(in, l1, "N", d.n, range(0, 1));
  check_digit(in, l1, "F", d.f, range(0, 2));
  check_digit(in, l1, "S", d.s, range(0, 3));

  // Word 2: (V) L D C M Z E, optional 10*GAPWGT + M2.
  const GroupValues w2 = read_word(in, "control word 2 (LDCMZE)", 7, true, "M2");
  const int l2 = out.lines[1] = w2.line(0);
  decode_vldcmze(w2.integer(0), d);
  check_digit(in, l2, "V", d.v, {0, 3});
  reject_polach(in, l2, d);
  check_digit(in, l2, "L", d.l, {0, 1, 2, 3, 4, 6});
  check_digit(in, l2, "D", d.d, range(0, 2));
  check_digit(in, l2, "C", d.c, {0, 1, 2, 3, 4, 9});
  check_digit(in, l2, "M", d.m, range(0, 7));
  check_digit(in, l2, "Z", d.z, range(0, 2));
  check_digit(in, l2, "E", d.e, {0, 1, 2, 3, 9});
  decode_m2_gapwgt(in, w2, l2, d);

  // Word 3: X H G I A O W R.
  const GroupValues w3 = read_word(in, "control word 3 (XHGIAOWR)", 8, false, {});
  const int l3 = out.lines[2] = w3.line(0);
  decode_word3(w3.integer(0), d);
  check_digit(in, l3, "X", d.x, range(0, 1));
  check_digit(in, l3, "H", d.h, {0, 1, 3});
  check_digit(in, l3, "G", d.g, range(0, 5));
  check_digit(in, l3, "I", d.i, range(0, 3));
  check_digit(in, l3, "A", d.a, range(0, 2));
  check_digit(in, l3, "O", d.o, range(0, 5));
  check_digit(in, l3, "R", d.r, range(0, 3));

  read_debug_word(in, d, out.lines[3]);
  return out;
}

Module1Words read_control_words_module1(InpStream& in) {
  Module1Words out;
  ControlDigits& d = out.digits;

  // Word 1: C1 P B T N F S (C1: the configuration, track or roller rig, left or right).
  const GroupValues w1 = read_word(in, "control word 1 (CPBTNFS)", 7, false, {});
  const int l1 = out.lines[0] = w1.line(0);
  out.config = digit_of(w1.integer(0), 6);
  decode_pbtnfs(w1.integer(0), d);
  check_digit(in, l1, "C1", out.config, {0, 1, 4, 5});
  check_digit(in, l1, "P", d.p, range(0, 3));
  check_digit(in, l1, "B", d.b, {0, 1, 5, 6});
  check_digit(in, l1, "T", d.t, range(0, 3));
  check_digit(in, l1, "N", d.n, range(0, 1));
  check_digit(in, l1, "F", d.f, range(0, 3));  // 2: MY_WS (docs/decisions.md)
  check_digit(in, l1, "S", d.s, range(0, 3));

  // Word 2: V L D C M Z E, optional 10*GAPWGT + M2.
  const GroupValues w2 = read_word(in, "control word 2 (VLDCMZE)", 7, true, "M2");
  const int l2 = out.lines[1] = w2.line(0);
  decode_vldcmze(w2.integer(0), d);
  check_digit(in, l2, "V", d.v, range(0, 2));
  reject_polach(in, l2, d);
  check_digit(in, l2, "L", d.l, {0, 1, 2, 3, 4, 6});
  check_digit(in, l2, "C", d.c, range(0, 4));
  check_digit(in, l2, "M", d.m, range(0, 7));
  check_digit(in, l2, "Z", d.z, range(0, 3));
  check_digit(in, l2, "E", d.e, range(0, 5));
  decode_m2_gapwgt(in, w2, l2, d);

  // Word 3: X H G I A O W R.
  const GroupValues w3 = read_word(in, "control word 3 (XHGIAOWR)", 8, false, {});
  const int l3 = out.lines[2] = w3.line(0);
  decode_word3(w3.integer(0), d);
  check_digit(in, l3, "X", d.x, range(0, 1));
  check_digit(in, l3, "H", d.h, {0, 1, 3});
  check_digit(in, l3, "G", d.g, range(0, 5));
  check_digit(in, l3, "I", d.i, range(0, 3));
  check_digit(in, l3, "A", d.a, range(0, 2));
  check_digit(in, l3, "O", d.o, range(0, 5));
  check_digit(in, l3, "R", d.r, range(0, 3));

  read_debug_word(in, d, out.lines[3]);
  return out;
}

}  // namespace rollcontact::format
