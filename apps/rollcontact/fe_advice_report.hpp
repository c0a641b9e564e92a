#pragma once
// What `rollcontact fe-advice` computed, and its text table and JSON.

#include <string>
#include <vector>

#include "rollcontact/fe_advice.hpp"

namespace rollcontact::cli {

/// One penalty factor: eqs 6–10, the oscillator at Δt_calc and, optionally, the layer contact.
struct FeAdviceRow {
  fe_advice::StabilityAdvice advice;
  fe_advice::OscillatorRun oscillator;  ///< the penalty oscillator run at Δt_calc
  fe_advice::NormalContactResult layered;
};

struct FeAdviceReport {
  fe_advice::FeContactSettings settings;
  fe_advice::NormalContactCase contact;
  bool with_pressure = true;
  fe_advice::NormalContactResult exact;  ///< the contact without layer
  std::vector<FeAdviceRow> rows;
  double boundary_undamped = 0.0;  ///< α where Δt_calc = Δt_cont of eq 8
  double boundary_damped = 0.0;    ///< the same with eq 9
};

std::string format_fe_advice_text(const FeAdviceReport& report);
std::string format_fe_advice_json(const FeAdviceReport& report);

}  // namespace rollcontact::cli
