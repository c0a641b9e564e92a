#pragma once
// Subcommands of the rollcontact CLI. Each add_*_command registers its options on `app` and
// returns the function main() calls when that subcommand was given; it returns the exit status.
//
// Exit status: 0 all cases solved and converged; 1 some case failed (not supported, inadmissible
// data, no convergence) or a validation comparison failed; 2 the input could not be read (nothing
// written); 3 internal error.

#include <CLI/CLI.hpp>
#include <functional>

#include "batch/distribution.hpp"

namespace rollcontact::cli {

inline constexpr int exit_ok = 0;
inline constexpr int exit_case_failed = 1;
inline constexpr int exit_input_error = 2;
inline constexpr int exit_internal = 3;

using CommandRunner = std::function<int()>;

/// `rollcontact run FILE.inp`: solve and write FILE.out / FILE.json; under mpirun the
/// sequences (result elements) are spread over the processes of `distribution`.
CommandRunner add_run_command(CLI::App& app, batch::Distribution& distribution);
/// `rollcontact example`: the built-in default example.
CommandRunner add_example_command(CLI::App& app);
/// `rollcontact convert IN OUT`: .inp <-> TOML case file (direction from the extensions).
CommandRunner add_convert_command(CLI::App& app);
/// `rollcontact validate DIR`: run the examples of DIR and compare with CONTACT's .ref_out.
CommandRunner add_validate_command(CLI::App& app);
/// `rollcontact plot FILE --what ... -o FIG.png`: plots through the Python package.
CommandRunner add_plot_command(CLI::App& app);
/// `rollcontact table -o FILE.csv`: the 3220-case creep-force table (Vollebregt et al. 2012),
/// over the processes of `distribution` (several under mpirun).
CommandRunner add_table_command(CLI::App& app, batch::Distribution& distribution);

/// `rollcontact dynamic CASE -o RUN.csv`: a wheel under a sprung mass rolling along the rail,
/// integrated in time with the contact solved at every step.
CommandRunner add_dynamic_command(CLI::App& app);

/// `rollcontact lookup -o FILE.h5`: a creep-force lookup table for MBS codes (HDF5); `--table
/// FILE --at ...` evaluates one.
CommandRunner add_lookup_command(CLI::App& app, batch::Distribution& distribution);

/// `rollcontact fe-advice`: contact time steps, stability and pressure error of explicit-FE
/// penalty contact per penalty factor (docs/fe-advice.md).
CommandRunner add_fe_advice_command(CLI::App& app);

}  // namespace rollcontact::cli
