# Checks SpherusEvolve, invoked by CTest as
#   cmake -DPROGRAM=<SpherusEvolve> -DVIEWER=<SpherusText> -DWORK=<scratch directory> -P ...
# A short run writes its four files; the same options give the same files on 1 and 3 threads;
# half the generations then --resume give the same files as the whole run; bad options,
# mismatched or corrupt checkpoints and an unwritable --out fail with a message and a non-zero
# status, and leave the files already written as they were. Then SpherusText --genome replays
# the best controller and writes an animated SVG, and refuses bad genomes.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
set(common --population 6 --steps 200 --trials 2 --seed 5 --checkpoint-every 1)
set(files fitness.csv fitness.svg best.genome checkpoint)

function(run_ok dir)
  execute_process(COMMAND ${PROGRAM} --out ${WORK}/${dir} ${common} ${ARGN}
                  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "SpherusEvolve --out ${dir} ${ARGN} failed (${status}): ${err}")
  endif()
  set(last_output "${out}" PARENT_SCOPE)
endfunction()

function(expect_same_files a b why)
  foreach(f ${files})
    file(SHA256 ${WORK}/${a}/${f} ha)
    file(SHA256 ${WORK}/${b}/${f} hb)
    if(NOT ha STREQUAL hb)
      message(FATAL_ERROR "${why}: ${a}/${f} and ${b}/${f} differ")
    endif()
  endforeach()
endfunction()

# Fails with a non-zero status and a message matching REGEX, and leaves DIR's files unchanged.
function(run_fails dir regex)
  foreach(f ${files})
    if(EXISTS ${WORK}/${dir}/${f})
      file(SHA256 ${WORK}/${dir}/${f} before_${f})
    endif()
  endforeach()
  execute_process(COMMAND ${PROGRAM} --out ${WORK}/${dir} ${ARGN}
                  RESULT_VARIABLE status OUTPUT_QUIET ERROR_VARIABLE err)
  if(status EQUAL 0 OR NOT err MATCHES "${regex}")
    message(FATAL_ERROR "'SpherusEvolve --out ${dir} ${ARGN}' should fail saying '${regex}', "
                        "got status ${status}: ${err}")
  endif()
  foreach(f ${files})
    if(DEFINED before_${f})
      file(SHA256 ${WORK}/${dir}/${f} after)
      if(NOT after STREQUAL before_${f})
        message(FATAL_ERROR "'SpherusEvolve ${ARGN}' failed but changed ${dir}/${f}")
      endif()
    endif()
  endforeach()
endfunction()

# The whole run: the files, one CSV row per generation, the progress lines.
run_ok(whole --generations 4 --threads 1)
foreach(f ${files})
  if(NOT EXISTS ${WORK}/whole/${f})
    message(FATAL_ERROR "no ${f} written")
  endif()
endforeach()
file(STRINGS ${WORK}/whole/fitness.csv rows)
list(LENGTH rows count)
list(GET rows 0 header)
if(NOT count EQUAL 5 OR NOT header STREQUAL "generation,best,mean,best_so_far")
  message(FATAL_ERROR "fitness.csv should be a header and 4 rows: ${rows}")
endif()
if(NOT last_output MATCHES "gen 4/4  best [0-9.e+-]+  mean [0-9.e+-]+  best so far")
  message(FATAL_ERROR "no progress line for generation 4: ${last_output}")
endif()
file(READ ${WORK}/whole/fitness.svg plot)
if(NOT plot MATCHES "<polyline class=\"best\"" OR NOT plot MATCHES "</svg>")
  message(FATAL_ERROR "fitness.svg has no best line")
endif()

# The same files on three threads.
run_ok(threads --generations 4 --threads 3)
expect_same_files(whole threads "1 and 3 threads")

# Half, then resumed to the end on two threads.
run_ok(resumed --generations 2)
run_ok(resumed --generations 4 --resume --threads 2)
expect_same_files(whole resumed "a resumed run")

# Bad options: status 2, naming the option.
foreach(bad "--task;nope" "--network;rnn:3" "--trials;0" "--generations;x" "--bogus;1")
  execute_process(COMMAND ${PROGRAM} --out ${WORK}/bad ${bad} RESULT_VARIABLE status
                  ERROR_VARIABLE err OUTPUT_QUIET)
  list(GET bad 0 option)
  if(NOT status EQUAL 2 OR NOT err MATCHES "${option}")
    message(FATAL_ERROR "'${bad}' should fail with status 2 naming ${option}: ${err}")
  endif()
endforeach()

# A checkpoint from other options, a run started again over an old one, --resume without one.
run_fails(whole "population 6, not 7" ${common} --population 7 --generations 6 --resume)
run_fails(whole "task distance, not clear" ${common} --task clear --generations 6 --resume)
run_fails(whole "already holds a run" ${common} --generations 6)
run_fails(empty "no checkpoint" ${common} --generations 6 --resume)

