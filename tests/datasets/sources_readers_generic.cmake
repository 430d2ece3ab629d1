# Tests of the generic interchange formats (labels, detections JSON, OpenPose, COCO, HDF5 cache).
list(APPEND RPT_DATASETS_TEST_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/readers_generic_test.cc
  ${CMAKE_CURRENT_LIST_DIR}/readers_generic_detections_test.cc
  ${CMAKE_CURRENT_LIST_DIR}/readers_generic_hdf5_test.cc
)
