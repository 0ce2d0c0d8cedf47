# IunctusText's own check, included by ConsoleProgramCheck.cmake: the scripted grasper runs, and
# is reproducible too.
execute_process(COMMAND ${PROGRAM} --grasp --steps 300 --every 100 OUTPUT_VARIABLE grasp_a
                RESULT_VARIABLE status)
execute_process(COMMAND ${PROGRAM} --grasp --steps 300 --every 100 OUTPUT_VARIABLE grasp_b)
if(NOT status EQUAL 0 OR NOT grasp_a STREQUAL grasp_b)
  message(FATAL_ERROR "--grasp failed or was not reproducible: ${grasp_a}")
endif()
