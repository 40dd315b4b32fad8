# Run PROGRAM (which writes OUTPUT and exits non-zero on a failed check),
# then compare OUTPUT with REFERENCE by numdiff with tolerances.
execute_process(COMMAND ${PROGRAM} ${OUTPUT} RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${PROGRAM} failed with status ${status}")
endif()
execute_process(COMMAND ${NUMDIFF} -q -s " \t\n," -r 1e-4 -a 1e-12 ${OUTPUT} ${REFERENCE}
  RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  execute_process(COMMAND ${NUMDIFF} -s " \t\n," -r 1e-4 -a 1e-12 ${OUTPUT} ${REFERENCE})
  message(FATAL_ERROR "${OUTPUT} differs from ${REFERENCE}")
endif()
