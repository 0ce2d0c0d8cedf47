# PacText's own check, included by ConsoleProgramCheck.cmake: the scripted Pac 0 eats, its count
# of food inside ends above zero.
execute_process(COMMAND ${PROGRAM} --steps 1500 --every 1500 --eat OUTPUT_VARIABLE eat
                RESULT_VARIABLE status)
if(NOT status EQUAL 0 OR NOT eat MATCHES "^1500 [0-9.-]+ [0-9.-]+ [1-9]")
  message(FATAL_ERROR "PacText --eat should end with food inside Pac 0: ${eat}")
endif()
