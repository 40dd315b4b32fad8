# Run the scene PRM (with SOLVER, or with the file APPEND appended, then
# APPEND_MORE if given) on one and on two MPI ranks and
# compare the histories with numdiff (relative 1e-8; absolute ABSOLUTE,
# default 1e-10, for round-off around zero); with FIELDS, check the field files too.
#
# COPY: a file copied next to the written scene (one that the scene names
# relative to itself, such as a Geometry/Mesh file).
#
# STAGE splits the work in two ctest tests (amfrac_np1_equals_np2 in
# CMakeLists.txt): "np1" writes the scene and runs it on one rank (a test
# that takes one processor), "np2" runs it on two ranks and compares (a
# test that takes two); without STAGE both run here.
if(NOT STAGE STREQUAL "np2")
file(REMOVE_RECURSE ${WORKDIR})
file(READ ${PRM} scene)
if(SOLVER)
  file(WRITE ${WORKDIR}/scene.prm "${scene}
subsection Linear solver
  set Solver    = ${SOLVER}
  set Tolerance = 1e-12
end
")
elseif(APPEND)
  file(READ ${APPEND} extra)
  # A second file after the first (APPEND_MORE).
  if(APPEND_MORE)
    file(READ ${APPEND_MORE} more)
    string(APPEND extra "\n${more}")
  endif()
  file(WRITE ${WORKDIR}/scene.prm "${scene}\n${extra}")
else()
  file(WRITE ${WORKDIR}/scene.prm "${scene}")
endif()
# A file the scene names relative to itself (a Geometry/Mesh file).
if(COPY)
  file(COPY ${COPY} DESTINATION ${WORKDIR})
endif()
endif()
if(STAGE STREQUAL "np1")
  set(ranks 1)
elseif(STAGE STREQUAL "np2")
  set(ranks 2)
  file(REMOVE_RECURSE ${WORKDIR}/np2)
  # Not a one-rank run of an older amfrac or scene (ctest -FS, or the
  # script run by hand).
  set(np1_history ${WORKDIR}/np1/output/history.csv)
  set(copy_newer FALSE)
  if(COPY)
    if("${COPY}" IS_NEWER_THAN ${np1_history})
      set(copy_newer TRUE)
    endif()
  endif()
  if(NOT EXISTS ${np1_history} OR ${AMFRAC} IS_NEWER_THAN ${np1_history}
      OR ${PRM} IS_NEWER_THAN ${np1_history} OR copy_newer)
    message(FATAL_ERROR "no one-rank run in ${WORKDIR}/np1 newer than "
      "amfrac and the scene (run its np1 stage)")
  endif()
else()
  set(ranks 1 2)
endif()
foreach(np ${ranks})
  file(MAKE_DIRECTORY ${WORKDIR}/np${np})
  execute_process(COMMAND ${MPIEXEC} --allow-run-as-root --oversubscribe
      -np ${np} ${AMFRAC} ${WORKDIR}/scene.prm
    WORKING_DIRECTORY ${WORKDIR}/np${np} RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "amfrac on ${np} rank(s) failed: ${status}")
  endif()
endforeach()
if(STAGE STREQUAL "np1")
  return()
endif()
if(NOT ABSOLUTE)
  set(ABSOLUTE 1e-10)
endif()
# Fail with COMPLAINT unless the CSV file NAME of the two runs agrees to
# relative 1e-8 (or the relative tolerance given as a third argument).
function(compare_ranks name complaint)
  set(relative 1e-8)
  if(ARGC GREATER 2)
    set(relative ${ARGV2})
  endif()
  # Columns of wall time (NAME_seconds: a remeshing's Gmsh and transfer
  # times) are no result: numdiff leaves them out (-X, fields from 1).
  file(STRINGS ${WORKDIR}/np1/output/${name} header LIMIT_COUNT 1)
  string(REPLACE "," ";" columns "${header}")
  set(exclude "")
  set(field 0)
  foreach(column ${columns})
    math(EXPR field "${field} + 1")
    if(column MATCHES "_seconds$")
      list(APPEND exclude -X 1:${field} -X 2:${field})
    endif()
  endforeach()
  execute_process(COMMAND ${NUMDIFF} -q -s " \t\n," -r ${relative} -a ${ABSOLUTE}
    ${exclude} ${WORKDIR}/np1/output/${name} ${WORKDIR}/np2/output/${name}
    RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${complaint}")
  endif()
endfunction()
compare_ranks(history.csv "one and two ranks differ")
# With crack insertion: the same insertion events. Relative 1e-6: the
# static rounds log the residual of the converged state on the split
# copies before the tractions are balanced (residual_before) and the
# largest correction, which cancel down from the forces and so carry the
# two runs' round-off magnified (measured 7e-8 relative); a different
# face or time differs in the leading digits.
if(EXISTS ${WORKDIR}/np1/output/cracks.csv)
  compare_ranks(cracks.csv "one and two ranks insert different cracks" 1e-6)
endif()
# With ADAPTIVITY (runs that adapt during a load history): the same mesh
# changes (cycle runs log their wall time there, so they are not compared;
# a remeshing's times are left out).
if(ADAPTIVITY)
  compare_ranks(adaptivity.csv "one and two ranks adapt differently")
  # ADAPTIVITY_ROWS: the mesh changes the comparison needs at least.
  if(ADAPTIVITY_ROWS)
    file(STRINGS ${WORKDIR}/np1/output/adaptivity.csv rows)
    list(LENGTH rows n)
    math(EXPR n "${n} - 1")
    if(n LESS ADAPTIVITY_ROWS)
      message(FATAL_ERROR "${n} mesh changes, ${ADAPTIVITY_ROWS} expected")
    endif()
  endif()
endif()
# With BUCKLING: the same load factors and (normalized) modes. The Lanczos
# sequence rounds differently on two ranks and stops at a residual of 1e-8,
# so a mode agrees to about that over its gap: relative 1e-6, absolute
# 1e-8, and the residual column (3) is left out.
if(BUCKLING)
  execute_process(COMMAND ${NUMDIFF} -q -s " \t\n," -r 1e-6 -a 1e-8
    -X 1:3 -X 2:3
    ${WORKDIR}/np1/output/buckling.csv ${WORKDIR}/np2/output/buckling.csv
    RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "one and two ranks buckle differently")
  endif()
endif()
if(NOT FIELDS)
  return()
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
