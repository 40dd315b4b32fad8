# Determinism: the scene PRM (with APPEND appended) run twice on NP ranks
# ends in the same state, bit for bit (checkpoint_diff DIFF with tolerance
# 0: every field, history and ledger entry), with the same history.csv.
file(REMOVE_RECURSE ${WORKDIR})
file(MAKE_DIRECTORY ${WORKDIR})
file(READ ${PRM} scene)
file(READ ${APPEND} extra)
foreach(run first second)
  file(WRITE ${WORKDIR}/${run}.prm "${scene}\n${extra}
subsection Output
  set Directory = ${run}
end
subsection Checkpoint
  set Every n steps = 1000000
end
")
  execute_process(COMMAND ${MPIEXEC} --allow-run-as-root --oversubscribe
      -np ${NP} ${AMFRAC} ${run}.prm
    WORKING_DIRECTORY ${WORKDIR} RESULT_VARIABLE status
    OUTPUT_FILE ${WORKDIR}/${run}.log ERROR_FILE ${WORKDIR}/${run}.err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "run ${run} failed: ${status}")
  endif()
endforeach()
execute_process(COMMAND ${DIFF} first/checkpoints second/checkpoints 0
  WORKING_DIRECTORY ${WORKDIR} RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "two runs of the same input end in different states")
endif()
execute_process(COMMAND ${NUMDIFF} -q -s " \t\n," -r 0 -a 0
    ${WORKDIR}/first/history.csv ${WORKDIR}/second/history.csv
  RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "two runs of the same input write different histories")
endif()
