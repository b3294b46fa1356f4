include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

install(DIRECTORY libacute/include/acute DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(TARGETS ${LIBACUTE_LIBRARY_TARGETS} acute_openmesh
        EXPORT libacuteTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(EXPORT libacuteTargets NAMESPACE acute:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/acute)
configure_package_config_file(cmake/acuteConfig.cmake.in ${CMAKE_CURRENT_BINARY_DIR}/acuteConfig.cmake
  INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/acute)
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/acuteConfigVersion.cmake COMPATIBILITY SameMajorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/acuteConfig.cmake ${CMAKE_CURRENT_BINARY_DIR}/acuteConfigVersion.cmake
  DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/acute)
if(TARGET acute_cli)
  install(TARGETS acute_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()
