# Checks SpherusEvolve over MPI ranks, invoked by CTest as
#   cmake -DPROGRAM=<SpherusEvolve> -DMPIEXEC=<mpirun> -DWORK=<scratch directory> -P ...
# `mpirun -n 2` writes the same files, byte for byte, as one process (with 1 or 2 threads per
# rank); a run of 2 ranks continued by 1 process (and one of 1 continued by 2 ranks) gives the
# same files as the whole run; a rank whose task throws, or that is killed, ends the job within
# seconds with a non-zero status (THYRIX_TEST_FAIL_RANK, SpherusEvolve's hook for this test).
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
set(common --population 6 --steps 200 --trials 2 --seed 5 --checkpoint-every 1)
set(files fitness.csv fitness.svg best.genome checkpoint)
set(mpirun ${MPIEXEC} -n 2 --oversubscribe)
execute_process(COMMAND id -u OUTPUT_VARIABLE uid OUTPUT_STRIP_TRAILING_WHITESPACE)
if(uid STREQUAL "0")
  list(APPEND mpirun --allow-run-as-root)
endif()

# Runs SpherusEvolve (under @p launcher, a list, possibly empty) with --out DIR and ARGN.
function(run_ok dir launcher)
  execute_process(COMMAND ${launcher} ${PROGRAM} --out ${WORK}/${dir} ${common} ${ARGN}
                  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 300)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${launcher} SpherusEvolve --out ${dir} ${ARGN} failed (${status}): ${err}")
  endif()
  set(last_output "${out}" PARENT_SCOPE)
endfunction()

function(expect_same_files a b why)
  foreach(f ${files})
    execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${WORK}/${a}/${f} ${WORK}/${b}/${f}
                    RESULT_VARIABLE differ)
    if(NOT differ EQUAL 0)
      message(FATAL_ERROR "${why}: ${a}/${f} and ${b}/${f} differ")
    endif()
  endforeach()
endfunction()

run_ok(one "" --generations 4 --threads 1)
run_ok(ranks2 "${mpirun}" --generations 4 --threads 1)
expect_same_files(one ranks2 "2 ranks of 1 thread against 1 process")
if(NOT last_output MATCHES "rank 0: idle [0-9.]+ s of [0-9.]+ s .*rank 1: idle [0-9.]+ s of")
  message(FATAL_ERROR "no idle time per rank in the output of 2 ranks: ${last_output}")
endif()
if(NOT last_output MATCHES "between generations [^\n]*: [0-9.]+ s")
  message(FATAL_ERROR "no time between generations in the output of 2 ranks: ${last_output}")
endif()
run_ok(ranks2threads2 "${mpirun}" --generations 4 --threads 2)
expect_same_files(one ranks2threads2 "2 ranks of 2 threads against 1 process")

# Resumed with another number of ranks, both ways.
run_ok(resume1 "${mpirun}" --generations 2)
run_ok(resume1 "" --generations 4 --resume)
expect_same_files(one resume1 "2 ranks, then 1 process after --resume")
run_ok(resume2 "" --generations 2)
run_ok(resume2 "${mpirun}" --generations 4 --resume)
expect_same_files(one resume2 "1 process, then 2 ranks after --resume")

# A failing rank ends the job within seconds (the limit of 60 s only stops a hung job).
foreach(fail 1 1:kill 0)
  string(TIMESTAMP begin "%s")
  execute_process(COMMAND ${CMAKE_COMMAND} -E env THYRIX_TEST_FAIL_RANK=${fail}
                          ${mpirun} ${PROGRAM} --out ${WORK}/fail${fail} ${common} --generations 4
                  RESULT_VARIABLE status OUTPUT_QUIET ERROR_VARIABLE err TIMEOUT 60)
  string(TIMESTAMP end "%s")
  math(EXPR seconds "${end} - ${begin}")
  if(status EQUAL 0 OR NOT status MATCHES "^[0-9]+$")
    message(FATAL_ERROR "THYRIX_TEST_FAIL_RANK=${fail}: the job did not fail (${status}): ${err}")
  endif()
  if(seconds GREATER 20)
    message(FATAL_ERROR "THYRIX_TEST_FAIL_RANK=${fail}: the job took ${seconds} s to end")
  endif()
  if(NOT fail MATCHES "kill" AND NOT err MATCHES "rank ${fail}\\): THYRIX_TEST_FAIL_RANK: this rank fails on purpose")
    message(FATAL_ERROR "THYRIX_TEST_FAIL_RANK=${fail}: no message naming the rank: ${err}")
  endif()
endforeach()
