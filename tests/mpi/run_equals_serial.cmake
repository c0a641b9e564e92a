# `mpirun -np P rollcontact run FILE` writes the report and JSON of a one-process run, byte for
# byte (issue 16, item 3): the sequences of FILE spread over 2 and 4 processes.
# Arguments: -DCLI=<rollcontact> -DMPIEXEC=<mpirun> -DINPUT=<file> -DWORK=<dir>.
set(ENV{OMPI_ALLOW_RUN_AS_ROOT} 1)
set(ENV{OMPI_ALLOW_RUN_AS_ROOT_CONFIRM} 1)
set(ENV{OMPI_MCA_rmaps_base_oversubscribe} 1)
file(REMOVE_RECURSE ${WORK})
get_filename_component(stem ${INPUT} NAME_WE)
execute_process(COMMAND ${CLI} run ${INPUT} -q -o ${WORK}/serial RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "serial run failed: ${rc}")
endif()
foreach(np 2 4)
  execute_process(COMMAND ${MPIEXEC} -np ${np} ${CLI} run ${INPUT} -q -o ${WORK}/mpi${np}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "mpirun -np ${np} failed (${rc}):\n${out}\n${err}")
  endif()
  foreach(ext out json)
    execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${WORK}/serial/${stem}.${ext}
                            ${WORK}/mpi${np}/${stem}.${ext} RESULT_VARIABLE diff)
    if(NOT diff EQUAL 0)
      message(FATAL_ERROR "${stem}.${ext} of ${np} MPI processes differs from the serial one")
    endif()
  endforeach()
  message(STATUS "${np} MPI processes: report and JSON identical to the serial run")
endforeach()
