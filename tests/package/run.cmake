# Configure, build and run tests/package against amfrac's build tree, or,
# with INSTALL_FROM set, against a fresh installation of it in WORKDIR.
file(REMOVE_RECURSE ${WORKDIR})
if(INSTALL_FROM)
  execute_process(COMMAND ${CMAKE_COMMAND} --install ${INSTALL_FROM}
      --prefix ${WORKDIR}/prefix
    OUTPUT_QUIET RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "cmake --install failed")
  endif()
  set(AMFRAC_DIR ${WORKDIR}/prefix/lib/cmake/amfrac)
  execute_process(COMMAND ${WORKDIR}/prefix/bin/amfrac --help
    OUTPUT_QUIET RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "the installed amfrac does not run")
  endif()
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE} -B ${WORKDIR}/build
    -Damfrac_DIR=${AMFRAC_DIR} -DCMAKE_BUILD_TYPE=${BUILD_TYPE}
  RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "configuring a user program with find_package(amfrac) failed")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORKDIR}/build RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "building the user program failed")
endif()
execute_process(COMMAND ${WORKDIR}/build/user_program RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "the user program failed")
endif()
