target_sources(lbmshape_lib PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/triangle_mesh.cpp
)
