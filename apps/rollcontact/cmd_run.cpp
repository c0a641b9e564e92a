// `rollcontact run` and `rollcontact example`.

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "batch/parallel.hpp"
#include "batch/run_input.hpp"
#include "batch/temporary_folder.hpp"
#include "commands.hpp"
#include "format/inp/builtin_example.hpp"
#include "format/report/report_writer.hpp"
#include "format/text/atomic_file.hpp"
#include "rollcontact/errors.hpp"

namespace rollcontact::cli {

namespace {

using batch::CaseOutcome;

FftBackendKind parse_backend(const std::string& name) {
  if (name == "fftw") return FftBackendKind::Fftw;
  if (name == "kiss") return FftBackendKind::Kiss;
  return FftBackendKind::Default;
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
  if (c.wheel_rail) {
    const WheelRailSolution& w = c.wheelrail;
    fmt::print(
        "case {:>4}: wheel/rail, {} patch{}  F(TR) = ({:.5g}, {:.5g}, {:.5g}) N  z_ws {:.5g} mm  "
        "{}  (geometry {:.2f} ms, patches {:.2f} ms)\n",
        p.case_number, w.patches.size(), w.patches.size() == 1 ? "" : "es", w.force_tr.x,
        w.force_tr.y, w.force_tr.z, w.z_ws_mm,
        w.converged ? "converged" : "NOT CONVERGED: " + w.message, 1e3 * w.geometry_seconds,
        1e3 * w.patch_solve_seconds);
    return;
  }
  const auto& s = c.solution;
  const auto& t = s.totals;
  fmt::print(
      "case {:>4}: FN {:.5g} N  FX {:.5g} N  FY {:.5g} N  PEN {:.4e} mm  PMAX {:.4g} N/mm2  "
      "contact {}/{} elements ({:.4g} mm2)  {}\n",
      p.case_number, t.fn, t.fx, t.fy, t.pen, t.pmax, s.statistics.ncon, s.statistics.npot,
      t.contact_area,
      s.solver.converged ? fmt::format("converged, {} CG iterations", s.solver.normal_iterations)
                         : "NOT CONVERGED: " + s.solver.message);
}

struct RunSettings {
  std::vector<std::string> inputs;
  std::string output_dir;
  std::string backend = "default";
  bool measure = false;
  bool quiet = false;
  bool timing = false;
  bool unvalidated = false;
  int threads = 1;
};

/// --timing: where the wall time went, on stderr so that reports and console stay as they are.
void print_timing(const batch::RunTiming& t) {
  fmt::print(stderr, "timing: read     {:.4f} s\n", t.read);
  fmt::print(stderr, "timing: set-up   {:.4f} s\n", t.read + t.setup);
  fmt::print(stderr, "timing: solve    {:.4f} s\n", t.solve);
  fmt::print(stderr, "timing: output   {:.4f} s\n", t.output);
}

/// The options every run shares: output folder and FFT choices.
batch::RunOptions solver_run_options(const RunSettings& settings) {
  batch::RunOptions options;
  options.output_dir = settings.output_dir;
  options.solve.fft = parse_backend(settings.backend);
  options.solve.fft_planning = settings.measure ? FftPlanning::Measure : FftPlanning::Estimate;
  options.solve_unvalidated = settings.unvalidated;
  // The report and JSON hold the fields; the program needs only each case's status after that.
  options.keep_fields = false;
  options.keep_outcomes = false;
  return options;
}

/// Says how to get our best answer for such cases anyway.
void print_unvalidated_hint(const batch::RunResult& result) {
  if (const std::size_t refused = result.refused_unvalidated; refused > 0)
    fmt::print(stderr,
               "note: {} case(s) refused as not validated against CONTACT; `rollcontact run "
               "--unvalidated` solves them, each with a warning in the report and the JSON\n",
               refused);
}

int run_job(const std::filesystem::path& input, const RunSettings& settings, bool show_picture,
            batch::Distribution* distribution = nullptr) {
  batch::RunOptions options = solver_run_options(settings);
  const bool distributed = distribution != nullptr && distribution->size() > 1;
  if (distributed) {
    options.distribution = distribution;
    if (distribution->is_root() && !settings.quiet)
      fmt::print(stderr, "run: {} MPI processes, one sequence (result element) at a time each{}\n",
                 distribution->size(), settings.threads > 1 ? "; --threads ignored" : "");
  }
  const bool quiet = settings.quiet;
  // With threads the cases come while the progress line is shown: clear it first.
  const bool progress_line =
      !quiet && !distributed && settings.threads > 1 && isatty(fileno(stderr));
  options.on_case = [quiet, show_picture, progress_line](const CaseOutcome& c, std::size_t k,
                                                         std::size_t count) {
    if (quiet) return;
    if (progress_line) fmt::print(stderr, "\r{:72}\r", "");
    print_case_summary(c);
    if (show_picture && c.solved && !c.wheel_rail) {
      std::ostringstream pic;
      format::write_element_division(pic, c.solution, c.problem.digits.t);
      fmt::print("{}\n", pic.str());
    }
    if (count > 20 && (k + 1) % 20 == 0) fmt::print(stderr, "  ... {}/{} cases\n", k + 1, count);
  };
  options.threads = settings.threads;
  if (progress_line) {
    // A progress line on a terminal while the threads work (not in pipes or with -q).
    const auto start = std::chrono::steady_clock::now();
    options.on_progress = [start](std::size_t done, std::size_t count) {
      const double s =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      const double rate = s > 0.0 ? static_cast<double>(done) / s : 0.0;
      const double left = rate > 0.0 ? static_cast<double>(count - done) / rate : 0.0;
      fmt::print(stderr, "\r  {}/{} cases, {:.1f} cases/s, {:.0f} s left   ", done, count, rate,
                 left);
      if (done == count) fmt::print(stderr, "\n");
    };
  }
  const auto result = batch::run_input_file(input, options);
  // Under MPI only the root writes the report and knows the verdict; mpirun's status is the
  // worst of the processes'.
  if (distributed && !distribution->is_root()) return exit_ok;
  if (settings.timing) print_timing(result.timing);
  if (!quiet && distributed) fmt::print("{} case(s) failed\n", result.failed);
  if (!quiet)
    fmt::print("wrote {} and {}\n", result.report_path.string(), result.json_path.string());
  if (!quiet) print_unvalidated_hint(result);
  return result.failed == 0 ? exit_ok : exit_case_failed;
}

/// The files in the order to start them: costliest first by an estimate from the inputs (a long
/// file started last would leave the other threads idle at the end); unreadable files last,
/// where their error is reported.
std::vector<std::size_t> costliest_first(const std::vector<std::string>& inputs) {
  std::vector<std::size_t> order(inputs.size());
  std::vector<double> cost(inputs.size(), -1.0);
  for (std::size_t k = 0; k < inputs.size(); ++k) {
    order[k] = k;
    try {
      cost[k] = batch::estimated_run_cost(inputs[k]);
    } catch (const Error&) {
    }
  }
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return cost[a] > cost[b]; });
  return order;
}

