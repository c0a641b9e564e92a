#pragma once
// The numerical influence coefficients file of C=9 (spec/inp-format.md §8.5): reading it into a
// model::InfluenceTable, and writing one (tests, and tables made by other programs).

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "rollcontact/model/influence_table.hpp"

namespace rollcontact::format {

/// The grid's element size [mm], when the case knows it before solving (IPOTCN > 0).
struct ElementSize {
  double dx_mm = 0.0, dy_mm = 0.0;
};

/// Parses the text of a coefficient file; `file_name` names it in messages. Throws InputError
/// (file, line) for an empty, truncated or malformed file, or when DXFILE, DYFILE differ from
/// `grid` by more than 1e-5 mm, and NotSupportedError for one matrix per grid row (NMATRIX > 1),
/// which the convolution products cannot represent.
model::InfluenceTable parse_influence_file(std::string_view text, const std::string& file_name,
                                           std::optional<ElementSize> grid = std::nullopt);

/// Reads and parses the file at `path` (InputError at line 0 when it cannot be read).
std::shared_ptr<const model::InfluenceTable> read_influence_file(
    const std::filesystem::path& path, std::optional<ElementSize> grid = std::nullopt);

/// The table in the file format (NMATRIX = 1, offsets IXOFS ≥ 0 only, as the format stores
/// them), numbers in their shortest form that reads back to the same double.
std::string format_influence_file(const model::InfluenceTable& table);

}  // namespace rollcontact::format
