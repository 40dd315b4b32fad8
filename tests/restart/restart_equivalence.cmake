# Restart equivalence: run the scene PRM (with the file APPEND appended,
# then APPEND_MORE if given)
# once to the end, and once stopped after step STOP (Checkpoint/Stop after
# step, exit status 75) and resumed with `amfrac --resume`; the final
# checkpoints (every field, every history, the ledger) must agree to
# relative RTOL entry by entry (DIFF: checkpoint_diff), and so must
# history.csv and, with ADAPTIVITY, adaptivity.csv (to RTOL, and absolute
# ABSOLUTE for columns of round-off such as the energy balance error). COPY:
# a file copied next to the written scenes. NP ranks run the whole
# run and the first part, RESUME_NP (default NP) the resumed part.
#
# STAGE splits the work in two ctest tests when NP and RESUME_NP differ
# (amfrac_restart_test in CMakeLists.txt), so that no test holds a
# processor it leaves idle: "runs" runs the whole run and the first part
# (a test that takes NP processors), "resume" resumes and compares (one
# that takes RESUME_NP); without STAGE all of it runs here.
if(NOT NP)
  set(NP 1)
endif()
if(NOT ABSOLUTE)
  set(ABSOLUTE 1e-300)
endif()
if(NOT RESUME_NP)
  set(RESUME_NP ${NP})
endif()

function(amfrac_run np expected log)
  execute_process(COMMAND ${MPIEXEC} --allow-run-as-root --oversubscribe
      -np ${np} ${AMFRAC} ${ARGN}
    WORKING_DIRECTORY ${WORKDIR} RESULT_VARIABLE status
    OUTPUT_FILE ${WORKDIR}/${log} ERROR_FILE ${WORKDIR}/${log}.err)
  if(NOT status EQUAL expected)
    file(READ ${WORKDIR}/${log}.err err)
    message(FATAL_ERROR
      "amfrac ${ARGN}: exit status ${status}, expected ${expected}\n${err}")
  endif()
endfunction()

if(NOT STAGE STREQUAL "resume")
file(REMOVE_RECURSE ${WORKDIR})
file(MAKE_DIRECTORY ${WORKDIR})
# COPY: a file the scene names relative to itself (a Geometry/Mesh file).
if(COPY)
  file(COPY ${COPY} DESTINATION ${WORKDIR})
endif()
file(READ ${PRM} scene)
if(APPEND)
  file(READ ${APPEND} extra)
  set(scene "${scene}\n${extra}")
endif()
# A second file after the first.
if(APPEND_MORE)
  file(READ ${APPEND_MORE} more)
  set(scene "${scene}\n${more}")
endif()
foreach(run whole split)
  set(stop "")
  if(run STREQUAL split)
    set(stop "  set Stop after step = ${STOP}\n")
  endif()
  file(WRITE ${WORKDIR}/${run}.prm "${scene}
subsection Output
  set Directory = ${run}
end
subsection Checkpoint
  set Every n steps = 1000000
${stop}end
")
endforeach()

amfrac_run(${NP} 0 whole.log whole.prm)
amfrac_run(${NP} 75 split.log split.prm)
# EXPECT_FIRST: what the first part must have done before the stop (a
# remeshing), so that the resume starts from that state.
if(EXPECT_FIRST)
  file(READ ${WORKDIR}/split.log first_part)
  if(NOT first_part MATCHES "${EXPECT_FIRST}")
    message(FATAL_ERROR "the first part never printed '${EXPECT_FIRST}'")
  endif()
endif()
file(WRITE ${WORKDIR}/first_part_done "")
endif()
if(STAGE STREQUAL "runs")
  return()
endif()
# Resume only a fresh first part of this amfrac: a resumed run extends
# split/, and resuming that again would compare the end with itself
# (ctest -FS, or the script run by hand twice).
if(NOT EXISTS ${WORKDIR}/first_part_done OR ${AMFRAC} IS_NEWER_THAN
    ${WORKDIR}/first_part_done)
  message(FATAL_ERROR "no fresh first part of this amfrac in ${WORKDIR}: "
    "run the test's fixture (restart/<name>_runs) first")
endif()
file(REMOVE ${WORKDIR}/first_part_done)
amfrac_run(${RESUME_NP} 0 resumed.log --resume split/checkpoints)
file(READ ${WORKDIR}/resumed.log log)
if(NOT log MATCHES "resumed from split/checkpoints/checkpoint-")
  message(FATAL_ERROR "the second part did not resume from the checkpoint")
endif()

execute_process(COMMAND ${DIFF} whole/checkpoints split/checkpoints ${RTOL}
  ${ABSOLUTE}
  WORKING_DIRECTORY ${WORKDIR} RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "the resumed run ends in another state")
endif()
set(tables history.csv)
if(ADAPTIVITY)
  list(APPEND tables adaptivity.csv)
endif()
foreach(table ${tables})
  execute_process(COMMAND ${NUMDIFF} -q -s " \t\n," -r ${RTOL} -a ${ABSOLUTE}
      ${WORKDIR}/whole/${table} ${WORKDIR}/split/${table}
    RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${table} of the resumed run differs")
  endif()
endforeach()
