lbmshape_test(core_tests
  ${CMAKE_CURRENT_LIST_DIR}/progress_test.cpp
)
