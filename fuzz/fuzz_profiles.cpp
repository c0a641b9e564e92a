// libFuzzer harness: the profile parsers (SIMPACK, Miniprof, plain table) and the clean-up of
// spec §8.3 on what they accept, rail and wheel. The first input byte picks the variant.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "format/profiles/profile_points.hpp"
#include "format/profiles/profile_simpack.hpp"
#include "format/profiles/profile_table.hpp"
#include "rollcontact/errors.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace rollcontact;
  if (size == 0) return 0;
  const unsigned variant = data[0];
  const std::string_view text(reinterpret_cast<const char*>(data + 1), size - 1);
  const bool wheel = (variant & 1u) != 0;
  std::vector<std::string> warnings;
  try {
    format::RawProfile raw;
    switch ((variant >> 1) % 3) {
      case 0:
        raw = format::parse_simpack_profile(text, "fuzz.prr", wheel, warnings);
        break;
      case 1:
        raw = format::parse_table_profile(text, "fuzz.ban", true, warnings);
        break;
      default:
        raw = format::parse_table_profile(text, "fuzz.txt", false, warnings);
        break;
    }
    format::ProfileOptions options;
    options.is_wheel = wheel;
    options.mirror_y = (variant >> 3) & 1u;
    options.mirror_z = static_cast<int>((variant >> 4) % 3) - 1;
    (void)format::finish_profile(std::move(raw), options, warnings);
  } catch (const Error&) {
  }
  return 0;
}
