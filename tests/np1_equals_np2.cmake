# Run the scene PRM with one and with two MPI ranks and compare the
# histories with numdiff (relative 1e-8; absolute 1e-10 for round-off
# around zero).
file(REMOVE_RECURSE ${WORKDIR})
foreach(np 1 2)
  file(MAKE_DIRECTORY ${WORKDIR}/np${np})
  execute_process(COMMAND ${MPIEXEC} --allow-run-as-root --oversubscribe
      -np ${np} ${AMFRAC} ${PRM}
    WORKING_DIRECTORY ${WORKDIR}/np${np} RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "amfrac on ${np} rank(s) failed: ${status}")
  endif()
endforeach()
execute_process(COMMAND ${NUMDIFF} -q -s " \t\n," -r 1e-8 -a 1e-10
  ${WORKDIR}/np1/output/history.csv ${WORKDIR}/np2/output/history.csv
  RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "one and two ranks differ")
endif()
foreach(f solution.pvd solution-00002.pvtu solution-00002.0001.vtu)
  if(NOT EXISTS ${WORKDIR}/np2/output/${f})
    message(FATAL_ERROR "missing ${f} in the two-rank output")
  endif()
endforeach()
