# Installs the libraries, headers and a CMake package so that an outside project can write
#   find_package(spar REQUIRED)
#   target_link_libraries(app PRIVATE spar::spar)
include(CMakePackageConfigHelpers)

get_property(spar_modules GLOBAL PROPERTY SPAR_MODULES)
install(TARGETS spar_base spar_spar ${spar_modules} EXPORT sparTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})

set(spar_cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/spar)
install(EXPORT sparTargets NAMESPACE spar:: DESTINATION ${spar_cmake_dir})
configure_package_config_file(cmake/sparConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/sparConfig.cmake INSTALL_DESTINATION ${spar_cmake_dir})
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/sparConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/sparConfig.cmake
              ${CMAKE_CURRENT_BINARY_DIR}/sparConfigVersion.cmake
              cmake/FindSuiteSparse.cmake
        DESTINATION ${spar_cmake_dir})
