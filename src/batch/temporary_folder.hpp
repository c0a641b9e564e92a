#pragma once
// A new, empty folder in the system's temporary directory, for runs whose outputs nobody asked
// to keep in a named place (`rollcontact example`, validation without --keep).

#include <filesystem>
#include <string>

namespace rollcontact::batch {

/// Creates `<temp>/<prefix>-<random number>` and returns it; throws Error when none can be made.
std::filesystem::path new_temporary_folder(const std::string& prefix);

}  // namespace rollcontact::batch
