# Configure, build and run tests/package against amfrac's build tree.
file(REMOVE_RECURSE ${WORKDIR})
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE} -B ${WORKDIR}
    -Damfrac_DIR=${AMFRAC_DIR} -DCMAKE_BUILD_TYPE=${BUILD_TYPE}
  RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "configuring a user program with find_package(amfrac) failed")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORKDIR} RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "building the user program failed")
endif()
execute_process(COMMAND ${WORKDIR}/user_program RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "the user program failed")
endif()
