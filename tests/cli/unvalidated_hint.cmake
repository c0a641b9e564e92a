# A plain `rollcontact run` refuses the wheel/rail features known to differ from CONTACT's
# references (mbench_a22_kpec cases 1 and 6) with exit status 1, names them per case and says
# how to solve them anyway; `--unvalidated` solves every case (status 0), each refused one with
# the warning in its report.
# Arguments: -DCLI=<rollcontact> -DEXAMPLES=<contact-examples folder> -DWORK=<scratch folder>.

if(NOT EXISTS "${EXAMPLES}/mbench_a22_kpec.inp")
  message("CONTACT example folder ${EXAMPLES} is absent: skipped")
  return()
endif()
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")

execute_process(COMMAND ${CLI} run "${EXAMPLES}/mbench_a22_kpec.inp" -o "${WORK}/plain"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 1)
  message(FATAL_ERROR "plain run: exit status ${rc}, expected 1 (two cases refused)")
endif()
if(NOT err MATCHES "note: 2 case\\(s\\) refused as not validated against CONTACT; `rollcontact run --unvalidated`")
  message(FATAL_ERROR "plain run: no hint on stderr:\n${err}")
endif()
if(NOT out MATCHES "case    1: ERROR [^\n]*KPEC[^\n]*not validated against CONTACT")
  message(FATAL_ERROR "plain run: case 1 not reported as refused:\n${out}")
endif()

execute_process(COMMAND ${CLI} run --unvalidated -q "${EXAMPLES}/mbench_a22_kpec.inp"
                        -o "${WORK}/unvalidated"
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "--unvalidated: exit status ${rc}, expected 0:\n${err}")
endif()
file(READ "${WORK}/unvalidated/mbench_a22_kpec.out" report)
string(REGEX MATCHALL "WARNING: not validated against CONTACT" warnings "${report}")
list(LENGTH warnings n)
if(NOT n EQUAL 2)
  message(FATAL_ERROR "--unvalidated: ${n} not-validated warnings in the report, expected 2")
endif()
file(REMOVE_RECURSE "${WORK}")
