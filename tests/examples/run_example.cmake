# Script mode: run EXAMPLE with ARGS and --out OUT, then CHECKER on OUT/FILE. Either failing fails
# the test, with both outputs shown. The example's last stdout line must be a JSON object (CMake's
# own parser) and every XDMF sidecar in OUT must pass `xmllint --noout` (libxml2): parsers
# independent of spar's writers and of the tests' own XML reader. Without xmllint the sidecars are
# not checked, and the log says so.
file(REMOVE_RECURSE ${OUT})
execute_process(COMMAND ${EXAMPLE} ${ARGS} --out ${OUT} RESULT_VARIABLE status OUTPUT_VARIABLE out
                ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "the example failed (${status}):\n${out}\n${err}")
endif()
string(STRIP "${out}" stripped)
string(REGEX REPLACE "^.*\n" "" last_line "${stripped}")
string(JSON type ERROR_VARIABLE json_error TYPE "${last_line}")
if(json_error OR NOT type STREQUAL "OBJECT")
  message(FATAL_ERROR "the example's last stdout line is not a JSON object (${json_error}):\n${last_line}")
endif()
file(GLOB sidecars ${OUT}/*.xmf ${OUT}/*.xdmf)
if(sidecars AND NOT XMLLINT)
  message(FATAL_ERROR "xmllint not found, so the XDMF sidecars cannot be checked: install libxml2-utils "
                      "(scripts/setup.sh --test)")
elseif(sidecars)
  execute_process(COMMAND ${XMLLINT} --noout ${sidecars} RESULT_VARIABLE status ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "an XDMF sidecar is not well-formed XML (xmllint):\n${err}")
  endif()
endif()
execute_process(COMMAND ${CHECKER} ${OUT}/${FILE} RESULT_VARIABLE status OUTPUT_VARIABLE out)
message(STATUS "${out}")
if(NOT status EQUAL 0)
  message(FATAL_ERROR "check_results failed")
endif()
