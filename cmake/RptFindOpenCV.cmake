# rpt_find_opencv(MODULE...): OpenCV's modules found one by one, as imported targets
# RptOpenCV::<module> (core, imgproc, imgcodecs, videoio, calib3d, ...). Debian ships OpenCV's
# own CMake package only with libopencv-dev, which depends on every module and on about 120 more
# packages (VTK, GDAL, Mesa, ...); rpt needs a few modules (libopencv-<module>-dev each), so a
# fresh machine installs about a third fewer packages (scripts/install_deps.sh). Used by the build
# and by the installed package (rptConfig.cmake), which ships this file.
function(rpt_find_opencv)
  find_path(RPT_OPENCV_INCLUDE_DIR opencv2/core.hpp PATH_SUFFIXES opencv4)
  if(NOT RPT_OPENCV_INCLUDE_DIR)
    message(FATAL_ERROR "OpenCV headers (opencv2/core.hpp) not found: install libopencv-core-dev "
                        "(bash scripts/install_deps.sh), or set RPT_OPENCV_INCLUDE_DIR")
  endif()
  foreach(module IN LISTS ARGN)
    if(TARGET RptOpenCV::${module})
      continue()
    endif()
    find_library(RPT_OPENCV_${module}_LIBRARY opencv_${module})
    if(NOT RPT_OPENCV_${module}_LIBRARY OR NOT EXISTS "${RPT_OPENCV_INCLUDE_DIR}/opencv2/${module}.hpp")
      message(FATAL_ERROR "OpenCV module ${module} not found (library opencv_${module} and header "
                          "opencv2/${module}.hpp): install libopencv-${module}-dev (bash scripts/install_deps.sh)")
    endif()
    add_library(RptOpenCV::${module} UNKNOWN IMPORTED)
    set_target_properties(RptOpenCV::${module} PROPERTIES IMPORTED_LOCATION "${RPT_OPENCV_${module}_LIBRARY}"
                                                          INTERFACE_INCLUDE_DIRECTORIES "${RPT_OPENCV_INCLUDE_DIR}")
  endforeach()
endfunction()