/// Several inputs: two with the same output stem (the same name in one -o folder, or x.inp and
/// x.toml side by side) would write the same outputs, and one input's report or JSON must not
/// replace another input (run x.inp x.json). Checked before anything runs.
void refuse_clashing_outputs(const RunSettings& settings) {
  namespace fs = std::filesystem;
  std::vector<std::pair<fs::path, std::string>> stems;  // output stem, its input
  for (const std::string& input : settings.inputs) {
    const fs::path plain = batch::output_stem(input, settings.output_dir);
    std::error_code ec;  // canonical, so that two spellings of one folder compare equal
    const fs::path stem =
        fs::weakly_canonical(plain.has_parent_path() ? plain.parent_path() : ".", ec) /
        plain.filename();
    for (const auto& [other, other_input] : stems)
      if (other == stem)
        throw InputError(input, 0,
                         fmt::format("{} writes its outputs to {}.out and .json as well; run the "
                                     "two one after the other, or rename one",
                                     other_input, stem.string()));
    stems.emplace_back(stem, input);
  }
  for (const std::string& input : settings.inputs)
    for (const auto& [stem, writer] : stems)
      for (const char* ext : {".out", ".json"}) {
        fs::path out = stem;
        out += ext;
        std::error_code ec;
        if (fs::exists(input, ec) && fs::exists(out, ec) && fs::equivalent(input, out, ec))
          throw InputError(input, 0,
                           fmt::format("the run of {} would replace this input with its {} "
                                       "output; rename it or write elsewhere with -o DIR",
                                       writer, ext));
      }
}

/// Several files on --threads workers, each file on one thread; one line per file at the end,
/// in the order given. Exit status: the worst of the files'.
int run_files_in_parallel(const RunSettings& settings) {
  const std::size_t n = settings.inputs.size();
  struct FileOutcome {
    int status = exit_ok;
    std::string line;
  };
  std::vector<FileOutcome> outcomes(n);
  batch::ParallelOptions parallel;
  parallel.threads = settings.threads;
  std::function<void(std::size_t)> progress;
  if (!settings.quiet && isatty(fileno(stderr)))
    progress = [n](std::size_t done) {
      fmt::print(stderr, "\r  {}/{} files   {}", done, n, done == n ? "\n" : "");
    };
  const std::vector<std::size_t> order = costliest_first(settings.inputs);
  const batch::RunOptions options = solver_run_options(settings);
  batch::parallel_for(
      n, parallel,
      [&](std::size_t, std::size_t j) {
        const std::size_t k = order[j];
        FileOutcome& o = outcomes[k];
        try {
          const batch::RunResult r = batch::run_input_file(settings.inputs[k], options);
          o.status = r.failed == 0 ? exit_ok : exit_case_failed;
          o.line =
              fmt::format("{}: {} case(s), {} failed; wrote {} and {}", settings.inputs[k],
                          r.case_count, r.failed, r.report_path.string(), r.json_path.string());
          if (const std::size_t refused = r.refused_unvalidated; refused > 0)
            o.line += fmt::format(
                " ({} refused as not validated against CONTACT: --unvalidated "
                "solves them with a warning)",
                refused);
        } catch (const InputError& e) {
          o.status = exit_input_error;
          o.line = fmt::format("rollcontact: error: {}", e.what());
        } catch (const Error& e) {
          o.status = exit_case_failed;
          o.line = fmt::format("rollcontact: error: {}", e.what());
        }
      },
      progress);
  int status = exit_ok;
  for (const FileOutcome& o : outcomes) {
    status = std::max(status, o.status);
    if (o.status == exit_input_error)
      fmt::print(stderr, "{}\n", o.line);
    else if (!settings.quiet)
      fmt::print("{}\n", o.line);
  }
  return status;
}

