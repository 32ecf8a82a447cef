lbmshape_test(gpu_tests
  ${CMAKE_CURRENT_LIST_DIR}/validation_layer_test.cpp
)
