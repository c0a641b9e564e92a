// libFuzzer harness: the .inp reader (modules 1 and 3) and, for every module-3 case it accepts,
// the adapter to the model and the model's validation. Anything but a rollcontact::Error
// escaping (or a sanitizer report, a hang, a leak) is a finding.

#include <cstddef>
#include <cstdint>
#include <string>
#include <variant>

#include "format/inp/inp_reader.hpp"
#include "format/inp/to_model.hpp"
#include "rollcontact/errors.hpp"
#include "rollcontact/model/validation.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace rollcontact;
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    // No base folder: profile and coefficient files named by the input are not found (errors).
    for (const format::InputCase& c : format::read_input_string(text, "fuzz.inp", {})) {
      const auto* record = std::get_if<format::CaseRecord>(&c);
      if (record == nullptr || !record->source.case_error.empty()) continue;
      try {
        model::validate(format::to_patch_problem(*record));
      } catch (const Error&) {
        // not supported or inadmissible: a clean rejection
      }
    }
  } catch (const Error&) {
    // a clean rejection with file and line
  }
  return 0;
}
