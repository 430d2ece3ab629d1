# Per-target compile settings (no directory-wide flags).
function(rpt_set_compile_options target)
  target_compile_features(${target} PUBLIC cxx_std_20)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic)
  if(RPT_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
  if(RPT_MARCH_NATIVE)
    target_compile_options(${target} PRIVATE -march=native)
  endif()
  # Unity build of the product libraries: most of a file's compile time is the same template code
  # (nlohmann::json, Eigen, the standard library) instantiated again in every file; batches of
  # RPT_UNITY_BATCH files instantiate it once. Names in anonymous namespaces must therefore be
  # unique within a library: a clash is a compile error, or, for same-named functions with
  # different parameters, a silent overload, which the test below catches. Executables and tests
  # keep one file per compile, so an edit there rebuilds one file.
  get_target_property(type ${target} TYPE)
  if(RPT_UNITY_BUILD AND type STREQUAL "STATIC_LIBRARY")
    set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE ${RPT_UNITY_BATCH})
    # The library's sources, for the test that file-local names are unique in it
    # (scripts/check_unity_names.py, ctest UnityBuild.FileLocalNamesAreUniquePerLibrary).
    file(GENERATE OUTPUT ${PROJECT_BINARY_DIR}/unity_sources/${target}.txt
         CONTENT "$<TARGET_PROPERTY:${target},SOURCE_DIR>\n$<JOIN:$<TARGET_PROPERTY:${target},SOURCES>,\n>\n")
  endif()
endfunction()
set(RPT_UNITY_BATCH 8 CACHE STRING "Files per unity batch (RPT_UNITY_BUILD)")

# Precompiled headers: the heavy third-party and standard headers most files of a target include
# (Eigen, nlohmann/json, CLI11, GoogleTest), parsed once per target instead of once per file. A
# file compiles in about half the CPU time with them (CONTRIBUTING.md); project headers are
# never precompiled, so editing them rebuilds exactly what it did before. -DRPT_PRECOMPILED_HEADERS=OFF
# turns them off (e.g. to check that every file includes what it uses).
set(RPT_PCH_STD <algorithm> <array> <cmath> <cstdint> <cstdio> <filesystem> <functional> <limits> <map>
    <memory> <optional> <span> <sstream> <stdexcept> <string> <string_view> <utility> <vector>)
set(RPT_PCH_EIGEN <Eigen/Core> <Eigen/Geometry>)
set(RPT_PCH_JSON <nlohmann/json.hpp>)
set(RPT_PCH_TEST <gtest/gtest.h> <gmock/gmock.h>)
set(RPT_PCH_CLI <CLI/CLI.hpp>)

# rpt_precompile_headers(target HEADER...): precompiles HEADER... for the files of `target`.
function(rpt_precompile_headers target)
  if(RPT_PRECOMPILED_HEADERS)
    target_precompile_headers(${target} PRIVATE ${ARGN})
  endif()
endfunction()
