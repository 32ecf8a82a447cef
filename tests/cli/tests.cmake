lbmshape_test(cli_tests
  ${CMAKE_CURRENT_LIST_DIR}/denoise_cli_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/jobs_file_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/json_results_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/morph_cli_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/morph_empty_frames_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/usage_errors_test.cpp
)
