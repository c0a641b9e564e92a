#pragma once
// Writer of one module-1 (wheel/rail) case of a CONTACT .inp file (spec/inp-format.md §5), every
// value explicit: the way back from TOML case files for wheel/rail cases (inp_writer.hpp).

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "format/inp/wheelrail_record.hpp"

namespace rollcontact::format {

/// A file the .inp text names and the writer makes: a profile given as points (TOML `points`)
/// has no file of its own, so it is written as a plain table beside the .inp file.
struct CompanionFile {
  std::string name;  ///< as the .inp names it, relative to its folder
  std::string text;
};

/// The companion files of one .inp text: one per distinct table of points (profiles without a
/// file; equal points in several cases share one), named
/// `<stem>_rail<k>.txt` / `<stem>_wheel<k>.txt`.
class CompanionFiles {
 public:
  explicit CompanionFiles(std::string stem) : stem_(std::move(stem)) {}

  /// The name of the table holding `profile` (canonical points, z downwards), made once.
  const std::string& table_for(const Profile& profile, bool is_wheel);
  const std::vector<CompanionFile>& files() const noexcept { return files_; }

 private:
  std::string stem_;
  std::map<const Profile*, std::size_t> made_;  ///< profile -> index into files_
  std::map<std::string, std::size_t> by_text_;  ///< table text -> index into files_
  std::vector<CompanionFile> files_;
  int rails_ = 0, wheels_ = 0;
};

/// Appends the control words and lines of `r` (not its module line) to `out`. Profile files are
/// named relative to `base_dir` (the folder of the .inp file; empty: as resolved). Throws
/// rollcontact::Error for what the .inp language cannot express (a file name with a quote, a
/// non-finite value).
void write_wheelrail_case(std::string& out, const WheelRailRecord& r,
                          const std::filesystem::path& base_dir, CompanionFiles& companions);

}  // namespace rollcontact::format
