// libFuzzer harness: the TOML case reader and, for every case it accepts, the adapter to the
// model and the model's validation.

#include <cstddef>
#include <cstdint>
#include <string>

#include "format/inp/to_model.hpp"
#include "format/toml/toml_case_reader.hpp"
#include "rollcontact/errors.hpp"
#include "rollcontact/model/validation.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace rollcontact;
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    for (const format::CaseRecord& record : format::read_toml_string(text, "fuzz.toml", {})) {
      if (!record.source.case_error.empty()) continue;
      try {
        model::validate(format::to_patch_problem(record));
      } catch (const Error&) {
      }
    }
  } catch (const Error&) {
  }
  return 0;
}