# A corrupt or truncated checkpoint.
file(COPY ${WORK}/whole/ DESTINATION ${WORK}/corrupt)
file(READ ${WORK}/whole/checkpoint text)
string(LENGTH "${text}" length)
math(EXPR half "${length} / 2")
string(SUBSTRING "${text}" 0 ${half} truncated)
file(WRITE ${WORK}/corrupt/checkpoint "${truncated}")
run_fails(corrupt "checkpoint .*line" ${common} --generations 6 --resume)
string(REPLACE "best-fitness 1 " "best-fitness 1 zz" garbled "${text}")
file(WRITE ${WORK}/corrupt/checkpoint "${garbled}")
run_fails(corrupt "best-fitness.*not a finite number" ${common} --generations 6 --resume)

# An unwritable --out: under a regular file.
run_fails(whole/fitness.csv/sub "cannot create the directory" ${common} --generations 2)

# Watching the result: SpherusText --genome runs the evolved controller (not the random one)
# and writes the episode as an animated SVG; bad genomes are refused with status 1.
set(watch --steps 100 --every 50 --seed 3)
execute_process(COMMAND ${VIEWER} ${watch} --genome ${WORK}/whole/best.genome
                        --animation ${WORK}/episode.svg
                RESULT_VARIABLE status OUTPUT_VARIABLE evolved ERROR_VARIABLE err)
execute_process(COMMAND ${VIEWER} ${watch} OUTPUT_VARIABLE random)
if(NOT status EQUAL 0 OR NOT evolved MATCHES "^50 [0-9.-]+ [0-9.-]+\n100 [0-9.-]+ [0-9.-]+\n$")
  message(FATAL_ERROR "SpherusText --genome failed (${status}): ${err}${evolved}")
endif()
if(evolved STREQUAL random)
  message(FATAL_ERROR "SpherusText --genome moved as the random controller does")
endif()
file(READ ${WORK}/episode.svg episode)
string(REGEX MATCHALL "<g class=\"frame\"" frames "${episode}")
list(LENGTH frames frame_count)
if(NOT frame_count EQUAL 11 OR NOT episode MATCHES "<animate attributeName=\"visibility\"")
  message(FATAL_ERROR "episode.svg should have 11 animated frames (steps 1, 10, ..., 100)")
endif()

file(READ ${WORK}/whole/best.genome genome)
string(SUBSTRING "${genome}" 0 200 truncated)
file(WRITE ${WORK}/truncated.genome "${truncated}")
set(small "thyrix-genome 1\nkind feed-forward\nactivation tanh\nlayers 3 2\nparameters 8\n")
foreach(i RANGE 1 8)
  string(APPEND small "0\n")
endforeach()
file(WRITE ${WORK}/small.genome "${small}")
foreach(case "truncated.genome;truncated.genome: " "small.genome;3 inputs and 2 outputs, but the agent has 35 sensors and 5 effectors"
             "missing.genome;missing.genome: cannot be opened")
  list(GET case 0 name)
  list(GET case 1 regex)
  execute_process(COMMAND ${VIEWER} ${watch} --genome ${WORK}/${name}
                  RESULT_VARIABLE status ERROR_VARIABLE err OUTPUT_QUIET)
  if(NOT status EQUAL 1 OR NOT err MATCHES "${regex}")
    message(FATAL_ERROR "SpherusText --genome ${name} should fail saying '${regex}': ${status} ${err}")
  endif()
endforeach()

# A hand-made genome with a closed-form path: no weights, biases that fire both forward rockets
# (tanh(3) mapped to [0, 1]: 0.99753) and not the backward ones (0.00247), so in an empty arena
# each circle moves forward (+y) at (0.99753 - 0.00247) N / 1 N s/m = 0.99505 m/s. Of 200 steps
# of 0.01 s the first comes before the controller acts: y = 5 + 1.99 * 0.99505 = 6.9802.
set(forward "thyrix-genome 1\nkind feed-forward\nactivation tanh\nlayers 35 5\nparameters 180\n")
string(APPEND forward "3\n-3\n3\n-3\n0\n")
foreach(i RANGE 1 175)
  string(APPEND forward "0\n")
endforeach()
file(WRITE ${WORK}/forward.genome "${forward}")
execute_process(COMMAND ${VIEWER} --genome ${WORK}/forward.genome --objects 0 --steps 200
                        --every 200 RESULT_VARIABLE status OUTPUT_VARIABLE line)
if(NOT status EQUAL 0 OR NOT line MATCHES "^200 5\\.0000[0-9]+ 6\\.980[0-9]+\n$")
  message(FATAL_ERROR "SpherusText --genome forward.genome should end at (5, 6.980): ${line}")
endif()

# Options the arena refuses are reported before --out is created.
execute_process(COMMAND ${PROGRAM} --out ${WORK}/crowded --objects 5000 RESULT_VARIABLE status
                ERROR_VARIABLE err OUTPUT_QUIET)
if(status EQUAL 0 OR NOT err MATCHES "SpherusSimulator.objects" OR EXISTS ${WORK}/crowded)
  message(FATAL_ERROR "--objects 5000 should fail naming SpherusSimulator.objects, creating "
                      "nothing: ${status} ${err}")
endif()
