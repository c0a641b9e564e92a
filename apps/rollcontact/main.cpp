// rollcontact command-line interface: subcommands live in cmd_*.cpp (see commands.hpp).

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "commands.hpp"
#include "heap_setup.hpp"
#include "process_distribution.hpp"
#include "rollcontact/errors.hpp"
#include "rollcontact/fft_plan_cache.hpp"
#include "rollcontact/version.hpp"

namespace {

/// Whether the parsed subcommand asks for FFTW_MEASURE plans.
bool fft_measure_requested(const CLI::App& app) {
  for (const CLI::App* cmd : app.get_subcommands()) {
    const CLI::Option* measure = cmd->get_option_no_throw("--fft-measure");
    if (measure != nullptr && measure->count() > 0) return true;
  }
  return false;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace rollcontact::cli;
  prepare_heap();
  // First: under mpirun this is MPI_Init (which may edit argc, argv); destroyed last.
  const auto distribution = make_process_distribution(argc, argv);
  const bool root = distribution->is_root();
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
  auto add = [&](CommandRunner runner) {
    commands.emplace_back(app.get_subcommands({}).back(), std::move(runner));
  };
  add(add_run_command(app, *distribution));
  add(add_example_command(app));
  add(add_convert_command(app));
  add(add_validate_command(app));
  add(add_table_command(app, *distribution));
  add(add_plot_command(app));
  add(add_lookup_command(app, *distribution));
  add(add_dynamic_command(app));
  add(add_fe_advice_command(app));

  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {  // --help, --version
    return root ? app.exit(e) : exit_ok;
  } catch (const CLI::ParseError& e) {
    // CLI11's own codes (105 for a missing file …) would contradict the documented statuses.
    if (root) app.exit(e);
    return exit_input_error;
  }

  // FFTW's plans from earlier processes (rollcontact/fft_plan_cache.hpp): a small case is planned
  // in microseconds instead of milliseconds. Not with --fft-measure, whose plans depend on timings.
  std::optional<rollcontact::FftPlanCache> wisdom;
  if (const auto dir = rollcontact::default_fft_plan_cache_dir();
      dir && !fft_measure_requested(app))
    wisdom.emplace(*dir);

  try {
    for (auto& [cmd, runner] : commands)
      if (cmd->parsed()) return runner();
  } catch (const rollcontact::InputError& e) {
    if (root) fmt::print(stderr, "rollcontact: error: {}\n", e.what());
    return exit_input_error;
  } catch (const rollcontact::Error& e) {
    if (root) fmt::print(stderr, "rollcontact: error: {}\n", e.what());
    return exit_case_failed;
  } catch (const std::exception& e) {
    // Every process reports: an internal error on one rank is not seen by the others.
    fmt::print(stderr, "rollcontact: internal error: {}\n", e.what());
    return exit_internal;
  }
  return exit_ok;
}
