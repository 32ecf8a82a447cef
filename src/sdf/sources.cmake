target_sources(lbmshape_lib PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/band_distance.cpp
  ${CMAKE_CURRENT_LIST_DIR}/band_signed_distance.cpp
  ${CMAKE_CURRENT_LIST_DIR}/device_band_distances.cpp
  ${CMAKE_CURRENT_LIST_DIR}/enclosed_volume.cpp
  ${CMAKE_CURRENT_LIST_DIR}/far_field.cpp
  ${CMAKE_CURRENT_LIST_DIR}/grid_frame.cpp
  ${CMAKE_CURRENT_LIST_DIR}/hole_radius.cpp
  ${CMAKE_CURRENT_LIST_DIR}/shell_orientation.cpp
  ${CMAKE_CURRENT_LIST_DIR}/signed_distance.cpp
  ${CMAKE_CURRENT_LIST_DIR}/triangle_bvh.cpp
  ${CMAKE_CURRENT_LIST_DIR}/winding_gradient_bound.cpp
  ${CMAKE_CURRENT_LIST_DIR}/winding_number.cpp
  ${CMAKE_CURRENT_LIST_DIR}/winding_sign.cpp
)
