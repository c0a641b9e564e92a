#include <gtest/gtest.h>

#include "format/report/json_writer.hpp"
#include "rollcontact/version.hpp"

namespace rollcontact::format {
namespace {

TEST(JsonWriter, ShiftCaseWithSolvedUnknowns) {
  format::CaseRecord p;
  p.case_number = 2;
  p.digits.t = 1;
  p.digits.f = 2;
  p.digits.n = 1;
  Solution s;
  s.totals.fn = 9.1954;
  s.totals.fx = -3.218;
  s.totals.pen = 0.01998;
  s.totals.shift_x = 0.008155;
  s.totals.creep_x = 99.0;  // not a rolling case: must not appear as creep
  s.statistics = {361, 177, 45, 132, 0, 1, 1};
  s.solver.normal_iterations = 6;
  s.solver.tangential_iterations = 59;
  s.solver.newton_iterations = 6;
  const auto j = case_to_json(p, s);
  EXPECT_EQ(j["case"], 2);
  EXPECT_EQ(j["module"], 3);
  EXPECT_EQ(j["result_element"], 1);
  EXPECT_EQ(j["patch"], 1);
  EXPECT_EQ(j["status"], "converged");
  EXPECT_EQ(j["message"], "");
  EXPECT_DOUBLE_EQ(j["totals"]["shift_x"].get<double>(), 0.008155);
  EXPECT_DOUBLE_EQ(j["totals"]["creep_x"].get<double>(), 0.0);
  EXPECT_DOUBLE_EQ(j["totals"]["pen"].get<double>(), 0.01998);
  EXPECT_EQ(j["statistics"]["nadh"], 45);
  EXPECT_EQ(j["statistics"]["nplast"], 0);
  EXPECT_EQ(j["solver"]["tangential_iterations"], 59);
  EXPECT_EQ(j["solver"]["newton_iterations"], 6);
}

TEST(JsonWriter, PrescribedValuesAndNonConvergence) {
  format::CaseRecord p;
  p.digits.t = 3;
  p.digits.n = 0;
  p.kinematics.pen = 0.05;
  p.kinematics.cksi = -2.4e-4;
  p.kinematics.cphi = 0.001;
  Solution s;
  s.solver.converged = false;
  s.solver.message = "MAXIN reached";
  const auto j = case_to_json(p, s);
  EXPECT_EQ(j["status"], "not_converged");
  EXPECT_EQ(j["message"], "MAXIN reached");
  EXPECT_DOUBLE_EQ(j["totals"]["pen"].get<double>(), 0.05);
  EXPECT_DOUBLE_EQ(j["totals"]["creep_x"].get<double>(), -2.4e-4);
  EXPECT_DOUBLE_EQ(j["totals"]["spin"].get<double>(), 0.001);
}

TEST(JsonWriter, ErrorCaseAndDocument) {
  format::CaseRecord p;
  p.case_number = 3;
  p.result_element = 4;
  const auto e = case_error_to_json(p, "file not found");
  EXPECT_EQ(e["status"], "error");
  EXPECT_EQ(e["message"], "file not found");
  EXPECT_EQ(e["result_element"], 4);
  EXPECT_FALSE(e.contains("totals"));

  const auto doc = results_document("cattaneo.inp", nlohmann::json::array({e}));
  EXPECT_EQ(doc["program"], "rollcontact");
  EXPECT_EQ(doc["version"], version_string);
  EXPECT_EQ(doc["input"], "cattaneo.inp");
  ASSERT_TRUE(doc["cases"].is_array());
  EXPECT_EQ(doc["cases"].size(), 1u);
  EXPECT_TRUE(results_document("x.inp", nlohmann::json())["cases"].is_array());
  EXPECT_EQ(results_document("x.inp", e)["cases"].size(), 1u);
}

}  // namespace
}  // namespace rollcontact::format
