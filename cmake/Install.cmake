# cmake --install: library and its image module, public headers, the OCIO config, the CLI, and a CMake package
# so that find_package(isotrace) works for other programs.
install(TARGETS isotrace EXPORT isotraceTargets
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/isotrace)
# The modules go beside the library, where it looks for them.
install(TARGETS isotrace_oiio isotrace_exr isotrace_blobs_avx2 LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
foreach(folder renderer geometry integrators)
  install(DIRECTORY ${folder} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/isotrace
          FILES_MATCHING PATTERN "*.h" PATTERN "*_test*" EXCLUDE)
endforeach()
install(FILES ${CMAKE_BINARY_DIR}/include/renderer/core/version.h
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/isotrace/renderer/core)
install(DIRECTORY config/ DESTINATION ${CMAKE_INSTALL_DATADIR}/isotrace/config)
install(DIRECTORY scenes/benchmark/ DESTINATION ${CMAKE_INSTALL_DATADIR}/isotrace/benchmark)
install(TARGETS isotrace_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
set_target_properties(isotrace_cli PROPERTIES INSTALL_RPATH "$ORIGIN/../${CMAKE_INSTALL_LIBDIR}")

set(package_dir ${CMAKE_INSTALL_LIBDIR}/cmake/isotrace)
install(EXPORT isotraceTargets NAMESPACE isotrace:: DESTINATION ${package_dir})
configure_package_config_file(cmake/isotraceConfig.cmake.in ${CMAKE_BINARY_DIR}/isotraceConfig.cmake
  INSTALL_DESTINATION ${package_dir})
write_basic_package_version_file(${CMAKE_BINARY_DIR}/isotraceConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/isotraceConfig.cmake ${CMAKE_BINARY_DIR}/isotraceConfigVersion.cmake
        DESTINATION ${package_dir})
