# Tests of datasets/io (pickle, NPY/NPZ, MAT, JSON helpers).
list(APPEND RPT_DATASETS_TEST_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/pickle_test.cc
  ${CMAKE_CURRENT_LIST_DIR}/npy_test.cc
  ${CMAKE_CURRENT_LIST_DIR}/mat_test.cc
  ${CMAKE_CURRENT_LIST_DIR}/json_file_test.cc
)
