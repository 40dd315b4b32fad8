# Run the scene PRM with SOLVER on one and on two MPI ranks and compare the
# histories with numdiff (relative 1e-8; absolute 1e-10 for round-off
# around zero).
file(REMOVE_RECURSE ${WORKDIR})
file(READ ${PRM} scene)
file(WRITE ${WORKDIR}/scene.prm "${scene}
subsection Linear solver
  set Solver    = ${SOLVER}
  set Tolerance = 1e-12
end
")
foreach(np 1 2)
  file(MAKE_DIRECTORY ${WORKDIR}/np${np})
  execute_process(COMMAND ${MPIEXEC} --allow-run-as-root --oversubscribe
      -np ${np} ${AMFRAC} ${WORKDIR}/scene.prm
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
# Both field formats, written by two ranks, complete and free of
# temporaries.
foreach(f solution.pvd solution-00002.pvtu solution-00002.0001.vtu
    solution.xdmf solution-00002.h5)
  if(NOT EXISTS ${WORKDIR}/np2/output/${f})
    message(FATAL_ERROR "missing ${f} in the two-rank output")
  endif()
endforeach()
file(READ ${WORKDIR}/np2/output/solution.xdmf xdmf)
if(NOT xdmf MATCHES "solution-00002.h5" OR NOT xdmf MATCHES "</Xdmf>")
  message(FATAL_ERROR "solution.xdmf does not reference the step-2 HDF5 file")
endif()
file(READ ${WORKDIR}/np2/output/solution-00002.0001.vtu vtu)
if(NOT vtu MATCHES "</VTKFile>")
  message(FATAL_ERROR "a VTU piece is truncated")
endif()
file(GLOB leftovers ${WORKDIR}/np2/output/*.tmp*)
if(leftovers)
  message(FATAL_ERROR "temporary files left behind: ${leftovers}")
endif()
