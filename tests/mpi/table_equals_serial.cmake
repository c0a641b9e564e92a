# The distributed creep-force table gives the serial table's bytes (issue 16, item 3): one
# process, then 2 and 4 MPI ranks (oversubscribed on small machines), the CSV files compared.
# Arguments: -DCLI=<rollcontact> -DMPIEXEC=<mpirun> -DWORK=<dir> -DCASES=<selection>.
file(MAKE_DIRECTORY ${WORK})
# CI containers run as root; Open MPI refuses that unless told.
set(ENV{OMPI_ALLOW_RUN_AS_ROOT} 1)
set(ENV{OMPI_ALLOW_RUN_AS_ROOT_CONFIRM} 1)
set(ENV{OMPI_MCA_rmaps_base_oversubscribe} 1)

execute_process(COMMAND ${CLI} table --threads 1 -q --cases ${CASES} -o ${WORK}/serial.csv
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "serial table failed: ${rc}")
endif()
foreach(np 2 4)
  execute_process(COMMAND ${MPIEXEC} -np ${np} ${CLI} table -q --cases ${CASES}
                          -o ${WORK}/mpi${np}.csv
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "mpirun -np ${np} failed (${rc}):\n${out}\n${err}")
  endif()
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${WORK}/serial.csv ${WORK}/mpi${np}.csv
                  RESULT_VARIABLE diff)
  if(NOT diff EQUAL 0)
    message(FATAL_ERROR "the table of ${np} MPI processes differs from the serial one")
  endif()
  message(STATUS "${np} MPI processes: identical to the serial table")
endforeach()
