#include "format/report/json_writer.hpp"

#include "format/report/report_values.hpp"
#include "rollcontact/version.hpp"

namespace rollcontact::format {
namespace {

nlohmann::json case_identity(const CaseRecord& problem) {
  nlohmann::json j;
  j["case"] = problem.case_number;
  j["module"] = 3;
  j["result_element"] = problem.result_element >= 1 ? problem.result_element : 1;
  j["patch"] = problem.contact_problem >= 1 ? problem.contact_problem : 1;
  return j;
}

}  // namespace

nlohmann::json case_to_json(const CaseRecord& problem, const Solution& solution) {
  nlohmann::json j = case_identity(problem);
  const bool converged = solution.solver.converged;
  j["status"] = converged ? "converged" : "not_converged";
  j["message"] = converged ? std::string() : solution.solver.message;

  const auto& t = solution.totals;
  const auto& dg = problem.digits;
  const EffectiveCreepages c = effective_creepages(problem, solution);
  const bool rolling = dg.t >= 2;
  const bool shifting = dg.t == 1;
  j["totals"] = {
      {"fn", t.fn},
      {"fx", t.fx},
      {"fy", t.fy},
      {"mz", t.mz},
      {"pen", effective_approach(problem, solution)},
      {"pmax", t.pmax},
      {"creep_x", rolling ? c.x : 0.0},
      {"creep_y", rolling ? c.y : 0.0},
      {"spin", rolling ? c.phi : 0.0},
      {"shift_x", shifting ? c.x : 0.0},
      {"shift_y", shifting ? c.y : 0.0},
      {"elastic_energy", t.elastic_energy},
      {"frictional_power", t.frictional_power},
  };
  if (dg.h >= 1) {  // surface temperature (docs/results-json.md)
    j["totals"]["max_temp1"] = t.max_temp1;
    j["totals"]["max_temp2"] = t.max_temp2;
  }
  const auto& s = solution.statistics;
  j["statistics"] = {{"npot", s.npot},   {"ncon", s.ncon},     {"nadh", s.nadh},
                     {"nslip", s.nslip}, {"nplast", s.nplast}, {"inorm", s.inorm},
                     {"itang", s.itang}};
  j["solver"] = {{"normal_iterations", solution.solver.normal_iterations},
                 {"tangential_iterations", solution.solver.tangential_iterations},
                 {"newton_iterations", solution.solver.newton_iterations}};
  if (!solution.warnings.empty()) j["warnings"] = solution.warnings;
  return j;
}

nlohmann::json wheelrail_case_to_json(const CaseRecord& identity,
                                      const WheelRailSolution& solution) {
  nlohmann::json j = case_identity(identity);
  j["module"] = 1;
  j.erase("patch");
  j["status"] = solution.converged ? "converged" : "not_converged";
  j["message"] = solution.converged ? std::string() : solution.message;
  auto vec = [](const Vector3& v) { return nlohmann::json::array({v.x, v.y, v.z}); };
  j["z_ws"] = solution.z_ws_mm;
  j["vpitch"] = solution.vpitch_rad_s;
  if (solution.pitch_iterations > 0) j["pitch_iterations"] = solution.pitch_iterations;
  j["force_tr"] = vec(solution.force_tr);
  j["force_ws"] = vec(solution.force_ws);
  if (const RailDeflection& rd = solution.rail_deflection; rd.active)
    j["rail_deflection"] = {{"dy", rd.dy_mm},
                            {"dz", rd.dz_mm},
                            {"ky", rd.ky_N_per_mm},
                            {"fy", rd.fy_N},
                            {"kz", rd.kz_N_per_mm},
                            {"fz", rd.fz_N},
                            {"residual_y", rd.residual_y_N},
                            {"residual_z", rd.residual_z_N},
                            {"iterations", rd.iterations}};
  nlohmann::json trace = nlohmann::json::array();
  for (const VerticalForceStep& s : solution.trace)
    trace.push_back({{"iteration", s.iteration},
                     {"z_ws", s.z_ws_mm},
                     {"fz", s.fz_N},
                     {"dfz_dz", s.dfz_dz_N_per_mm}});
  if (!trace.empty()) j["vertical_force_iterations"] = std::move(trace);
  nlohmann::json patches = nlohmann::json::array();
  for (const WheelRailPatch& w : solution.patches) {
    const Totals& t = w.solution.totals;
    const Statistics& s = w.solution.statistics;
    patches.push_back({
        {"reference_tr", vec(w.reference_tr)},
        {"contact_angle", w.contact_angle_rad},
        {"reference_rail", nlohmann::json::array({w.y_rail_mm, w.z_rail_mm})},
        {"reference_wheel", vec(w.reference_wheel)},
        {"creepages", {{"xi", w.xi}, {"eta", w.eta}, {"phi", w.phi_per_mm}}},
        {"rolling", {{"chi", w.chi_rad}, {"dq", w.dq_mm}, {"veloc", w.veloc_mm_s}}},
        {"grid",
         {{"dx", w.dx_mm},
          {"ds", w.ds_mm},
          {"mx", w.solution.grid.mx},
          {"my", w.solution.grid.my}}},
        {"force_tr", vec(w.force_tr)},
        {"force_ws", vec(w.force_ws)},
        {"fn", t.fn},
        {"fx", t.fx},
        {"fs", t.fy},
        {"mn", t.mz},
        {"pen", t.pen},
        {"pmax", t.pmax},
        {"elastic_energy", t.elastic_energy},
        {"frictional_power", t.frictional_power},
        {"statistics", {{"npot", s.npot}, {"ncon", s.ncon}, {"nadh", s.nadh}, {"nslip", s.nslip}}},
        {"converged", w.solution.solver.converged},
    });
    if (w.conformal.active) {  // D=4: the planar (bar) forces above, the curved frame here
      const ConformalPatch& c = w.conformal;
      patches.back()["fn"] = c.bar_fn;
      patches.back()["fx"] = c.bar_fx;
      patches.back()["fs"] = c.bar_fs;
      patches.back()["mn"] = c.moment_planar.z;
      nlohmann::json conformal = {
          {"tilde_fn", c.tilde_fn},
          {"tilde_fx", c.tilde_fx},
          {"tilde_fs", c.tilde_fs},
          {"moments_planar", vec(c.moment_planar)},
          {"row_y", c.row_y_mm},
          {"row_z", c.row_z_mm},
          {"row_alpha", c.row_alpha_rad},
          {"row0_s", c.row0_s_mm},
          {"contact_rows", nlohmann::json::array({c.contact_row_first, c.contact_row_last})},
      };
      if (!c.row_friction.empty()) conformal["row_friction"] = c.row_friction;
      patches.back()["conformal"] = std::move(conformal);
    }
    if (identity.digits.h >= 1) {  // flash temperatures of the patch [°C]
      patches.back()["max_temp1"] = t.max_temp1;
      patches.back()["max_temp2"] = t.max_temp2;
    }
  }
  j["patches"] = std::move(patches);
  if (!solution.warnings.empty()) j["warnings"] = solution.warnings;
  return j;
}

nlohmann::json case_error_to_json(const CaseRecord& problem, const std::string& message) {
  nlohmann::json j = case_identity(problem);
  j["status"] = "error";
  j["message"] = message;
  return j;
}

nlohmann::json results_document(const std::string& input_name, nlohmann::json cases) {
  // Always an array: a single case object is wrapped, null becomes empty.
  if (cases.is_null()) {
    cases = nlohmann::json::array();
  } else if (!cases.is_array()) {
    cases = nlohmann::json::array({std::move(cases)});
  }
  nlohmann::json doc;
  doc["program"] = "rollcontact";
  doc["version"] = version_string;
  doc["input"] = input_name;
  doc["cases"] = std::move(cases);
  return doc;
}

}  // namespace rollcontact::format
