# Generic interchange formats: labels (skelda), detections JSON, OpenPose folders, COCO result
# lists, the HDF5 cache and the ReadDetectionsFile entry point; the OpenPose BODY_25 definition
# (also used by the 4D-Association Shelf reader).
target_sources(rpt_datasets PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/generic_common.cc
  ${CMAKE_CURRENT_LIST_DIR}/generic_labels.cc
  ${CMAKE_CURRENT_LIST_DIR}/generic_detections.cc
  ${CMAKE_CURRENT_LIST_DIR}/openpose_body25.cc
  ${CMAKE_CURRENT_LIST_DIR}/openpose_json.cc
  ${CMAKE_CURRENT_LIST_DIR}/coco_detections.cc
  ${CMAKE_CURRENT_LIST_DIR}/hdf5_cache.cc
  ${CMAKE_CURRENT_LIST_DIR}/detections_file.cc
)
