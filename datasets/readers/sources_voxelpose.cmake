# Readers for Shelf, Campus (VoxelPose layout) and CMU Panoptic (panoptic-toolbox layout).
target_sources(rpt_datasets PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/voxelpose_calibration.cc
  ${CMAKE_CURRENT_LIST_DIR}/voxelpose_detections.cc
  ${CMAKE_CURRENT_LIST_DIR}/shelf_campus.cc
  ${CMAKE_CURRENT_LIST_DIR}/panoptic.cc
)
