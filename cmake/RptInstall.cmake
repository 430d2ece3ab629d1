# `cmake --install`: the libraries an application links (core, formats, readers, simulation,
# metrics, engine), their headers under include/rpt/ (included as "core/...", "engine/..." as
# inside the project) and a CMake package, so that an application can
#   find_package(rpt REQUIRED)
#   target_link_libraries(app PRIVATE rpt::engine)   # or rpt::core for the triangulator alone
# The command line, the renderer (OpenCV video I/O) and the tests are not part of the package.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(RPT_INSTALL_INCLUDEDIR ${CMAKE_INSTALL_INCLUDEDIR}/rpt)
set(RPT_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/rpt)
set(RPT_INSTALLED_LIBRARIES rpt_core rpt_io rpt_datasets rpt_simulation rpt_metrics rpt_engine)

foreach(target IN LISTS RPT_INSTALLED_LIBRARIES)
  target_include_directories(${target} INTERFACE $<INSTALL_INTERFACE:${RPT_INSTALL_INCLUDEDIR}>)
  # rpt::core etc. for the consumer, as the aliases name them inside the build.
  string(REPLACE "rpt_" "" export_name ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${export_name})
endforeach()

install(TARGETS ${RPT_INSTALLED_LIBRARIES} EXPORT rptTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
# The headers of the installed libraries, folder layout kept (engine/render/ belongs to the
# renderer, which is not installed).
foreach(dir core datasets metrics engine)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${dir}/ DESTINATION ${RPT_INSTALL_INCLUDEDIR}/${dir}
          FILES_MATCHING PATTERN "*.h" PATTERN "render" EXCLUDE
          PATTERN "hdf5_file.h" EXCLUDE)  # the HDF5 C API wrapper of the readers, not part of the API
endforeach()
install(EXPORT rptTargets NAMESPACE rpt:: DESTINATION ${RPT_INSTALL_CMAKEDIR})

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/rptConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/rptConfig.cmake INSTALL_DESTINATION ${RPT_INSTALL_CMAKEDIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/rptConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/rptConfig.cmake ${PROJECT_BINARY_DIR}/rptConfigVersion.cmake
              ${PROJECT_SOURCE_DIR}/cmake/RptFindOpenCV.cmake
        DESTINATION ${RPT_INSTALL_CMAKEDIR})
