lbmshape_test(core_tests
  ${CMAKE_CURRENT_LIST_DIR}/concurrent_union_find_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/host_memory_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/last_resort_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/parameter_names_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/parallel_copy_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/progress_test.cpp
)
