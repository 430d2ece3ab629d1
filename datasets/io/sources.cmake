# Low-level container readers: pickle, NPY/NPZ, MAT v5, JSON helpers, whitespace-separated text
# tokens (namespace rpt::io).
target_sources(rpt_datasets PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/binary.cc
  ${CMAKE_CURRENT_LIST_DIR}/py_value.cc
  ${CMAKE_CURRENT_LIST_DIR}/pickle.cc
  ${CMAKE_CURRENT_LIST_DIR}/npy.cc
  ${CMAKE_CURRENT_LIST_DIR}/mat.cc
  ${CMAKE_CURRENT_LIST_DIR}/json_file.cc
  ${CMAKE_CURRENT_LIST_DIR}/text_tokens.cc
)
