// `rollcontact table`: the 3220-case creep-force table of Vollebregt, Iwnicki, Xie & Shackleton
// (VSD 2012) with one method, written as CSV; with --reference, error statistics of an
// approximate method against an exact table (src/batch/creep_table*.hpp).

#include <fmt/format.h>

#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <functional>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "batch/creep_table.hpp"
#include "batch/creep_table_stats.hpp"
#include "batch/parallel.hpp"
#include "commands.hpp"
#include "format/text/atomic_file.hpp"
#include "progress_line.hpp"
#include "rollcontact/errors.hpp"

namespace rollcontact::cli {

namespace {

struct TableOptions {
  std::string method = "exact";
  int bound = -1;
  int mx = 11;
  double eps = 1e-5;
  std::string output;
  std::string reference;
  std::string stats;
  std::string cases;
  int threads = 0;
  bool quiet = false;
};

int run_table_command(const TableOptions& o, batch::Distribution& distribution) {
  batch::TableSettings settings;
  settings.method = batch::parse_table_method(o.method);
  settings.bound = o.bound;
  settings.mx = o.mx;
  settings.eps = o.eps;
  batch::check_table_settings(settings);
  const int bound = batch::effective_bound(settings);
  // Read the reference first: a bad file should fail before an hour of computing.
  std::vector<batch::TableRow> reference;
  if (!o.reference.empty()) reference = batch::read_table_csv_file(o.reference);
  const std::vector<batch::TableCase> cases = batch::select_table_cases(o.cases);
  const bool distributed = distribution.size() > 1;
  const bool root = distribution.is_root();
  // Under MPI every rank is one worker (start as many ranks as cores); threads stay for one
  // process.
  const int threads = distributed ? 1 : batch::default_thread_count(o.threads);
  if (distributed && root && o.threads > 1 && !o.quiet)
    fmt::print(stderr, "table: --threads {} ignored under MPI: {} processes, one thread each\n",
               o.threads, distribution.size());

  const auto wall0 = std::chrono::steady_clock::now();
  const std::clock_t cpu0 = std::clock();
  const auto progress = make_progress_line("table " + o.method, cases.size(), o.quiet);
  const std::vector<batch::TableRow> rows =
      distributed ? batch::run_table_distributed(cases, settings, distribution)
                  : batch::run_table(cases, settings, threads, progress);
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  const double cpu = static_cast<double>(std::clock() - cpu0) / CLOCKS_PER_SEC;
  // Only the root writes and reports (mpirun's status is the worst of the processes'); no
  // collective call follows, so that a root that fails to write cannot leave the others waiting.
  if (!root) return exit_ok;

  std::ostringstream csv;
  batch::write_table_csv(csv, rows);
  format::write_output_file(o.output, csv.str());

  std::vector<const batch::TableRow*> failed;
  for (const auto& r : rows)
    if (!r.converged) failed.push_back(&r);
  const double n = static_cast<double>(rows.size());
  if (!o.quiet) {
    const std::string workers = distributed ? fmt::format("{} MPI processes", distribution.size())
                                            : fmt::format("{} threads", threads);
    fmt::print("table {} (B={}, mx={}, {}): {} cases, {} not converged -> {}\n", o.method, bound,
               settings.mx, workers, rows.size(), failed.size(), o.output);
    fmt::print("time: wall {:.3f} s, CPU {:.3f} s{}; per case {:.4g} ms CPU, {:.4g} ms wall\n",
               wall, cpu, distributed ? " (root process)" : "", 1e3 * cpu / n, 1e3 * wall / n);
    for (const auto* r : failed)
      fmt::print("  not converged: case {} (a/b {:g}, spin {:g}, angle {:g}, magnitude {:g}): {}\n",
                 r->tc.number, r->tc.a_over_b, r->tc.spin, r->tc.angle_deg, r->tc.magnitude,
                 r->message);
  }

  if (!reference.empty()) {
    const batch::TableStatistics st = batch::compare_tables(rows, reference);
    const std::string title =
        fmt::format("{} B={} mx={} against {}", o.method, bound, settings.mx, o.reference);
    if (!o.quiet) fmt::print("\n{}", batch::format_statistics_text(st, title));
    if (!o.stats.empty())
      format::write_output_file(o.stats, batch::format_statistics_markdown(st, title));
  }
  return failed.empty() ? exit_ok : exit_case_failed;
}

}  // namespace

CommandRunner add_table_command(CLI::App& app, batch::Distribution& distribution) {
  auto opts = std::make_shared<TableOptions>();
  CLI::App* cmd = app.add_subcommand(
      "table",
      "Creep-force table of Vollebregt et al. (VSD 2012): 3220 steady-rolling Hertzian cases "
      "with one method, as CSV; with --reference, error statistics against an exact table");
  cmd->add_option("--method", opts->method, "exact | fastsim1 | fastsim3 | fastrip")
      ->check(CLI::IsMember({"exact", "fastsim1", "fastsim3", "fastrip"}))
      ->capture_default_str();
  cmd->add_option("--bound", opts->bound,
                  "normal pressure: 0 exact normal solve, 2 elliptic, 3 parabolic (default 0 for "
                  "exact, 2 for the approximate methods)")
      ->check(CLI::IsMember({0, 2, 3}));
  cmd->add_option("--mx", opts->mx, "elements per axis (mx = my; mx-4 over the Hertz ellipse)")
      ->capture_default_str();
  cmd->add_option("--eps", opts->eps, "solver tolerance of the exact theory")
      ->capture_default_str();
  cmd->add_option("-o,--output", opts->output, "CSV file to write")->required();
  cmd->add_option("--reference", opts->reference,
                  "CSV of --method exact with the same mx: print error statistics against it");
  cmd->add_option("--stats", opts->stats, "also write the error statistics as Markdown");
  cmd->add_option("--cases", opts->cases, "subset of case numbers, e.g. 1-50,100 (default all)");
  cmd->add_option("--threads", opts->threads,
                  "worker threads (default: all cores); under mpirun each process is one worker");
  cmd->add_flag("-q,--quiet", opts->quiet, "no progress line and no summary");
  return [opts, &distribution] { return run_table_command(*opts, distribution); };
}

}  // namespace rollcontact::cli
