// `rollcontact dynamic CASE -o RUN.csv`: a wheel under a sprung mass rolling along the rail of a
// wheel/rail case, integrated in time with the contact solved at every step
// (rollcontact/dynamics.hpp, spec/dynamic-rolling.md §5). Defaults: the Ma et al. (2018) study.

#include <fmt/format.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "batch/run_input.hpp"
#include "commands.hpp"
#include "format/inp/to_wheelrail.hpp"
#include "rollcontact/dynamics.hpp"
#include "rollcontact/errors.hpp"

namespace rollcontact::cli {

namespace {

struct DynamicOptions {
  std::string input, output;
  int case_number = 0;  ///< 0: the first wheel/rail case
  dynamics::SprungWheel vehicle;
  dynamics::DynamicRollingSettings run;
  std::string start = "equilibrium";
  double speed_mm_s = 0.0;  ///< 0: the case's VS
  double window_s = 0.0;    ///< 0: the last quarter of the run
  bool quiet = false;
  bool unvalidated = false;  ///< solve what is not validated against CONTACT (wheel slices, ...)
};

model::WheelRailProblem wheel_rail_case(const DynamicOptions& o) {
  const std::vector<format::InputCase> cases = batch::read_input_file(o.input);
  for (const format::InputCase& c : cases) {
    const auto* w = std::get_if<format::WheelRailRecord>(&c);
    if (w == nullptr || (o.case_number != 0 && w->case_number != o.case_number)) continue;
    return format::to_wheelrail_problem(*w, o.unvalidated);
  }
  throw InputError(o.input, 0,
                   o.case_number != 0
                       ? fmt::format("case {} is not a wheel/rail (module 1) case", o.case_number)
                       : std::string("no wheel/rail (module 1) case in the file"));
}

void write_csv(const std::filesystem::path& path, const dynamics::DynamicRollingResult& r) {
  // Written to a temporary name and renamed: a failed run leaves no half-written file.
  const std::filesystem::path partial = path.string() + ".partial";
  {
    std::ofstream f(partial);
    if (!f) throw Error(fmt::format("cannot write {}", path.string()));
    f << "# rollcontact dynamic: static load " << fmt::format("{:.6g}", r.static_load_N)
      << " N, z_ws static " << fmt::format("{:.6g}", r.z_ws_static_mm) << " mm, contact stiffness "
      << fmt::format("{:.6g}", r.contact_stiffness_N_per_mm) << " N/mm ("
      << fmt::format("{:.4g}", r.contact_frequency_Hz) << " Hz)\n";
    f << "t_s,s_mm,z_ws_mm,z_sprung_mm,vz_wheel_mm_s,rail_dz_mm,fx_N,fy_N,fz_N,area_mm2,"
         "pmax_N_mm2,contact_elements,slip_elements,patches,solves,converged\n";
    for (const dynamics::TimeSample& s : r.history)
      f << fmt::format(
          "{:.8g},{:.8g},{:.9g},{:.8g},{:.8g},{:.8g},{:.8g},{:.8g},{:.8g},{:.8g},"
          "{:.8g},{},{},{},{},{}\n",
          s.t_s, s.s_mm, s.z_ws_mm, s.z_sprung_mm, s.vz_wheel_mm_s, s.rail_dz_mm, s.fx_N, s.fy_N,
          s.fz_N, s.area_mm2, s.pmax_N_mm2, s.contact_elements, s.slip_elements, s.patches,
          s.solves, s.converged ? 1 : 0);
    if (!f) throw Error(fmt::format("cannot write {}", path.string()));
  }
  std::filesystem::rename(partial, path);
}

int run_dynamic(DynamicOptions o) {
  model::WheelRailProblem problem = wheel_rail_case(o);
  if (o.speed_mm_s > 0.0) {
    // A new speed rolls the wheel at the same creepage: VPITCH scales with it.
    const double scale = o.speed_mm_s / problem.motion.vs_mm_s;
    problem.motion.vs_mm_s = o.speed_mm_s;
    problem.motion.vpitch_rad_s *= scale;
  }
  o.run.start =
      o.start == "contact" ? dynamics::StartState::FirstContact : dynamics::StartState::Equilibrium;
  const bool show = !o.quiet && isatty(fileno(stderr)) != 0;
  int last_percent = -1;
  const dynamics::Progress progress = [&](const dynamics::TimeSample& s, double fraction) {
    const int percent = static_cast<int>(100.0 * fraction);
    if (!show || percent == last_percent) return;
    last_percent = percent;
    fmt::print(stderr, "\rdynamic: {:3d} %  s {:8.1f} mm  Fz {:10.1f} N", percent, s.s_mm, s.fz_N);
  };
  const dynamics::DynamicRollingResult r =
      dynamics::run_dynamic_rolling(problem, o.vehicle, o.run, {}, progress);
  if (show) fmt::print(stderr, "\n");
  write_csv(o.output, r);
  const double duration = r.history.empty() ? 0.0 : r.history.back().t_s;
  const double window = o.window_s > 0.0 ? o.window_s : 0.25 * duration;
  const dynamics::SignalSummary sum = dynamics::summarise_force(r.history, window);
  fmt::print(
      "dynamic rolling: {} steps of {:.3g} s over {:.1f} mm at {:.1f} km/h, {} contact solves\n"
      "  static load {:.1f} N, z_ws static {:.5f} mm (contact starts at {:.5f} mm)\n"
      "  contact stiffness {:.4g} N/mm, wheel-on-contact frequency {:.1f} Hz\n"
      "  last {:.4g} s: Fz mean {:.1f} N (static {:+.3f} %), min {:.1f}, max {:.1f} N, "
      "dominant frequency {:.1f} Hz\n"
      "wrote {}\n",
      r.steps, o.run.time_step_s, o.run.distance_mm, 3.6e-3 * std::abs(problem.motion.vs_mm_s),
      r.solves, r.static_load_N, r.z_ws_static_mm, r.z_ws_contact_mm, r.contact_stiffness_N_per_mm,
      r.contact_frequency_Hz, window, sum.mean, 100.0 * (sum.mean / r.static_load_N - 1.0), sum.min,
      sum.max, sum.dominant_frequency_Hz, o.output);
  for (const std::string& w : r.warnings) fmt::print(stderr, "rollcontact: warning: {}\n", w);
  if (!r.converged) {
    fmt::print(stderr, "rollcontact: NOT CONVERGED: {}\n", r.message);
    return exit_case_failed;
  }
  return exit_ok;
}

}  // namespace

CommandRunner add_dynamic_command(CLI::App& app) {
  auto o = std::make_shared<DynamicOptions>();
  auto* cmd = app.add_subcommand(
      "dynamic",
      "Roll the wheel of a wheel/rail case (.inp or .toml, module 1) under a sprung mass on a "
      "primary suspension, integrated in time (trapezoidal rule) with the contact solved exactly "
      "at every step; writes the history as CSV (plot it with `rollcontact plot RUN.csv --what "
      "dynamic`). Defaults: Ma, Markine, Mashal, Ren (2018): 10 t on 1.15 MN/m and 2500 N s/m, "
      "a 350 kg wheel (assumed), 1 m of rail (docs/validation-fe.md)");
  cmd->add_option("CASE", o->input, "wheel/rail input file (.inp, .toml)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", o->output, "history, CSV")->required();
  cmd->add_option("--case", o->case_number, "case number (default: the first wheel/rail case)");
  cmd->add_option("--distance-mm", o->run.distance_mm, "rolled distance [mm] (1000)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--dt-s", o->run.time_step_s, "time step [s] (2e-5)")->check(CLI::PositiveNumber);
  cmd->add_option("--speed-mm-s", o->speed_mm_s,
                  "rolling speed [mm/s] (default: the case's VS; VPITCH scaled with it)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--sprung-mass-kg", o->vehicle.sprung_mass_kg, "sprung mass [kg] (10000)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--wheel-mass-kg", o->vehicle.wheel_mass_kg, "wheel mass [kg] (350)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--suspension-N-per-mm", o->vehicle.suspension_stiffness_N_per_mm,
                  "primary suspension stiffness [N/mm] (1150)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--damping-N-s-per-mm", o->vehicle.suspension_damping_N_s_per_mm,
                  "primary suspension damping [N s/mm] (2.5)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--start", o->start,
                  "equilibrium (static, default) or contact (wheel just touching, springs at "
                  "their static length: it drops onto the rail)")
      ->check(CLI::IsMember({"equilibrium", "contact"}));
  cmd->add_option("--vz-mm-s", o->run.initial_vz_mm_per_s,
                  "initial downward velocity of wheel and sprung mass [mm/s] (0)");
  cmd->add_option("--dip-depth-mm", o->run.dip.depth_mm, "depth of a cosine rail dip [mm] (0)");
  cmd->add_option("--dip-start-mm", o->run.dip.start_mm, "where the dip starts [mm] (0)");
  cmd->add_option("--dip-length-mm", o->run.dip.length_mm, "length of the dip [mm] (100)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--contact-damping", o->run.contact_damping_ratio,
                  "viscous wheel-rail damping, fraction of critical for the wheel on the contact "
                  "(0: the elastic contact; an FE model's VDC = 100 x this)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--keep-every", o->run.keep_every, "write every n-th step (1)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--window-s", o->window_s,
                  "summary window at the end [s] (default: the last quarter)");
  cmd->add_flag("-q,--quiet", o->quiet, "no progress line");
  cmd->add_flag("--unvalidated", o->unvalidated,
                "also roll what `rollcontact run` refuses as not yet validated against CONTACT, "
                "e.g. a wheel with a flat (slices; the wheel turns at VPITCH), with a warning");
  return [o] { return run_dynamic(*o); };
}

}  // namespace rollcontact::cli
