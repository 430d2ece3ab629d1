# Tests of the Shelf, Campus, CMU Panoptic, 4D-Association Shelf and MVOR readers (datasets/readers),
# including the greedy PAF association.
list(APPEND RPT_DATASETS_TEST_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/readers_voxelpose_test.cc
  ${CMAKE_CURRENT_LIST_DIR}/readers_shelf_campus_test.cc
  ${CMAKE_CURRENT_LIST_DIR}/readers_panoptic_test.cc
  ${CMAKE_CURRENT_LIST_DIR}/openpose_paf_association_test.cc
  ${CMAKE_CURRENT_LIST_DIR}/readers_shelf_4da_test.cc
  ${CMAKE_CURRENT_LIST_DIR}/readers_mvor_test.cc
)
