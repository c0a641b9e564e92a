#pragma once
// The reader of a wheel/rail (module 1) [[case]] of a TOML case file (docs/case-files.md,
// "Wheel/rail cases").

#include <string>

#include "format/inp/wheelrail_record.hpp"
#include "format/toml/toml_table.hpp"

namespace rollcontact::format::toml_input {

/// The case `c` (which has a [case.wheel_rail] table) as the .inp reader would give it; profile
/// files are read relative to ctx.base_dir. Throws InputError with file, line and key path.
WheelRailRecord read_wheelrail_case(Table& c, const Context& ctx, const std::string& file,
                                    int case_number);

}  // namespace rollcontact::format::toml_input
