lbmshape_test(pipeline_tests
  ${CMAKE_CURRENT_LIST_DIR}/denoise_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/morph_test.cpp
)
lbmshape_shared_asset_test(pipeline_shared_mesh_tests
  ${CMAKE_CURRENT_LIST_DIR}/shared_denoise_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/shared_morph_test.cpp
)
