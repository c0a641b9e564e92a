# Outputs never replace an input (exit status 2, the inputs unchanged, nothing run):
#  - `run x.inp x.json`: x.inp's JSON would be x.json (another input of the same run);
#  - `run x.inp x.toml`: both write x.out and x.json;
#  - a profile named like an output of its own run (wr.inp reading the rail profile wr.out);
#  - `convert x.inp link.toml` where link.toml is a link to x.inp.
# Arguments: -DCLI=<rollcontact> -DEXAMPLES=<repository examples folder> -DWORK=<scratch folder>.

file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
file(COPY "${EXAMPLES}/hertz_normal.inp" DESTINATION "${WORK}")
file(RENAME "${WORK}/hertz_normal.inp" "${WORK}/x.inp")
file(WRITE "${WORK}/x.json" "{\"keep\": true}\n")
file(COPY "${EXAMPLES}/toml/hertz_normal.toml" DESTINATION "${WORK}")
file(RENAME "${WORK}/hertz_normal.toml" "${WORK}/x.toml")

function(expect_refused what message)
  execute_process(COMMAND ${ARGN} WORKING_DIRECTORY "${WORK}" RESULT_VARIABLE rc
                  OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 2)
    message(FATAL_ERROR "${what}: exit status ${rc}, expected 2\n${out}\n${err}")
  endif()
  if(NOT err MATCHES "${message}")
    message(FATAL_ERROR "${what}: the message does not say \"${message}\":\n${err}")
  endif()
  if(EXISTS "${WORK}/x.out")
    message(FATAL_ERROR "${what}: a report was written")
  endif()
endfunction()

expect_refused("run x.inp x.json" "writes its outputs to .*x.out and .json as well" ${CLI} run -q
               x.inp x.json)
file(READ "${WORK}/x.json" json)
if(NOT json STREQUAL "{\"keep\": true}\n")
  message(FATAL_ERROR "run x.inp x.json replaced x.json")
endif()
file(REMOVE "${WORK}/x.json")
expect_refused("run x.inp x.toml" "writes its outputs to .*x.out" ${CLI} run -q x.inp x.toml)

# A rail profile (a plain table, a 300 mm arc) named wr.out, read by wr.inp.
set(table "")
foreach(k RANGE 0 60)
  math(EXPR y "${k} - 30")
  math(EXPR z "${y} * ${y} * 100000 / 600")  # z = y²/600 mm, in units of 1e-5 mm
  string(APPEND table "${y} ${z}e-5\n")
endforeach()
file(WRITE "${WORK}/wr.out" "${table}")
file(READ "${EXAMPLES}/massless_rail.inp" inp)
string(REPLACE "'profiles/MBench_UIC60_v3.prr'" "'wr.out'" inp "${inp}")
string(REPLACE "'profiles/MBench_S1002_v3.prw'" "'${EXAMPLES}/profiles/MBench_S1002_v3.prw'" inp
       "${inp}")
file(WRITE "${WORK}/wr.inp" "${inp}")
expect_refused("a profile named like an output" "would replace the input wr.out" ${CLI} run -q
               wr.inp)
file(READ "${WORK}/wr.out" after)
if(NOT after STREQUAL table)
  message(FATAL_ERROR "the profile wr.out was replaced")
endif()

# convert onto a profile the cases read (a plain table named railprof.toml).
file(WRITE "${WORK}/railprof.toml" "${table}")
string(REPLACE "'wr.out'" "'railprof.toml'" inp "${inp}")
file(WRITE "${WORK}/wr2.inp" "${inp}")
expect_refused("convert onto a profile" "is the file .*railprof.toml that the cases read" ${CLI}
               convert -q wr2.inp railprof.toml)
file(READ "${WORK}/railprof.toml" after)
if(NOT after STREQUAL table)
  message(FATAL_ERROR "convert replaced the profile railprof.toml")
endif()

# A profile that is a link to the JSON the run would write (rail.txt -> wr3.json).
file(WRITE "${WORK}/wr3.json" "${table}")
file(CREATE_LINK "${WORK}/wr3.json" "${WORK}/rail.txt" SYMBOLIC)
string(REPLACE "'railprof.toml'" "'rail.txt'" inp "${inp}")
file(WRITE "${WORK}/wr3.inp" "${inp}")
expect_refused("a profile linked to an output" "would replace the input rail.txt" ${CLI} run -q
               wr3.inp)
file(READ "${WORK}/wr3.json" after)
if(NOT after STREQUAL table)
  message(FATAL_ERROR "the run replaced the profile behind rail.txt")
endif()

file(CREATE_LINK "${WORK}/x.inp" "${WORK}/link.toml" SYMBOLIC)
file(READ "${WORK}/x.inp" before)
expect_refused("convert onto a link to the input" "is the input x.inp itself" ${CLI} convert -q
               x.inp link.toml)
file(READ "${WORK}/x.inp" after)
if(NOT after STREQUAL before)
  message(FATAL_ERROR "convert replaced its input through a link")
endif()
file(REMOVE_RECURSE "${WORK}")
