# Readers for Shelf, Campus (VoxelPose layout), CMU Panoptic (panoptic-toolbox layout) and the
# 4D-Association Shelf bundle (its calibration and text files, greedy PAF association).
target_sources(rpt_datasets PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/voxelpose_calibration.cc
  ${CMAKE_CURRENT_LIST_DIR}/voxelpose_detections.cc
  ${CMAKE_CURRENT_LIST_DIR}/shelf_campus.cc
  ${CMAKE_CURRENT_LIST_DIR}/panoptic.cc
  ${CMAKE_CURRENT_LIST_DIR}/fourda_calibration.cc
  ${CMAKE_CURRENT_LIST_DIR}/fourda_text.cc
  ${CMAKE_CURRENT_LIST_DIR}/openpose_paf_association.cc
  ${CMAKE_CURRENT_LIST_DIR}/shelf_4da.cc
)
