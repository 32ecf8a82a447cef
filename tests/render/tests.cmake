lbmshape_test(render_tests
  ${CMAKE_CURRENT_LIST_DIR}/colour_and_curvature_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/golden_image_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/layout_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/picture_support.cpp
  ${CMAKE_CURRENT_LIST_DIR}/surface_renderer_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/view_test.cpp
  DEVICE_SUITES GoldenImage SurfaceRenderer
)
target_link_libraries(render_tests PRIVATE PkgConfig::STB)
target_compile_definitions(render_tests PRIVATE LBMSHAPE_GOLDEN_IMAGES="${CMAKE_CURRENT_LIST_DIR}/golden")
