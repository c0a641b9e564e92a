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
