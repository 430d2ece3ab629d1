# Tests of the Shelf, Campus and CMU Panoptic readers (datasets/readers) and the greedy PAF
# association.
list(APPEND RPT_DATASETS_TEST_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/readers_voxelpose_test.cc
  ${CMAKE_CURRENT_LIST_DIR}/readers_shelf_campus_test.cc
  ${CMAKE_CURRENT_LIST_DIR}/readers_panoptic_test.cc
  ${CMAKE_CURRENT_LIST_DIR}/openpose_paf_association_test.cc
)
