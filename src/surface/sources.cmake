target_sources(lbmshape_lib PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/band_marching_cubes.cpp
  ${CMAKE_CURRENT_LIST_DIR}/cube_cases.cpp
  ${CMAKE_CURRENT_LIST_DIR}/inside_mask.cpp
  ${CMAKE_CURRENT_LIST_DIR}/loop_triangulation.cpp
  ${CMAKE_CURRENT_LIST_DIR}/marching_cubes.cpp
  ${CMAKE_CURRENT_LIST_DIR}/surface_pieces.cpp
  ${CMAKE_CURRENT_LIST_DIR}/triangle_relaxation.cpp
  ${CMAKE_CURRENT_LIST_DIR}/volume_keeping.cpp
)
