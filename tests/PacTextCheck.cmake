# Runs PacText twice with one seed and once with another, with each solver; checks the line
# count and format, that the same seed gives the same output and another seed another; then
# the scripted eater (--eat), and that a bad option fails with status 2 naming it.
# Invoked by CTest with -DPROGRAM=<path of PacText>.
foreach(solver baraff gauss-seidel)
  foreach(run a b)
    execute_process(COMMAND ${PROGRAM} --steps 500 --every 10 --seed 3 --solver ${solver}
                    OUTPUT_VARIABLE out_${run} RESULT_VARIABLE status)
    if(NOT status EQUAL 0)
      message(FATAL_ERROR "PacText --solver ${solver} failed: ${status}")
    endif()
  endforeach()
  execute_process(COMMAND ${PROGRAM} --steps 500 --every 10 --seed 4 --solver ${solver}
                  OUTPUT_VARIABLE out_c)
  string(REGEX MATCHALL "\n" newlines "${out_a}")
  list(LENGTH newlines lines)
  if(NOT lines EQUAL 50)
    message(FATAL_ERROR "expected 50 lines (one per printed step), got ${lines}")
  endif()
  if(NOT out_a STREQUAL out_b)
    message(FATAL_ERROR "the same seed printed different lines (${solver})")
  endif()
  if(out_a STREQUAL out_c)
    message(FATAL_ERROR "another seed printed the same lines (${solver})")
  endif()
  string(REGEX MATCH "^10 [0-9.-]+ [0-9.-]+ [0-9]+ [0-9.-]+ [0-9.-]+ [0-9]+\n" first "${out_a}")
  if(first STREQUAL "")
    message(FATAL_ERROR "lines are not 'step x0 y0 n0 x1 y1 n1': ${out_a}")
  endif()
endforeach()

# The scripted Pac 0 eats: its count of food inside ends above zero.
execute_process(COMMAND ${PROGRAM} --steps 1500 --every 1500 --eat OUTPUT_VARIABLE eat
                RESULT_VARIABLE status)
if(NOT status EQUAL 0 OR NOT eat MATCHES "^1500 [0-9.-]+ [0-9.-]+ [1-9]")
  message(FATAL_ERROR "PacText --eat should end with food inside Pac 0: ${eat}")
endif()

foreach(bad "--steps;nope" "--solver;nope" "--bogus;1" "--food")
  execute_process(COMMAND ${PROGRAM} ${bad} RESULT_VARIABLE status ERROR_VARIABLE message
                  OUTPUT_QUIET)
  list(GET bad 0 option)
  if(NOT status EQUAL 2 OR NOT message MATCHES "${option}")
    message(FATAL_ERROR "'${bad}' should fail with status 2 naming ${option}: ${message}")
  endif()
endforeach()