/// Several input files: each is run as `run FILE` would run it (its report, JSON and side
/// files, bytes as from a run of its own), one after the other or, with --threads N, N at a
/// time. An unreadable file does not stop the others.
int run_files(const RunSettings& settings, batch::Distribution& distribution) {
  refuse_clashing_outputs(settings);
  if (distribution.size() == 1 && settings.threads > 1) return run_files_in_parallel(settings);
  int status = exit_ok;
  for (const std::string& input : settings.inputs) {
    int s = exit_ok;
    try {
      s = run_job(input, settings, false, &distribution);
    } catch (const InputError& e) {
      if (distribution.is_root()) fmt::print(stderr, "rollcontact: error: {}\n", e.what());
      s = exit_input_error;
    }
    status = std::max(status, s);
  }
  return status;
}

void add_solver_options(CLI::App* cmd, RunSettings& s) {
  cmd->add_option("--fft", s.backend, "FFT backend")
      ->check(CLI::IsMember({"default", "fftw", "kiss"}))
      ->capture_default_str();
  cmd->add_flag("--fft-measure", s.measure,
                "plan FFTs with FFTW_MEASURE (faster transforms, seconds of planning per grid)");
  cmd->add_flag("-q,--quiet", s.quiet, "no console output");
}

}  // namespace

CommandRunner add_run_command(CLI::App& app, batch::Distribution& distribution) {
  auto settings = std::make_shared<RunSettings>();
  auto* cmd = app.add_subcommand(
      "run", "Solve every case of a CONTACT .inp file; writes FILE.out (report) and FILE.json");
  cmd->add_option("FILE", settings->inputs,
                  "input file(s) (.inp); several files run one after the other, or with "
                  "--threads N N at a time")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("-o,--output-dir", settings->output_dir,
                  "folder for the outputs (default: next to FILE)");
  add_solver_options(cmd, *settings);
  cmd->add_flag("--timing", settings->timing,
                "print the wall time of reading, set-up (kernels, operators, FFT plans), solve "
                "and output to stderr");
  cmd->add_option("-j,--threads", settings->threads,
                  "worker threads: sequences (result elements) run in parallel, each in its "
                  "order (several files: the files run in parallel); the outputs are those of "
                  "one thread")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->add_flag("--unvalidated", settings->unvalidated,
                "also solve the wheel/rail features whose results are known to differ from "
                "CONTACT's references (wheel slices near a flat, KPEC beyond its ellipse, ANALYN "
                "on combined regions, D_TURN-turned patches), each case with a warning, instead "
                "of refusing them (docs/decisions.md)");
  return [settings, &distribution] {
    if (settings->inputs.size() > 1) return run_files(*settings, distribution);
    return run_job(settings->inputs.front(), *settings, false, &distribution);
  };
}

CommandRunner add_example_command(CLI::App& app) {
  auto settings = std::make_shared<RunSettings>();
  auto* cmd = app.add_subcommand(
      "example", "Write the built-in example (wheel on rail, 80 kN) as example.inp and solve it");
  cmd->add_option("-o,--output-dir", settings->output_dir,
                  "folder for example.inp and outputs (default: a new temporary folder)");
  add_solver_options(cmd, *settings);
  return [settings] {
    // Nothing is left in the working directory unless asked for.
    const std::filesystem::path dir = settings->output_dir.empty()
                                          ? batch::new_temporary_folder("rollcontact-example")
                                          : std::filesystem::path(settings->output_dir);
    std::filesystem::create_directories(dir);
    const auto path = dir / "example.inp";
    format::write_file_atomically(path, std::string(format::builtin_example_inp));
    if (!settings->quiet) fmt::print("built-in example: {}\n", path.string());
    RunSettings local = *settings;
    local.inputs = {path.string()};
    local.output_dir.clear();  // outputs next to example.inp
    return run_job(path, local, true);
  };
}

}  // namespace rollcontact::cli
