# Script mode: the largest count OPTION accepts is read from EXAMPLE's --help ("[low, high]",
# examples::element_limit: the example's measured memory per element in half the physical memory,
# so it differs from machine to machine); then EXAMPLE OPTION high+1 must end at once with exit
# status 1 and a message that gives the memory the run would need (issue 29: at the former bound,
# 126380 here, four examples ended in std::bad_alloc or KLU's "out of memory").
execute_process(COMMAND ${EXAMPLE} --help RESULT_VARIABLE status OUTPUT_VARIABLE help ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "--help failed (${status}):\n${help}\n${err}")
endif()
string(REGEX MATCH "  ${OPTION} [^\n]*\\[([0-9]+), ([0-9]+)\\]" line "${help}")
if(NOT line)
  message(FATAL_ERROR "--help lists no range [low, high] for ${OPTION}:\n${help}")
endif()
set(high ${CMAKE_MATCH_2})
math(EXPR beyond "${high} + 1")
message(STATUS "${OPTION}: at most ${high} on this machine; trying ${beyond}")
execute_process(COMMAND ${EXAMPLE} ${OPTION} ${beyond} --out ${OUT} RESULT_VARIABLE status OUTPUT_VARIABLE out
                ERROR_VARIABLE err TIMEOUT 60)
if(NOT status EQUAL 1)
  message(FATAL_ERROR "${OPTION} ${beyond} was not refused (exit status ${status}):\n${out}\n${err}")
endif()
if(NOT err MATCHES "'${beyond}' elements would need about [0-9.e+]+ GB of memory \\([0-9.e+]+ kB per element")
  message(FATAL_ERROR "${OPTION} ${beyond} was refused without the memory it would need:\n${err}")
endif()
message(STATUS "${err}")
