// `rollcontact lookup`: creep-force lookup tables for multibody codes
// (include/rollcontact/creep_lookup.hpp): build one with the exact theory (or Fastsim) over the
// default grid of semi-axis ratio and normalised creepages, store it as HDF5 and report its
// interpolation error at held-back points; or evaluate a stored table.

#include <fmt/format.h>

#include <chrono>
#include <cstdio>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "batch/creep_lookup_build.hpp"
#include "batch/parallel.hpp"
#include "commands.hpp"
#include "progress_line.hpp"
#include "rollcontact/creep_lookup.hpp"
#include "rollcontact/errors.hpp"

namespace rollcontact::cli {

namespace {

struct LookupOptions {
  std::string output;
  std::string method = "exact";
  std::string grid = "default";
  int mx = 15;
  double eps = 1e-5;
  int threads = 0;
  int check = 200;
  std::string table;
  std::vector<double> at;
  bool quiet = false;
};

int evaluate_table(const LookupOptions& o) {
  const CreepLookupTable table = load_creep_lookup(o.table);
  if (o.at.size() % 4 != 0)
    throw InputError("--at", 0, "expects groups of 4 values: a/b ksi_n eta_n phi_n");
  fmt::print(
      "# {} (method {}, mx {}, nu {:g}): a/b ksi_n eta_n phi_n -> Fx/(mu FN) Fy/(mu FN) "
      "Mz/(mu FN c)\n",
      o.table, table.info().method, table.info().mx, table.info().poisson_ratio);
  for (std::size_t i = 0; i < o.at.size(); i += 4) {
    const CreepLookupValue v = table.evaluate(o.at[i], o.at[i + 1], o.at[i + 2], o.at[i + 3]);
    fmt::print("{:g} {:g} {:g} {:g} -> {:.6f} {:.6f} {:.6f}\n", o.at[i], o.at[i + 1], o.at[i + 2],
               o.at[i + 3], v.fx, v.fy, v.mz);
  }
  return exit_ok;
}

int build_table(const LookupOptions& o, batch::Distribution& distribution) {
  batch::TableSettings s;
  s.method = batch::parse_table_method(o.method);
  s.mx = o.mx;
  s.eps = o.eps;
  batch::check_table_settings(s);
  const CreepLookupAxes axes =
      o.grid == "coarse" ? batch::coarse_lookup_axes() : batch::default_lookup_axes();
  const bool root = distribution.is_root();
  const int threads = distribution.size() > 1 ? 1 : batch::default_thread_count(o.threads);
  const std::size_t nodes =
      axes.a_over_b.size() * axes.ksi.size() * axes.eta.size() * axes.phi.size();
  const auto t0 = std::chrono::steady_clock::now();
  auto seconds = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  };
  const auto progress = make_progress_line("lookup " + o.method, nodes, o.quiet || !root);
  const CreepLookupTable table =
      batch::build_creep_lookup(axes, s, threads, &distribution, progress);
  if (!root) return exit_ok;
  const double build_s = seconds();
  save_creep_lookup(table, o.output);
  if (!o.quiet)
    fmt::print(stderr, "lookup {} (mx {}): {} nodes in {:.1f} s -> {}\n", o.method, o.mx, nodes,
               build_s, o.output);
  if (o.check > 0) {
    const batch::LookupAccuracy acc = batch::held_back_accuracy(
        table, s, static_cast<std::size_t>(o.check), 1u, batch::default_thread_count(o.threads));
    fmt::print(
        "interpolation error at {} held-back points ({} itself): |dF|/(mu FN) max {:.4f}, "
        "rms {:.4f}; |dMz|/(mu FN c) max {:.4f}\n",
        acc.points, o.method, acc.max_force_error, acc.rms_force_error, acc.max_moment_error);
  }
  return exit_ok;
}

}  // namespace

CommandRunner add_lookup_command(CLI::App& app, batch::Distribution& distribution) {
  auto o = std::make_shared<LookupOptions>();
  CLI::App* cmd = app.add_subcommand(
      "lookup",
      "Creep-force lookup table for MBS codes: build it (-o FILE.h5, HDF5) over a/b and "
      "normalised creepages with the exact theory or Fastsim, or evaluate one (--table, --at)");
  cmd->add_option("-o,--output", o->output, "HDF5 file to build");
  cmd->add_option("--method", o->method, "exact | fastsim1 | fastsim3 | fastrip")
      ->check(CLI::IsMember({"exact", "fastsim1", "fastsim3", "fastrip"}))
      ->capture_default_str();
  cmd->add_option("--grid", o->grid,
                  "default: 223,125 nodes (a/b 0.2-5, normalised creepages to 1, spin to 3); "
                  "coarse: 441 nodes for quick checks")
      ->check(CLI::IsMember({"default", "coarse"}))
      ->capture_default_str();
  cmd->add_option("--mx", o->mx, "elements per axis of each node's grid")->capture_default_str();
  cmd->add_option("--eps", o->eps, "solver tolerance of the exact theory")->capture_default_str();
  cmd->add_option("--threads", o->threads, "worker threads (default: all cores)");
  cmd->add_option("--check", o->check,
                  "held-back points at which the interpolation is compared with the method (0: "
                  "none)")
      ->capture_default_str();
  cmd->add_option("--table", o->table, "HDF5 table to evaluate");
  cmd->add_option("--at", o->at, "a/b ksi_n eta_n phi_n (repeatable groups of 4)");
  cmd->add_flag("-q,--quiet", o->quiet, "no progress line");
  return [o, &distribution] {
    if (!o->table.empty()) return evaluate_table(*o);
    if (o->output.empty()) throw InputError("lookup", 0, "give -o FILE.h5 (build) or --table FILE");
    return build_table(*o, distribution);
  };
}

}  // namespace rollcontact::cli
