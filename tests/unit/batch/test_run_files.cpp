#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "batch/run_files.hpp"
#include "format/report/json_writer.hpp"
#include "format/report/report_writer.hpp"
#include "support/files.hpp"

namespace rollcontact::batch {
namespace {

namespace fs = std::filesystem;

/// Cases with what the serializer indents or escapes: nested objects and arrays, empty
/// containers, a message with a newline and quotes, non-ASCII text, numbers of every kind.
std::vector<CaseOutput> sample_cases() {
  std::vector<CaseOutput> cases(4);
  cases[0].report = "\n Case     1\n";
  cases[0].json = nlohmann::json{
      {"case", 1},
      {"force_tr", {-16.68, 37.77, 10000.0}},
      {"patches", {{{"fn", 9996.9}, {"grid", {{"mx", 24}, {"my", 40}}}}}},
      {"message", ""}}.dump(2);
  cases[1].report = " (R = 3: read, not solved)\n";  // no results entry
  cases[2].report = "\n Case     3\n error\n";
  cases[2].json = nlohmann::json{{"case", 3},
                                 {"status", "error"},
                                 {"message", "line 1\n\"quoted\" — ä"},
                                 {"patches", nlohmann::json::array()},
                                 {"extra", nlohmann::json::object()}}
                      .dump(2);
  cases[2].failed = 1;
  cases[3].json = nlohmann::json{{"case", 4}, {"values", {1e-300, -0.0, 3}}}.dump(2);
  return cases;
}

std::string expected_report(const std::vector<CaseOutput>& cases) {
  std::ostringstream os;
  format::write_report_banner(os);
  for (const CaseOutput& c : cases) os << c.report;
  format::write_report_end(os);
  return os.str();
}

std::string expected_json(const std::vector<CaseOutput>& cases, const std::string& name) {
  nlohmann::json all = nlohmann::json::array();
  for (const CaseOutput& c : cases)
    if (!c.json.empty()) all.push_back(nlohmann::json::parse(c.json));
  return format::results_document(name, std::move(all)).dump(2) + "\n";
}

TEST(RunFiles, CaseByCaseEqualsTheWholeDocument) {
  const test_support::ScratchDir scratch("rollcontact_run_files");
  const std::vector<CaseOutput> all = sample_cases();
  for (std::size_t n = 0; n <= all.size(); ++n) {
    const std::vector<CaseOutput> cases(all.begin(), all.begin() + static_cast<long>(n));
    const std::string name = "sweep \"" + std::to_string(n) + "\".inp";
    RunFilesWriter files(scratch / "run", name);
    for (const CaseOutput& c : cases) files.add(c);
    files.finish();
    EXPECT_EQ(test_support::file_text(files.report_path()), expected_report(cases)) << n;
    EXPECT_EQ(test_support::file_text(files.json_path()), expected_json(cases, name)) << n;
  }
}

TEST(RunFiles, NothingAppearsBeforeTheRunFinishes) {
  const test_support::ScratchDir scratch("rollcontact_run_files_abort");
  {
    RunFilesWriter files(scratch / "run", "x.inp");
    files.add(sample_cases()[0]);
    EXPECT_FALSE(fs::exists(scratch / "run.out"));
    EXPECT_FALSE(fs::exists(scratch / "run.json"));
  }  // destroyed unfinished, as when a run throws
  EXPECT_EQ(std::distance(fs::directory_iterator(scratch.path()), fs::directory_iterator()), 0);
}

}  // namespace
}  // namespace rollcontact::batch
