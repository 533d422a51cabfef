# The SDK: `cmake --install BUILD --prefix P` gives P/include/relpos/..., the libraries, the relpos
# command, the example plugins in P/lib/relpos/plugins and P/lib/cmake/relpos/relpos-config.cmake.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set_target_properties(relpos_core PROPERTIES EXPORT_NAME core)
set_target_properties(relpos_io PROPERTIES EXPORT_NAME io)
set_target_properties(relpos_rules PROPERTIES EXPORT_NAME rules)
set_target_properties(relpos_builtins PROPERTIES EXPORT_NAME builtins)
set_target_properties(relpos_manifolds PROPERTIES EXPORT_NAME manifolds)
set_target_properties(relpos_complete PROPERTIES EXPORT_NAME complete)
set_target_properties(relpos_plugin_sdk PROPERTIES EXPORT_NAME plugin)
set_target_properties(relpos_plugin_loader PROPERTIES EXPORT_NAME plugin_loader)
set_target_properties(relpos_conformance PROPERTIES EXPORT_NAME conformance)
set_target_properties(relpos_collision PROPERTIES EXPORT_NAME collision)
set_target_properties(relpos_report PROPERTIES EXPORT_NAME report)
set_target_properties(relpos PROPERTIES INSTALL_RPATH "$ORIGIN/../${CMAKE_INSTALL_LIBDIR}")

install(TARGETS relpos_core relpos_io relpos_rules relpos_manifolds relpos_complete relpos_builtins
                relpos_plugin_sdk relpos_plugin_loader relpos_conformance relpos_collision
                relpos_report
        EXPORT relpos-targets
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(TARGETS relpos RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS relpos_plugin_symmetric relpos_plugin_helical
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}/relpos/plugins)
foreach(folder core io rules manifolds complete builtins plugins collision report)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${folder}/include/relpos
          DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endforeach()
install(EXPORT relpos-targets NAMESPACE relpos::
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/relpos)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/relpos-config.cmake.in
  ${PROJECT_BINARY_DIR}/relpos-config.cmake
  INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/relpos)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/relpos-config-version.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/relpos-config.cmake
              ${PROJECT_BINARY_DIR}/relpos-config-version.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/relpos)
