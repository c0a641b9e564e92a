// rollcontact command-line interface.
//
// Exit status: 0 all cases solved and converged; 1 some case failed (not supported, inadmissible
// data, no convergence); 2 the input could not be read (nothing written); 3 internal error.

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "io/atomic_file.hpp"
#include "io/builtin_example.hpp"
#include "io/report_writer.hpp"
#include "io/run_input.hpp"
#include "rollcontact/errors.hpp"
#include "rollcontact/version.hpp"

namespace {

using rollcontact::io::CaseOutcome;

constexpr int exit_ok = 0;
constexpr int exit_case_failed = 1;
constexpr int exit_input_error = 2;
constexpr int exit_internal = 3;

rollcontact::FftBackendKind parse_backend(const std::string& name) {
  if (name == "fftw") return rollcontact::FftBackendKind::Fftw;
  if (name == "kiss") return rollcontact::FftBackendKind::Kiss;
  return rollcontact::FftBackendKind::Default;
}

/// One console line per case: what a user looks for first.
void print_case_summary(const CaseOutcome& c) {
  const auto& p = c.problem;
  if (c.skipped) {
    fmt::print("case {:>4}: skipped (R={})\n", p.case_number, p.digits.r);
    return;
  }
  if (!c.solved) {
    fmt::print("case {:>4}: ERROR {}\n", p.case_number, c.error);
    return;
  }
  const auto& s = c.solution;
  const auto& t = s.totals;
  fmt::print(
      "case {:>4}: FN {:.4g} N  FX {:.4g} N  FY {:.4g} N  PEN {:.4e} mm  PMAX {:.4g} N/mm2  "
      "contact {}/{} elements ({:.4g} mm2)  {}\n",
      p.case_number, t.fn, t.fx, t.fy, t.pen, t.pmax, s.statistics.ncon, s.statistics.npot,
      t.contact_area,
      s.solver.converged ? fmt::format("converged, {} CG iterations", s.solver.normal_iterations)
                         : "NOT CONVERGED: " + s.solver.message);
}

int run_job(const std::filesystem::path& input, const std::string& outdir,
            const std::string& backend, bool quiet, bool show_picture) {
  rollcontact::io::RunOptions options;
  options.output_dir = outdir;
  options.solve.fft = parse_backend(backend);
  options.on_case = [&](const CaseOutcome& c, std::size_t k, std::size_t count) {
    if (quiet) return;
    print_case_summary(c);
    if (show_picture && c.solved) {
      std::ostringstream pic;
      rollcontact::io::write_element_division(pic, c.solution, c.problem.digits.t);
      fmt::print("{}\n", pic.str());
    }
    if (count > 20 && (k + 1) % 20 == 0) fmt::print(stderr, "  ... {}/{} cases\n", k + 1, count);
  };
  const auto result = rollcontact::io::run_input_file(input, options);
  if (!quiet)
    fmt::print("wrote {} and {}\n", result.report_path.string(), result.json_path.string());
  return result.failed == 0 ? exit_ok : exit_case_failed;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "rollcontact: rolling and sliding contact between elastic bodies "
      "(CONTACT-compatible, Kalker's exact half-space theory)"};
  app.set_version_flag("--version", std::string("rollcontact ") + rollcontact::version_string);
  app.require_subcommand(1);

  bool quiet = false;
  std::string outdir;
  std::string backend = "default";

  auto* run = app.add_subcommand("run",
                                 "Solve every case of a CONTACT .inp file; writes FILE.out "
                                 "(report) and FILE.json (results)");
  std::string input;
  run->add_option("FILE", input, "input file (.inp)")->required()->check(CLI::ExistingFile);
  run->add_option("-o,--output-dir", outdir, "folder for the outputs (default: next to FILE)");
  run->add_flag("-q,--quiet", quiet, "no console output");
  run->add_option("--fft", backend, "FFT backend")
      ->check(CLI::IsMember({"default", "fftw", "kiss"}));

  auto* example = app.add_subcommand(
      "example", "Write the built-in example (wheel on rail, 80 kN) as example.inp and solve it");
  std::string example_dir = "rollcontact-example";
  example->add_option("-o,--output-dir", example_dir, "folder for example.inp and its outputs")
      ->capture_default_str();
  example->add_flag("-q,--quiet", quiet, "no console output");

  CLI11_PARSE(app, argc, argv);

  try {
    if (run->parsed()) return run_job(input, outdir, backend, quiet, false);
    if (example->parsed()) {
      std::filesystem::create_directories(example_dir);
      const auto path = std::filesystem::path(example_dir) / "example.inp";
      rollcontact::io::write_file_atomically(path,
                                             std::string(rollcontact::io::builtin_example_inp));
      if (!quiet) fmt::print("built-in example: {}\n", path.string());
      return run_job(path, "", "default", quiet, true);
    }
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
