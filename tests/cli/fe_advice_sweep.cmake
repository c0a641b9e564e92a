# `rollcontact fe-advice --sweep` reproduces the paper's stability boundary (issue 17, item 4):
# with the paper's mesh — 1 mm contact elements and the calculation step of its smallest element,
# 0.018 µs (docs/fe-advice.md: inferred from the paper's VDC study, equivalently a 0.12 mm
# element) — penalty factors up to 102.4 are stable and 204.8, 409.6 unstable by eq 10 with
# the eq 8 contact step; bad values exit with status 2.
# Arguments: -DCLI=<rollcontact>.

function(fe_advice_json out)
  execute_process(COMMAND ${CLI} fe-advice --sweep --json ${ARGN} RESULT_VARIABLE rc
                  OUTPUT_VARIABLE json ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "fe-advice ${ARGN} failed (${rc}): ${err}")
  endif()
  set(${out} "${json}" PARENT_SCOPE)
endfunction()

foreach(mesh "--dt-calc;0.018" "--smallest-element;0.12")
  fe_advice_json(json ${mesh})
  string(JSON boundary GET "${json}" stability_boundary penalty_factor_eq8)
  if(NOT (boundary GREATER 102.4 AND boundary LESS 204.8))
    message(FATAL_ERROR "${mesh}: the eq 8 stability boundary alpha = ${boundary}, not in (102.4, 204.8)")
  endif()
  string(JSON n LENGTH "${json}" rows)
  math(EXPR last "${n} - 1")
  foreach(i RANGE ${last})
    string(JSON alpha GET "${json}" rows ${i} penalty_factor)
    string(JSON stable GET "${json}" rows ${i} stable_eq8)
    if(alpha LESS boundary AND NOT stable)
      message(FATAL_ERROR "${mesh}: alpha = ${alpha} below the boundary but UNSTABLE")
    elseif(alpha GREATER boundary AND stable)
      message(FATAL_ERROR "${mesh}: alpha = ${alpha} above the boundary but stable")
    endif()
  endforeach()
  # The pressure error vanishes with α: pmax with the layer within 0.5 % at α = 409.6.
  string(JSON ratio GET "${json}" rows ${last} pmax_ratio)
  if(ratio LESS 0.995 OR ratio GREATER 1.0)
    message(FATAL_ERROR "${mesh}: pmax ratio at alpha = 409.6 is ${ratio}")
  endif()
  message(STATUS "${mesh}: stable up to alpha = ${boundary} (eq 8)")
endforeach()

# The text table says the same words.
execute_process(COMMAND ${CLI} fe-advice -a 102.4 -a 204.8 --dt-calc 0.018 --no-pressure
                RESULT_VARIABLE rc OUTPUT_VARIABLE text)
if(NOT rc EQUAL 0 OR NOT text MATCHES "102.4[^\n]* stable " OR NOT text MATCHES "204.8[^\n]* UNSTABLE")
  message(FATAL_ERROR "fe-advice text table (${rc}):\n${text}")
endif()

foreach(bad "--element-size;0" "--element-size;-1" "--curvatures;0;1e-3" "-a;-0.1" "--vdc;-10"
        "--poisson;0.5" "--dt-calc;-1" "--density;0")
  execute_process(COMMAND ${CLI} fe-advice ${bad} RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
  if(NOT rc EQUAL 2 OR NOT err MATCHES "error")
    message(FATAL_ERROR "fe-advice ${bad}: exit ${rc} (expected 2), stderr: ${err}")
  endif()
endforeach()
