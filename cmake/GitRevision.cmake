# Writes ${OUT} with the current git revision; rewrites it only when it changed (no rebuilds
# otherwise). Run at every build by the rpt_git_revision target.
execute_process(COMMAND git -C ${SOURCE_DIR} rev-parse --short=12 HEAD
                OUTPUT_VARIABLE revision OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET RESULT_VARIABLE status)
if(NOT status EQUAL 0 OR revision STREQUAL "")
  set(revision "unknown")
endif()
# Only source changes make a build "dirty" (regenerated results/ do not).
execute_process(COMMAND git -C ${SOURCE_DIR} status --porcelain --untracked-files=no -- core datasets metrics cli bench cmake CMakeLists.txt
                OUTPUT_VARIABLE dirty OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
if(NOT dirty STREQUAL "")
  set(revision "${revision}-dirty")
endif()
set(content "#pragma once\n#define RPT_GIT_REVISION \"${revision}\"\n")
if(EXISTS ${OUT})
  file(READ ${OUT} old)
endif()
if(NOT old STREQUAL content)
  file(WRITE ${OUT} "${content}")
endif()
