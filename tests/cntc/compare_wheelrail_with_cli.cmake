# Builds a one-case module-1 .inp (Manchester benchmark A-2.2, y = 3 mm, yaw 7.2 mrad, C1 =
# SIDE) next to copies of the profiles, runs `rollcontact run` on it and requires the C client
# to give the same totals and patch-1 forces: the report's values are CONTACT's output
# convention (track coordinates, a left wheel's FS and MN as CONTACT prints them), and so are
# the library's.
if(NOT EXISTS ${EXAMPLES}/MBench_UIC60_v3.prr)
  message(STATUS "CONTACT examples not found at ${EXAMPLES}: skipped")
  return()
endif()
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
file(COPY ${EXAMPLES}/MBench_UIC60_v3.prr ${EXAMPLES}/MBench_S1002_v3.prw DESTINATION ${WORK_DIR})
file(WRITE ${WORK_DIR}/case.inp
" 1 MODULE
 ${SIDE}203100    C-P-B-T-N-F-S
 0022033    V-L-D-C-M-Z-E
 0000321    H-G-I-A-O-W-R
    999     100    30    1     1e-5
  0.300   0.300
  0.280   0.280   82000.  82000.
  0.200   0.200   1.000   90d   8.0   4.0
   14.0     0    1435.0   0.000
  'MBench_UIC60_v3.prr'   0     1.0   0.0
     0.0    0.0   0.000   0.0   0.0   0.000
  1360.0  -70.0   460.0
  'MBench_S1002_v3.prw'   0     1.0   0.0
  0.0  3.0  10000. -0.00018030 0.0072  0.0
 2000. 0.0    0.0   0.0        0.0  -4.34515030
 0 MODULE
")
execute_process(COMMAND ${CLI} run -q ${WORK_DIR}/case.inp RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "rollcontact run failed (${rc})")
endif()
file(READ ${WORK_DIR}/case.json json)
string(JSON fx GET "${json}" cases 0 force_tr 0)
string(JSON fy GET "${json}" cases 0 force_tr 1)
string(JSON fz GET "${json}" cases 0 force_tr 2)
string(JSON npatch LENGTH "${json}" cases 0 patches)
string(JSON fn1 GET "${json}" cases 0 patches 0 fn)
string(JSON fx1 GET "${json}" cases 0 patches 0 fx)
string(JSON fs1 GET "${json}" cases 0 patches 0 fs)
string(JSON mn1 GET "${json}" cases 0 patches 0 mn)
set(expected ${fx} ${fy} ${fz} ${npatch} ${fn1} ${fx1} ${fs1} ${mn1})
execute_process(COMMAND ${CLIENT} ${SIDE} ${WORK_DIR} ${expected} WORKING_DIRECTORY ${WORK_DIR}
                OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
message(STATUS "rollcontact run: ${expected}")
message(STATUS "C client:        ${out}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "C client (side ${SIDE}) failed (${rc}): ${err}")
endif()
