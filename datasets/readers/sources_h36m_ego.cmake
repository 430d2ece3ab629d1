# Readers for Human3.6M, H3WB and EgoHumans (plus the COLMAP text model parser).
target_sources(rpt_datasets PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/h36m_ego_common.cc
  ${CMAKE_CURRENT_LIST_DIR}/human36m_cameras.cc
  ${CMAKE_CURRENT_LIST_DIR}/human36m.cc
  ${CMAKE_CURRENT_LIST_DIR}/h3wb.cc
  ${CMAKE_CURRENT_LIST_DIR}/colmap_text.cc
  ${CMAKE_CURRENT_LIST_DIR}/egohumans.cc
)
