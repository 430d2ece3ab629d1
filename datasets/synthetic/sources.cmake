# Synthetic scenes and the simulated 2D detector (namespace rpt::synthetic).
target_sources(rpt_datasets PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/random.cc
  ${CMAKE_CURRENT_LIST_DIR}/camera_rig.cc
  ${CMAKE_CURRENT_LIST_DIR}/person_motion.cc
  ${CMAKE_CURRENT_LIST_DIR}/scene.cc
  ${CMAKE_CURRENT_LIST_DIR}/detector_options.cc
  ${CMAKE_CURRENT_LIST_DIR}/detector_geometry.cc
  ${CMAKE_CURRENT_LIST_DIR}/detector_occlusion.cc
  ${CMAKE_CURRENT_LIST_DIR}/detector_error_model.cc
  ${CMAKE_CURRENT_LIST_DIR}/detector_simulator.cc
  ${CMAKE_CURRENT_LIST_DIR}/synthetic_sequence.cc
)
