# FindSuiteSparse — Debian's libsuitesparse-dev (5.x) ships no CMake package, so this small module
# finds the headers and the libraries spar uses and defines imported targets:
#   SuiteSparse::KLU  SuiteSparse::UMFPACK  SuiteSparse::CHOLMOD  (each pulls AMD, COLAMD, BTF, config)
include(FindPackageHandleStandardArgs)

find_path(SuiteSparse_INCLUDE_DIR klu.h PATH_SUFFIXES suitesparse)
foreach(lib klu umfpack cholmod amd colamd camd ccolamd btf suitesparseconfig)
  string(TOUPPER ${lib} LIB)
  find_library(SuiteSparse_${LIB}_LIBRARY ${lib})
endforeach()

find_package_handle_standard_args(SuiteSparse REQUIRED_VARS SuiteSparse_INCLUDE_DIR
  SuiteSparse_KLU_LIBRARY SuiteSparse_UMFPACK_LIBRARY SuiteSparse_CHOLMOD_LIBRARY
  SuiteSparse_AMD_LIBRARY SuiteSparse_COLAMD_LIBRARY SuiteSparse_BTF_LIBRARY
  SuiteSparse_SUITESPARSECONFIG_LIBRARY)

if(SuiteSparse_FOUND)
  foreach(lib CONFIG AMD COLAMD CAMD CCOLAMD BTF CHOLMOD UMFPACK KLU)
    set(path ${SuiteSparse_${lib}_LIBRARY})
    if(lib STREQUAL "CONFIG")
      set(path ${SuiteSparse_SUITESPARSECONFIG_LIBRARY})
    endif()
    if(NOT TARGET SuiteSparse::${lib})
      add_library(SuiteSparse::${lib} UNKNOWN IMPORTED)
      set_target_properties(SuiteSparse::${lib} PROPERTIES IMPORTED_LOCATION ${path}
        INTERFACE_INCLUDE_DIRECTORIES ${SuiteSparse_INCLUDE_DIR})
    endif()
  endforeach()
  set_property(TARGET SuiteSparse::AMD SuiteSparse::COLAMD SuiteSparse::CAMD SuiteSparse::CCOLAMD
               SuiteSparse::BTF PROPERTY INTERFACE_LINK_LIBRARIES SuiteSparse::CONFIG)
  set_property(TARGET SuiteSparse::CHOLMOD PROPERTY INTERFACE_LINK_LIBRARIES
               SuiteSparse::AMD SuiteSparse::COLAMD SuiteSparse::CAMD SuiteSparse::CCOLAMD
               SuiteSparse::CONFIG)
  set_property(TARGET SuiteSparse::UMFPACK PROPERTY INTERFACE_LINK_LIBRARIES
               SuiteSparse::CHOLMOD SuiteSparse::AMD SuiteSparse::CONFIG)
  set_property(TARGET SuiteSparse::KLU PROPERTY INTERFACE_LINK_LIBRARIES
               SuiteSparse::AMD SuiteSparse::COLAMD SuiteSparse::BTF SuiteSparse::CONFIG)
endif()
mark_as_advanced(SuiteSparse_INCLUDE_DIR)
