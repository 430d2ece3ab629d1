# Tests of the Human3.6M, H3WB and EgoHumans readers and the COLMAP text parser.
list(APPEND RPT_DATASETS_TEST_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/readers_human36m_test.cc
  ${CMAKE_CURRENT_LIST_DIR}/readers_h3wb_test.cc
  ${CMAKE_CURRENT_LIST_DIR}/readers_colmap_text_test.cc
  ${CMAKE_CURRENT_LIST_DIR}/readers_egohumans_test.cc
)
