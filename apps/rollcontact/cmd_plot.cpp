// `rollcontact plot FILE --what ... -o FIG.png`: the plots of the Python package, from the
// command line. The CLI runs Debian's Python (or $ROLLCONTACT_PYTHON) on `-m rollcontact plot`
// with the package found next to this executable: <bin>/../python in a build tree,
// <bin>/../lib/python3/dist-packages when installed.

#include <fmt/format.h>
#include <spawn.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "commands.hpp"
#include "rollcontact/errors.hpp"

extern char** environ;

namespace rollcontact::cli {

namespace {

struct PlotSettings {
  std::string input;
  std::string what;
  std::string output;
  int case_number = 1;
  int patch = 1;
};

/// The folder holding the `rollcontact` package, or empty.
std::filesystem::path package_folder() {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path bin = fs::read_symlink("/proc/self/exe", ec).parent_path();
  for (const fs::path& candidate :
       {bin / ".." / "python", bin / ".." / "lib" / "python3" / "dist-packages"})
    if (fs::exists(candidate / "rollcontact" / "__init__.py", ec)) return fs::canonical(candidate);
  return {};
}

int plot(const PlotSettings& s) {
  const std::filesystem::path package = package_folder();
  if (package.empty())
    throw Error(
        "plot needs the Python package rollcontact next to this program (built with "
        "python3-dev and pybind11-dev; see docs/python.md)");
  const char* python_env = std::getenv("ROLLCONTACT_PYTHON");
  const std::string python = python_env != nullptr ? python_env : "/usr/bin/python3";
  std::vector<std::string> args = {python,
                                   "-m",
                                   "rollcontact",
                                   "plot",
                                   s.input,
                                   "--what",
                                   s.what,
                                   "--case",
                                   std::to_string(s.case_number),
                                   "--patch",
                                   std::to_string(s.patch),
                                   "-o",
                                   s.output};
  const char* old_path = std::getenv("PYTHONPATH");
  const std::string python_path =
      "PYTHONPATH=" + package.string() + (old_path != nullptr ? std::string(":") + old_path : "");
  std::vector<std::string> env_strings = {python_path, "MPLBACKEND=Agg"};
  for (char** e = environ; *e != nullptr; ++e) {
    const std::string entry(*e);
    if (entry.rfind("PYTHONPATH=", 0) != 0 && entry.rfind("MPLBACKEND=", 0) != 0)
      env_strings.push_back(entry);
  }
  std::vector<char*> argv, envp;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  for (auto& e : env_strings) envp.push_back(e.data());
  envp.push_back(nullptr);
  pid_t pid = 0;
  if (posix_spawn(&pid, python.c_str(), nullptr, nullptr, argv.data(), envp.data()) != 0)
    throw Error(
        fmt::format("cannot start {} (set ROLLCONTACT_PYTHON to Python 3 with NumPy "
                    "and matplotlib)",
                    python));
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : exit_internal;
}

}  // namespace

CommandRunner add_plot_command(CLI::App& app) {
  auto settings = std::make_shared<PlotSettings>();
  auto* cmd = app.add_subcommand(
      "plot",
      "Solve FILE (.inp, .toml, or the .json a run wrote) and plot one result as an image: "
      "pressure, traction, slip (with the adhesion/slip boundary), the creep-force curve of "
      "the file's cases or a wheel/rail case's profiles with its contact patches, or the history "
      "of `rollcontact dynamic` (FILE.csv, --what dynamic) (uses the Python package; "
      "docs/python.md)");
  cmd->add_option("FILE", settings->input,
                  "input file (.inp, .toml), a run's .json, or a dynamic run's .csv")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--what", settings->what, "what to plot")
      ->required()
      ->check(
          CLI::IsMember({"pressure", "traction", "slip", "creep-curve", "profiles", "dynamic"}));
  cmd->add_option("--case", settings->case_number, "case number (default 1)");
  cmd->add_option("--patch", settings->patch, "wheel/rail patch (module 1, default 1)");
  cmd->add_option("-o,--output", settings->output, "image file (.png, .pdf, .svg)")->required();
  return [settings] { return plot(*settings); };
}

}  // namespace rollcontact::cli
