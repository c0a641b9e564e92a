#pragma once
// The report (.out) and results (.json) of a run, written case by case as the cases finish:
// a run of any length holds one case's outputs at a time, and the files appear (atomically)
// only when the run completes.

#include <filesystem>
#include <string>

#include "format/text/atomic_file.hpp"

namespace rollcontact::batch {

/// What one case adds to the run's files.
struct CaseOutput {
  std::string report;
  /// The case's entry of the results, as nlohmann::json::dump(2) writes it (text: a tenth of
  /// the memory of the JSON object while a run with threads holds its cases' outputs); empty:
  /// nothing for the results (R = 2, 3 cases).
  std::string json;
  int failed = 0;  ///< 1: an error or not converged
};

/// <stem>.out and <stem>.json of one run. The JSON is byte for byte
/// format::results_document(input_name, cases).dump(2) + "\n", without the document in memory.
class RunFilesWriter {
 public:
  /// Opens both files' temporary files; throws rollcontact::Error when they cannot be made.
  RunFilesWriter(const std::filesystem::path& output_stem, const std::string& input_name);

  /// Appends the next case (cases come in case order).
  void add(const CaseOutput& output);
  /// Writes the closing parts and puts both files in place.
  void finish();

  const std::filesystem::path& report_path() const noexcept { return report_.path(); }
  const std::filesystem::path& json_path() const noexcept { return json_.path(); }

 private:
  format::AtomicFileWriter report_, json_;
  std::string json_tail_;  ///< the document after the cases array's elements
  bool first_case_ = true;
};

}  // namespace rollcontact::batch
