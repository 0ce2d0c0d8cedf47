# Checks a console example program (SpherusText, PacText, IunctusText), invoked by CTest as
#   cmake -DPROGRAM=<path> -DARGS=<extra arguments> -DLINE=<regex of the line of step 10>
#         -DCOUNT=<its object-count option> [-DSCRIPT=<further checks>] -P ConsoleProgramCheck.cmake
# It runs 500 steps printing every 10th, twice with one seed and once with another: one line per
# printed step, the same seed prints the same lines and another seed others. A bad option fails
# with status 2 naming it; an unusable --svg directory and an object count the arena cannot hold
# fail at the start. SCRIPT, if given, is included last for the program's own checks.
separate_arguments(ARGS UNIX_COMMAND "${ARGS}")
foreach(run a b)
  execute_process(COMMAND ${PROGRAM} --steps 500 --every 10 --seed 3 ${ARGS}
                  OUTPUT_VARIABLE out_${run} RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${PROGRAM} ${ARGS} failed: ${status}")
  endif()
endforeach()
execute_process(COMMAND ${PROGRAM} --steps 500 --every 10 --seed 4 ${ARGS} OUTPUT_VARIABLE out_c)
string(REGEX MATCHALL "\n" newlines "${out_a}")
list(LENGTH newlines lines)
if(NOT lines EQUAL 50)
  message(FATAL_ERROR "expected 50 lines (one per printed step), got ${lines}")
endif()
if(NOT out_a STREQUAL out_b)
  message(FATAL_ERROR "the same seed printed different lines")
endif()
if(out_a STREQUAL out_c)
  message(FATAL_ERROR "another seed printed the same lines")
endif()
string(REGEX MATCH "^${LINE}\n" first "${out_a}")
if(first STREQUAL "")
  message(FATAL_ERROR "the first line does not match '${LINE}': ${out_a}")
endif()

foreach(bad "--steps;nope" "--solver;nope" "--bogus;1" "${COUNT}")
  execute_process(COMMAND ${PROGRAM} ${bad} RESULT_VARIABLE status ERROR_VARIABLE message
                  OUTPUT_QUIET)
  list(GET bad 0 option)
  if(NOT status EQUAL 2 OR NOT message MATCHES "${option}")
    message(FATAL_ERROR "'${bad}' should fail with status 2 naming ${option}: ${message}")
  endif()
endforeach()

# Refused at the start, before any step: an --svg directory that cannot be created (under a
# file), and more objects than the arena can hold (decided up front, not after a long search).
execute_process(COMMAND ${PROGRAM} --steps 1 --svg "${PROGRAM}/pictures" --svg-every 1000
                RESULT_VARIABLE status ERROR_VARIABLE message OUTPUT_QUIET)
if(NOT status EQUAL 1 OR NOT message MATCHES "--svg: cannot create the directory")
  message(FATAL_ERROR "an --svg directory under a file should fail at the start: ${message}")
endif()
execute_process(COMMAND ${PROGRAM} --steps 1 ${COUNT} 100000 RESULT_VARIABLE status
                ERROR_VARIABLE message OUTPUT_QUIET TIMEOUT 10)
if(NOT status EQUAL 1 OR NOT message MATCHES "do not fit in the arena \\(at most [0-9]+")
  message(FATAL_ERROR "${COUNT} 100000 should be refused up front: ${status} ${message}")
endif()

if(SCRIPT)
  include(${SCRIPT})
endif()
