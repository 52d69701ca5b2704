# spar_add_module(NAME <lie|iga|...> SOURCES ... DEPENDS ...)
# Declares one module library `spar_<name>` with the alias `spar::<name>`, its public headers in
# <folder>/include, and the project's warning flags.
function(spar_add_module)
  cmake_parse_arguments(ARG "" "NAME;EXPORT" "SOURCES;DEPENDS" ${ARGN})
  set(target spar_${ARG_NAME})
  if(ARG_SOURCES)
    add_library(${target} ${ARG_SOURCES})
    set(scope PUBLIC)
    target_link_libraries(${target} PRIVATE $<BUILD_INTERFACE:spar_warnings>)
  else()
    add_library(${target} INTERFACE)
    set(scope INTERFACE)
  endif()
  add_library(spar::${ARG_NAME} ALIAS ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${ARG_NAME} OUTPUT_NAME spar_${ARG_NAME})
  target_include_directories(${target} ${scope}
    $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_link_libraries(${target} ${scope} spar_base ${ARG_DEPENDS})
  set_property(GLOBAL APPEND PROPERTY SPAR_MODULES ${target})
  install(DIRECTORY include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endfunction()
