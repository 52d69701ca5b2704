# SPAR_SOURCE_REVISION: the source revision every results file records as `spar_revision`
# (docs/output.md, "Schema and provenance"): `git describe --always --dirty` of the source tree
# when CMake configures the build ("-dirty": files had changed), or "unknown" where the sources
# are no git checkout of their own (a release archive, even one unpacked inside another
# repository) or git is missing. Only lib/output's provenance object is compiled with it.
set(SPAR_SOURCE_REVISION unknown)
find_package(Git QUIET)
if(GIT_FOUND)
  execute_process(COMMAND ${GIT_EXECUTABLE} rev-parse --show-toplevel
                  WORKING_DIRECTORY ${PROJECT_SOURCE_DIR} OUTPUT_VARIABLE spar_git_top
                  RESULT_VARIABLE spar_git_status OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  file(REAL_PATH "${PROJECT_SOURCE_DIR}" spar_source_dir)
  if(spar_git_status EQUAL 0 AND spar_git_top)
    file(REAL_PATH "${spar_git_top}" spar_git_top)
  endif()
  if(spar_git_status EQUAL 0 AND spar_git_top STREQUAL spar_source_dir)
    execute_process(COMMAND ${GIT_EXECUTABLE} describe --always --dirty
                    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR} OUTPUT_VARIABLE spar_git_describe
                    RESULT_VARIABLE spar_git_status OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
    if(spar_git_status EQUAL 0 AND spar_git_describe)
      set(SPAR_SOURCE_REVISION ${spar_git_describe})
    endif()
  endif()
endif()
message(STATUS "spar ${PROJECT_VERSION}, source revision ${SPAR_SOURCE_REVISION}")
