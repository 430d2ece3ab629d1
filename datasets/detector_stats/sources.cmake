# Statistics of 2D detections against projected ground truth (rpt detector-stats).
target_sources(rpt_datasets PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/association.cc
  ${CMAKE_CURRENT_LIST_DIR}/statistics.cc
)
