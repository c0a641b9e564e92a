#pragma once
// Reading rail and wheel profile files for a model::WheelRailProblem built in C++
// (spec/inp-format.md §5.1, §8): SIMPACK (.prr, .prw), Miniprof (.ban, .whl) and plain tables,
// the format from the extension; the points come back cleaned up (double points removed) in
// CONTACT's canonical form: mm, z downwards, rail by ascending y, wheel by descending y.

#include <filesystem>
#include <string>
#include <vector>

#include "rollcontact/model/profile.hpp"

namespace rollcontact {

struct ProfileFileOptions {
  bool is_wheel = false;
  int mirror_y = 0;       ///< MIRRORY: 1 mirror y (combined with a SIMPACK file's own flag)
  int mirror_z = 0;       ///< MIRRORZ: 0 auto-detect (Miniprof, plain), -1 as is, 1 mirror z
  double scale_yz = 1.0;  ///< SCALEYZ: file units to mm (1000 for a file in metres)
};

/// Throws InputError naming the file and line for unreadable or malformed files, GeometryError
/// for a profile whose length is outside 5–500 mm (SCALEYZ or the file's units are probably
/// wrong). `warnings` (optional) receives one line per adjustment made.
Profile read_profile(const std::filesystem::path& path, const ProfileFileOptions& options,
                     std::vector<std::string>* warnings = nullptr);

}  // namespace rollcontact
