lbmshape_test(gpu_tests
  ${CMAKE_CURRENT_LIST_DIR}/device_bandwidth_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/device_choice_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/driver_shader_cache_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/recorded_commands_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/validation_layer_test.cpp
)
