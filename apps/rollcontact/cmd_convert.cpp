// `rollcontact convert`: CONTACT .inp <-> TOML case files (docs/case-files.md).

#include <fmt/format.h>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "batch/run_input.hpp"
#include "commands.hpp"
#include "format/inp/inp_reader.hpp"
#include "format/inp/inp_writer.hpp"
#include "format/inp/to_wheelrail.hpp"
#include "format/toml/toml_case_reader.hpp"
#include "format/toml/toml_case_writer.hpp"
#include "rollcontact/errors.hpp"

namespace rollcontact::cli {

namespace {

struct ConvertSettings {
  std::string input;
  std::string output;
  bool quiet = false;
};

bool is_toml(const std::filesystem::path& p) {
  return p.extension() == ".toml";
}

int report(const ConvertSettings& s, const std::filesystem::path& in,
           const std::filesystem::path& out, std::size_t count,
           const std::vector<format::CaseRecord>& problems);

/// The case records whose warnings report() prints (a wheel/rail case's identity record).
std::vector<format::CaseRecord> identities_of(const std::vector<format::InputCase>& cases) {
  std::vector<format::CaseRecord> identities;
  for (const auto& c : cases)
    identities.push_back(std::holds_alternative<format::CaseRecord>(c)
                             ? std::get<format::CaseRecord>(c)
                             : format::identity_record(std::get<format::WheelRailRecord>(c)));
  return identities;
}

/// The output must not be a file the cases read (a profile, an influence file): it would be
/// replaced by the converted cases.
void refuse_replacing_read_files(const ConvertSettings& s, const std::filesystem::path& out,
                                 const std::vector<format::InputCase>& cases) {
  std::error_code ec;
  if (!std::filesystem::exists(out, ec)) return;
  for (const std::filesystem::path& file : batch::files_read_by(cases)) {
    if (std::filesystem::equivalent(file, out, ec)) {
      throw InputError(s.output, 0,
                       fmt::format("is the file {} that the cases read; the output never "
                                   "replaces an input",
                                   file.string()));
    }
  }
}

int convert(const ConvertSettings& s) {
  const std::filesystem::path in(s.input);
  const std::filesystem::path out(s.output);
  if (is_toml(in) == is_toml(out)) {
    throw InputError(s.output, 0,
                     "convert needs one .toml and one .inp file (e.g. convert case.inp "
                     "case.toml, or convert case.toml case.inp)");
  }
  std::error_code ec;
  if (std::filesystem::exists(out, ec) && std::filesystem::equivalent(in, out, ec)) {
    throw InputError(s.output, 0,
                     fmt::format("is the input {} itself (a link to it); the output never "
                                 "replaces the input",
                                 s.input));
  }
  if (!is_toml(out)) {
    // TOML -> .inp: module-3 and wheel/rail cases (profiles given as points become tables
    // beside the .inp file).
    const std::vector<format::InputCase> cases = format::read_toml_input_file(in);
    refuse_replacing_read_files(s, out, cases);
    const auto tables = format::write_inp_input_file(out, cases);
    if (!s.quiet)
      for (const std::filesystem::path& t : tables)
        fmt::print("wrote the profile table {} (a profile given as points)\n", t.string());
    return report(s, in, out, cases.size(), identities_of(cases));
  }
  const std::vector<format::InputCase> cases = batch::read_input_file(in);
  refuse_replacing_read_files(s, out, cases);
  format::write_toml_input_file(out, cases);
  return report(s, in, out, cases.size(), identities_of(cases));
}

int report(const ConvertSettings& s, const std::filesystem::path& in,
           const std::filesystem::path& out, std::size_t count,
           const std::vector<format::CaseRecord>& problems) {
  if (!s.quiet) {
    fmt::print("converted {} case{} from {} to {}\n", count, count == 1 ? "" : "s", in.string(),
               out.string());
    // Overrides applied while reading change what the output says; the user should know.
    for (const format::CaseRecord& p : problems)
      for (const std::string& w : p.source.warnings)
        fmt::print(stderr, "rollcontact: warning: case {}: {}\n", p.case_number, w);
  }
  return exit_ok;
}

}  // namespace

CommandRunner add_convert_command(CLI::App& app) {
  auto settings = std::make_shared<ConvertSettings>();
  auto* cmd = app.add_subcommand(
      "convert",
      "Convert a CONTACT .inp file to a TOML case file or back (direction from the extensions; "
      "see docs/case-files.md)");
  cmd->add_option("INPUT", settings->input, "input file (.inp or .toml)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("OUTPUT", settings->output, "output file (.toml or .inp)")->required();
  cmd->add_flag("-q,--quiet", settings->quiet, "no console output");
  return [settings] { return convert(*settings); };
}

}  // namespace rollcontact::cli
