// `rollcontact validate DIR`: solve every example of a folder that has a CONTACT reference report
// and compare (src/io/validation*.hpp).

#include <fcntl.h>
#include <fmt/format.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

#include "batch/validation.hpp"
#include "batch/validation_summary.hpp"
#include "commands.hpp"
#include "format/text/atomic_file.hpp"

namespace rollcontact::cli {

namespace {

struct ValidateSettings {
  std::string folder;
  int jobs = 1;
  std::string markdown;
  std::string keep;
  std::string backend = "default";
  bool verbose = false;
  bool quiet = false;
  bool in_process = false;
  bool unvalidated = false;
};

extern "C" char** environ;  // NOLINT: POSIX, passed on to the child

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
  return text;
}

/// Runs `rollcontact run FILE.inp -o OUT -q` as a child process of this very executable: a
/// crash or abort in one example then fails that example instead of the whole validation.
batch::ExampleRun run_in_child(const batch::ExampleFiles& example, const std::filesystem::path& out,
                               const std::string& backend, bool unvalidated) {
  batch::ExampleRun run;
  std::error_code ec;
  const auto self = std::filesystem::read_symlink("/proc/self/exe", ec);
  std::filesystem::create_directories(out, ec);
  if (self.empty()) {
    run.failure = "cannot locate the rollcontact executable (/proc/self/exe)";
    return run;
  }
  const auto log = out / (example.name + ".stderr");
  std::vector<std::string> args{
      self.string(), "run", example.input.string(), "-o", out.string(), "-q", "--fft", backend};
  if (unvalidated) args.emplace_back("--unvalidated");
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, log.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) {
    run.failure = std::string("cannot start rollcontact run: ") + std::strerror(spawned);
    return run;
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  const std::string messages = read_text(log);
  if (WIFSIGNALED(status)) {
    run.failure = fmt::format("rollcontact run crashed (signal {})", WTERMSIG(status));
  } else if (const int code = WEXITSTATUS(status); code == exit_input_error) {
    constexpr std::string_view prefix = "rollcontact: error: ";
    run.input_error = messages.rfind(prefix, 0) == 0 ? messages.substr(prefix.size()) : messages;
  } else if (code != exit_ok && code != exit_case_failed) {
    run.failure = fmt::format("rollcontact run exited with status {}: {}", code, messages);
  } else {
    run.report = out / (example.input.stem().string() + ".out");
    run.json = out / (example.input.stem().string() + ".json");
  }
  return run;
}

FftBackendKind backend_kind(const std::string& name) {
  if (name == "fftw") return FftBackendKind::Fftw;
  if (name == "kiss") return FftBackendKind::Kiss;
  return FftBackendKind::Default;
}

void print_progress(const batch::ExampleResult& r, std::size_t done, std::size_t total) {
  fmt::print(
      stderr, "[{:>2}/{}] {:<20} {:>4} cases: {} passed, {} failed, {} not supported ({:.1f} s)\n",
      done, total, r.name, r.cases.size(), r.count(batch::CaseStatus::Passed),
      r.count(batch::CaseStatus::Failed), r.count(batch::CaseStatus::NotSupported), r.seconds);
}

int run_validation(const ValidateSettings& s) {
  batch::ValidationOptions options;
  options.jobs = s.jobs;
  options.output_dir = s.keep;
  options.solve.fft = backend_kind(s.backend);
  options.solve_unvalidated = s.unvalidated;
  if (!s.in_process) {
    options.runner = [backend = s.backend, unvalidated = s.unvalidated](
                         const batch::ExampleFiles& e, const std::filesystem::path& out) {
      return run_in_child(e, out, backend, unvalidated);
    };
  }
  if (!s.quiet) options.on_example = print_progress;

  const auto results = batch::validate_folder(s.folder, options);

  if (s.verbose) {
    fmt::print("\n");
    for (const auto& r : results) fmt::print("{}\n", batch::format_case_details(r));
  }
  fmt::print("{}", batch::format_validation_table(results, batch::TableStyle::Text));
  fmt::print("{}", batch::format_case_reasons(results, batch::TableStyle::Text));
  const int compared = batch::compared_cases(results);
  fmt::print("compared {} case{} with the references of {} example{}{}\n", compared,
             compared == 1 ? "" : "s", results.size(), results.size() == 1 ? "" : "s",
             compared == 0 ? ": NOTHING COMPARED, which is a failure" : "");
  if (!s.markdown.empty())
    format::write_file_atomically(s.markdown, batch::format_validation_markdown(results, s.folder));
  return batch::any_failed(results) ? exit_case_failed : exit_ok;
}

}  // namespace

CommandRunner add_validate_command(CLI::App& app) {
  auto settings = std::make_shared<ValidateSettings>();
  auto* cmd = app.add_subcommand(
      "validate",
      "Run every .inp of DIR that has a CONTACT reference .ref_out and compare forces, approach, "
      "solved creepages, PMAX and element counts case by case; exit status 1 when a supported case "
      "differs");
  cmd->add_option("DIR", settings->folder, "folder with FILE.inp + FILE.ref_out pairs (read only)")
      ->required()
      ->check(CLI::ExistingDirectory);
  cmd->add_option("-j,--jobs", settings->jobs, "examples run concurrently")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->add_option("--output", settings->markdown, "also write the table as Markdown to FILE");
  cmd->add_option("--keep-outputs", settings->keep,
                  "write our reports (FILE.out, FILE.json) to this folder and keep them "
                  "(default: a temporary folder, removed afterwards)");
  cmd->add_option("--fft", settings->backend, "FFT backend")
      ->check(CLI::IsMember({"default", "fftw", "kiss"}))
      ->capture_default_str();
  cmd->add_flag("--in-process", settings->in_process,
                "solve in this process instead of one `rollcontact run` child process per example "
                "(for debugging; a crash then ends the validation)");
  cmd->add_flag("-v,--verbose", settings->verbose,
                "per-case details: every compared quantity, ours vs reference");
  cmd->add_flag("-q,--quiet", settings->quiet, "no progress lines on stderr");
  cmd->add_flag("--unvalidated", settings->unvalidated,
                "compare also the wheel/rail cases a plain run refuses as not yet validated "
                "(`rollcontact run --unvalidated`): where they stand");
  return [settings] { return run_validation(*settings); };
}

}  // namespace rollcontact::cli
