#include "batch/run_files.hpp"

#include <nlohmann/json.hpp>
#include <sstream>

#include "format/report/json_writer.hpp"
#include "format/report/report_writer.hpp"
#include "rollcontact/errors.hpp"

namespace rollcontact::batch {

namespace {

std::filesystem::path with_extension(const std::filesystem::path& stem, const char* ext) {
  std::filesystem::path p = stem;
  p += ext;
  return p;
}

/// The cases array's place in the pretty-printed document: its elements are indented by two
/// levels (four spaces) under the top-level key.
constexpr std::string_view kEmptyCases = "\"cases\": []";
constexpr std::string_view kElementIndent = "    ";

}  // namespace

RunFilesWriter::RunFilesWriter(const std::filesystem::path& output_stem,
                               const std::string& input_name)
    : report_(with_extension(output_stem, ".out")), json_(with_extension(output_stem, ".json")) {
  std::ostringstream banner;
  format::write_report_banner(banner);
  report_.append(banner.str());
  // The document's frame as the serializer writes it (key order, indentation, escaping of
  // the input name), split where the cases go.
  const std::string frame =
      format::results_document(input_name, nlohmann::json::array()).dump(2) + "\n";
  const std::size_t at = frame.find(kEmptyCases);
  if (at == std::string::npos) throw Error("internal: results document without a cases array");
  const std::size_t open = at + kEmptyCases.size() - 1;  // the "]"
  json_.append(std::string_view(frame).substr(0, open));
  json_tail_ = frame.substr(open);
}

void RunFilesWriter::add(const CaseOutput& output) {
  report_.append(output.report);
  if (output.json.empty()) return;
  // dump(2) of the case alone, every line indented to its depth in the document.
  const std::string& text = output.json;
  std::string indented;
  indented.reserve(text.size() + text.size() / 8);
  indented += first_case_ ? "\n" : ",\n";
  indented += kElementIndent;
  for (const char c : text) {
    indented += c;
    if (c == '\n') indented += kElementIndent;
  }
  json_.append(indented);
  first_case_ = false;
}

void RunFilesWriter::finish() {
  std::ostringstream end;
  format::write_report_end(end);
  report_.append(end.str());
  if (!first_case_) json_.append("\n  ");  // a non-empty array closes on a line of its own
  json_.append(json_tail_);
  report_.commit();
  json_.commit();
}

}  // namespace rollcontact::batch
