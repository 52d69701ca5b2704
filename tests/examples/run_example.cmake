# Script mode: run EXAMPLE with ARGS and --out OUT, then CHECKER on OUT/FILE. Either failing fails
# the test, with both outputs shown.
file(REMOVE_RECURSE ${OUT})
execute_process(COMMAND ${EXAMPLE} ${ARGS} --out ${OUT} RESULT_VARIABLE status OUTPUT_VARIABLE out
                ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "the example failed (${status}):\n${out}\n${err}")
endif()
execute_process(COMMAND ${CHECKER} ${OUT}/${FILE} RESULT_VARIABLE status OUTPUT_VARIABLE out)
message(STATUS "${out}")
if(NOT status EQUAL 0)
  message(FATAL_ERROR "check_results failed")
endif()
