target_sources(lbmshape_lib PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/colour_map.cpp
  ${CMAKE_CURRENT_LIST_DIR}/curvature_colours.cpp
  ${CMAKE_CURRENT_LIST_DIR}/image.cpp
  ${CMAKE_CURRENT_LIST_DIR}/layout.cpp
  ${CMAKE_CURRENT_LIST_DIR}/png_file.cpp
  ${CMAKE_CURRENT_LIST_DIR}/surface_renderer.cpp
  ${CMAKE_CURRENT_LIST_DIR}/surface_values.cpp
  ${CMAKE_CURRENT_LIST_DIR}/text_overlay.cpp
  ${CMAKE_CURRENT_LIST_DIR}/view.cpp
)
