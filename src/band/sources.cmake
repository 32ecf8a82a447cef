target_sources(lbmshape_lib PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/band_field.cpp
  ${CMAKE_CURRENT_LIST_DIR}/brick_set.cpp
)
