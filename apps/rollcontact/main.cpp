// rollcontact command-line interface: subcommands live in cmd_*.cpp (see commands.hpp).

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <string>
#include <utility>
#include <vector>

#include "commands.hpp"
#include "rollcontact/errors.hpp"
#include "rollcontact/version.hpp"

int main(int argc, char** argv) {
  using namespace rollcontact::cli;
  CLI::App app{
      "rollcontact: rolling and sliding contact between elastic bodies (CONTACT-compatible, "
      "Kalker's exact half-space theory)"};
  app.set_version_flag("--version", std::string("rollcontact ") + rollcontact::version_string);
  app.require_subcommand(1);
  app.footer(
      "Exit status: 0 success; 1 a case failed (not supported, inadmissible, not converged) or a "
      "comparison failed; 2 unreadable input or bad command line (nothing written); 3 internal "
      "error.");

  std::vector<std::pair<CLI::App*, CommandRunner>> commands;
  auto add = [&](CommandRunner (*adder)(CLI::App&)) {
    CommandRunner runner = adder(app);
    commands.emplace_back(app.get_subcommands({}).back(), std::move(runner));
  };
  add(add_run_command);
  add(add_example_command);
  add(add_convert_command);
  add(add_validate_command);
  add(add_table_command);
  add(add_plot_command);

  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {  // --help, --version
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // CLI11's own codes (105 for a missing file …) would contradict the documented statuses.
    app.exit(e);
    return exit_input_error;
  }

  try {
    for (auto& [cmd, runner] : commands)
      if (cmd->parsed()) return runner();
  } catch (const rollcontact::InputError& e) {
    fmt::print(stderr, "rollcontact: error: {}\n", e.what());
    return exit_input_error;
  } catch (const rollcontact::Error& e) {
    fmt::print(stderr, "rollcontact: error: {}\n", e.what());
    return exit_case_failed;
  } catch (const std::exception& e) {
    fmt::print(stderr, "rollcontact: internal error: {}\n", e.what());
    return exit_internal;
  }
  return exit_ok;
}
