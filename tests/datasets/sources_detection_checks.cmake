# Tests of the detection/GT checks behind eval's warnings (datasets/detection_checks).
list(APPEND RPT_DATASETS_TEST_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/detection_checks_test.cc
)
