# `cmake --install`: headers, the static layer libraries, the CLI, and the CMake package `acute`
# (find_package(acute CONFIG) then target_link_libraries(app PRIVATE acute::acute)).
# LIBACUTE_LIBRARY_TARGETS comes from libacute/CMakeLists.txt (one acute_<layer> per layer plus
# the umbrella `acute`, exported as acute::<layer> and acute::acute).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

if(NOT LIBACUTE_LIBRARY_TARGETS)
  message(FATAL_ERROR "LIBACUTE_LIBRARY_TARGETS is empty: libacute/CMakeLists.txt must set it in the parent scope")
endif()

set(ACUTE_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/acute CACHE STRING
    "Where the acute CMake package files are installed (relative to the prefix)")

install(DIRECTORY ${PROJECT_SOURCE_DIR}/libacute/include/acute DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        FILES_MATCHING PATTERN "*.h")
# acute_openmesh wraps OpenMesh's un-namespaced OpenMeshCore: the package config finds OpenMesh.
install(TARGETS ${LIBACUTE_LIBRARY_TARGETS} acute_openmesh
        EXPORT libacuteTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(EXPORT libacuteTargets NAMESPACE acute:: DESTINATION ${ACUTE_INSTALL_CMAKEDIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/acuteConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/acuteConfig.cmake
  INSTALL_DESTINATION ${ACUTE_INSTALL_CMAKEDIR})
# 0.x: a minor release may break the API, so only the same major.minor is compatible.
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/acuteConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/acuteConfig.cmake ${CMAKE_CURRENT_BINARY_DIR}/acuteConfigVersion.cmake
        DESTINATION ${ACUTE_INSTALL_CMAKEDIR})
if(TARGET acute_cli)
  install(TARGETS acute_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()
