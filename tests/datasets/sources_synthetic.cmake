# Tests of the synthetic scenes and the simulated detector (datasets/synthetic).
list(APPEND RPT_DATASETS_TEST_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/synthetic_test.cc
  ${CMAKE_CURRENT_LIST_DIR}/synthetic_detector_test.cc
  ${CMAKE_CURRENT_LIST_DIR}/detector_stats_test.cc
  ${CMAKE_CURRENT_LIST_DIR}/detector_model_test.cc
)
